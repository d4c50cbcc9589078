/// The `triaxial` scene kind end to end, through the ffp program.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "models/math_constants.hpp"
#include "tests/support/scratch.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

/// This file's scratch folders are named ffp-triaxial-….
struct Scratch : ffp::test_support::Scratch {
  Scratch() : ffp::test_support::Scratch("ffp-triaxial") {}
};

using ffp::test_support::read_text;
using ffp::test_support::run_ffp;

double n_phi(double phi_deg) {
  const double s = std::sin(phi_deg * ffp::kDegree);
  return (1 + s) / (1 - s);
}

const std::string kScenes = std::string(FFP_SOURCE_DIR) + "/data/scenes/";

}  // namespace

TEST_CASE("triaxial scene: MC peak σ3(Nφ−1), force–displacement history and the work terms", "[triaxial][scene]") {
  Scratch dir;
  REQUIRE(run_ffp(dir, kScenes + "triaxial_mc.json") == 0);
  const json s = json::parse(read_text(dir.path / "out" / "summary.json"));
  CHECK(s["peak_q_kPa"].get<double>() == Approx(1.72 * (n_phi(39) - 1)).epsilon(1e-8));
  CHECK(s["residual_q_kPa"].get<double>() == Approx(1.72 * (n_phi(39) - 1)).epsilon(1e-8));
  const double W = s["dissipated_work_J"].get<double>();
  CHECK(std::abs(s["work_balance_error_J"].get<double>()) < 1e-9 * W);
  CHECK(s["plastic_work_J"].get<double>() < W);
  CHECK(s.contains("dissipated_work_integration"));
  CHECK(s["steps"].get<long>() == 2000);

  const std::string history = read_text(dir.path / "out" / "history.csv");
  const std::string header = history.substr(0, history.find('\n'));
  for (const char* column : {"axial_strain", "volumetric_strain", "q_kPa", "axial_displacement_m", "axial_force_N",
                             "dissipated_work_J", "plastic_work_J"}) {
    CAPTURE(column);
    CHECK(header.find(column) != std::string::npos);
  }
  // 2000 increments and the start: 2001 rows and the header.
  CHECK(std::count(history.begin(), history.end(), '\n') == 2002);
}

TEST_CASE("triaxial scene: the specimen is weightless and the keys are checked", "[triaxial][scene]") {
  Scratch dir;
  CHECK(run_ffp(dir, kScenes + "triaxial_mc.json", "--set material.density_kg_m3=1500") == 2);
  CHECK(read_text(dir.path / "log.txt").find("density_kg_m3") != std::string::npos);
  CHECK(run_ffp(dir, kScenes + "triaxial_mc.json", "--set cell_pressure_kPa=0") == 2);
  CHECK(read_text(dir.path / "log.txt").find("cell_pressure_kPa") != std::string::npos);
  CHECK(run_ffp(dir, kScenes + "triaxial_mc.json", "--set specimen.height_mm=150") == 2);
  CHECK(read_text(dir.path / "log.txt").find("specimen.height_mm") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("triaxial scene: the paper's SSMC softens from the peak and the output thins but the work does not",
          "[triaxial][scene][ssmc]") {
  Scratch dir;
  REQUIRE(run_ffp(dir, kScenes + "triaxial_ssmc_paper.json") == 0);
  const json full = json::parse(read_text(dir.path / "out" / "summary.json"));
  REQUIRE(run_ffp(dir, kScenes + "triaxial_ssmc_paper.json", "--set output_every_increments=100") == 0);
  const json thinned = json::parse(read_text(dir.path / "out" / "summary.json"));
  // Below the continuum peak by O(η Δε_a): the increment that yields already softens (2e-4 here).
  CHECK(full["peak_q_kPa"].get<double>() < 1.72 * (n_phi(39) - 1));
  CHECK(full["peak_q_kPa"].get<double>() == Approx(1.72 * (n_phi(39) - 1)).epsilon(1e-3));
  CHECK(full["residual_q_kPa"].get<double>() < full["peak_q_kPa"].get<double>());
  CHECK(full["residual_q_kPa"].get<double>() > 1.72 * (n_phi(32) - 1));
  // The work integral uses every increment, whatever history.csv keeps.
  CHECK(thinned["dissipated_work_J"].get<double>() == full["dissipated_work_J"].get<double>());
  const std::string history = read_text(dir.path / "out" / "history.csv");
  CHECK(std::count(history.begin(), history.end(), '\n') == 22);
}

TEST_CASE("integration_error scene: a Bolton material is refused, its MC comparison would drop ψ",
          "[integration][scene]") {
  Scratch dir;
  std::ifstream in(kScenes + "integration_error.json");
  json scene = json::parse(in);
  scene["material"].erase("psi_peak_deg");
  scene["material"]["relative_density"] = 0.15;
  dir.write("bolton.json", scene.dump());
  CHECK(run_ffp(dir, "bolton.json") == 2);
  CHECK(read_text(dir.path / "log.txt").find("material.relative_density") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "out"));
}
