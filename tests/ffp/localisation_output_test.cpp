/// output.localisation: the soil's loss of ellipticity written by the `ffp` program, and
/// nothing else about the run changed by asking for it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "ffp_test_support.hpp"
#include "reports/plot.hpp"

using namespace ffp;
using namespace ffp::test;

TEST_CASE("reference FFP on 2 cm with output.localisation: the sheared sand has localised, the run is unchanged",
          "[ffp][program][localisation]") {
  ScratchDir scratch;
  auto run = [&](const std::string& dir, bool localisation) {
    std::vector<std::string> args = {"run",
                                     scene_path("ffp_reference.json"),
                                     "--out",
                                     (scratch.path() / dir).string(),
                                     "--quiet",
                                     "--set",
                                     "mesh.min_cell_m=0.02",
                                     "--set",
                                     "end_time_s=0.03",
                                     "--set",
                                     "output.history_interval_s=0.0005",
                                     "--set",
                                     "output.field_times_s=[0.03]"};
    if (localisation) args.insert(args.end(), {"--set", "output.localisation=true"});
    return run_program(args, scratch.path());
  };
  REQUIRE(run("on", true).exit_code == 0);
  REQUIRE(run("off", false).exit_code == 0);
  const CsvData on = read_numeric_csv(scratch.path() / "on" / "history.csv");
  const CsvData off = read_numeric_csv(scratch.path() / "off" / "history.csv");
  const nlohmann::json summary = read_json(scratch.path() / "on" / "summary.json");

  // Without the key: none of its columns or figures (the shipped scenes' outputs).
  CHECK_FALSE(off.has("localised_fraction"));
  CHECK_FALSE(read_json(scratch.path() / "off" / "summary.json").contains("localised_fraction_max"));
  // Evaluated at the rows only: the steps, hence every other column, are the same bits.
  for (const std::string& column : off.columns) CHECK(on.column(column) == off.column(column));

  const auto& fraction = on.column("localised_fraction");
  const auto& face = on.column("yield_face_particles");
  const auto& edge = on.column("yield_edge_particles");
  const auto& apex = on.column("yield_apex_particles");
  const double most = *std::max_element(fraction.begin(), fraction.end());
  INFO("localised fraction: max " << most << " at " << summary["localised_time_s"].get<double>()
                                  << " s; last row: face " << face.back() << ", edge " << edge.back() << ", apex "
                                  << apex.back());
  // The share is of the evaluated particles, face and edge (the apex is not tested).
  const auto& on_face = on.column("localised_face_particles");
  const auto& on_edge = on.column("localised_edge_particles");
  for (std::size_t k = 0; k < fraction.size(); ++k) {
    CHECK(on_face[k] <= face[k]);
    CHECK(on_edge[k] <= edge[k]);
    if (face[k] + edge[k] > 0.0)  // the CSV has 10 digits
      CHECK(fraction[k] == Approx((on_face[k] + on_edge[k]) / (face[k] + edge[k])).epsilon(1e-9));
  }
  // The largest share counts only the rows where 5 % of the sand yields (a share of a handful
  // of particles under the tip in the first milliseconds is noise).
  const double minimum = summary["localised_fraction_min_yielding"].get<double>();
  CHECK(minimum == std::ceil(0.05 * summary["soil_particles"].get<double>()));
  double counted = 0.0, uncounted = 0.0;
  for (std::size_t k = 0; k < fraction.size(); ++k) {
    double& largest = face[k] + edge[k] >= minimum ? counted : uncounted;
    largest = std::max(largest, fraction[k]);
  }
  INFO("largest share of the rows with at least " << minimum << " yielding: " << counted << "; of the others "
                                                  << uncounted);
  CHECK(fraction.front() == 0.0);  // at rest before impact (K0 state inside the surface)
  CHECK(face.back() > 0.0);
  // Non-associated (ψ = 0) perfectly plastic MC: a face particle whose band plane is the
  // r–z plane has r_min = −0.074, an edge with θθ in its pair −0.08 or −0.05 (models/localisation
  // tests), so sheared sand localises.
  CHECK(counted > 0.1);
  CHECK(most <= 1.0);
  CHECK(summary["localised_fraction_max"].get<double>() == Approx(counted).epsilon(1e-9));  // the CSV has 10 digits
  // Rows 0.5 ms apart: in the first millisecond some sand yields under the tip, less than 5 % of it,
  // and those rows' shares are left out.
  CHECK(uncounted > 0.0);
  CHECK(summary["localised_time_s"].get<double>() > 0.0);
  CHECK(summary["localised_time_s"].get<double>() <= 0.03);

  std::ifstream in(scratch.path() / "on" / "fields" / "particles_0000.vtu");
  const std::string vtu((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* name : {"localised", "band_angle_deg"})
    CHECK(vtu.find(std::string("Name=\"") + name + "\"") != std::string::npos);
  // The share against time and the map at the field time, as PNGs (none without gnuplot).
  for (const char* png : {"localisation.png", "localisation_t0.030.png"}) {
    INFO(png);
    CHECK(std::filesystem::exists(scratch.path() / "on" / "plots" / png) == gnuplot_available());
    CHECK_FALSE(std::filesystem::exists(scratch.path() / "off" / "plots" / png));
  }
}
