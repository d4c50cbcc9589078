/// The `point` scene kind end to end, through the ffp program.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "models/math_constants.hpp"
#include "tests/support/scratch.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

/// This file's scratch folders are named ffp-point-….
struct ScratchDirectory : ffp::test_support::Scratch {
  ScratchDirectory() : ffp::test_support::Scratch("ffp-point") {}
};

using ffp::test_support::run_ffp;

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

/// A point scene on a general path read from `csv`: MC sand (φ = 50°) starting at 1.72 kPa.
json table_path_scene(const std::string& name, const std::string& csv) {
  return {{"kind", "point"},
          {"name", name},
          {"material", {{"model", "mohr_coulomb"}, {"E_kPa", 2500}, {"nu", 0.33}, {"phi_peak_deg", 50}}},
          {"initial_pressure_kPa", 1.72},
          {"path", {{"type", "general"}, {"table_csv", csv}, {"increments_per_row", 200}}}};
}

constexpr const char* kTableHeader = "time_s,stress_11_kPa,strain_22,stress_33_kPa,strain_12,strain_23,strain_13\n";

double n_phi(double phi_deg) {
  const double s = std::sin(phi_deg * ffp::kDegree);
  return (1 + s) / (1 - s);
}

}  // namespace

TEST_CASE("point scene: drained triaxial peak equals σ3(Nφ−1) and the outputs are written", "[point][scene]") {
  ScratchDirectory dir;
  const std::string scene = std::string(FFP_SOURCE_DIR) + "/data/scenes/point_triaxial_mc.json";
  REQUIRE(run_ffp(dir, scene) == 0);
  const json summary = read_json(dir.path / "out" / "summary.json");
  CHECK(summary["peak_q_kPa"].get<double>() == Approx(1.72 * (n_phi(39) - 1)).epsilon(1e-8));
  CHECK(summary["steps"].get<long>() == 2000);
  CHECK(summary["dissipated_work_J_m3"].get<double>() > 0.0);
  CHECK(summary["scene"]["path"]["strain_rate_per_s"].get<double>() == 1e-4);  // defaults are echoed
  CHECK(fs::exists(dir.path / "out" / "history.csv"));
}

TEST_CASE("point scene: a CSV table path gives the same peak as the named path", "[point][scene]") {
  ScratchDirectory dir;
  dir.write("path.csv", std::string(kTableHeader) +
                            "0,1.72,0,1.72,0,0,0\n"
                            "100,1.72,0.05,1.72,0,0,0\n");
  dir.write("scene.json", table_path_scene("table", "path.csv").dump());
  REQUIRE(run_ffp(dir, "scene.json") == 0);
  const json summary = read_json(dir.path / "out" / "summary.json");
  CHECK(summary["peak_q_kPa"].get<double>() == Approx(1.72 * (n_phi(50) - 1)).epsilon(1e-8));
  CHECK(summary["final_axial_strain"].get<double>() == Approx(0.05).epsilon(1e-14));
}

TEST_CASE("point scene: a CSV table's strains count from its first row, and its first stresses must be the start",
          "[point][scene]") {
  ScratchDirectory dir;
  // A lab record whose strain gauge read 0.01 at the start: the 0.05 leg is 0.04.
  dir.write("offset.csv", std::string(kTableHeader) +
                              "0,1.72,0.01,1.72,0,0,0\n"
                              "100,1.72,0.05,1.72,0,0,0\n");
  dir.write("scene.json", table_path_scene("offset", "offset.csv").dump());
  REQUIRE(run_ffp(dir, "scene.json") == 0);
  const json summary = read_json(dir.path / "out" / "summary.json");
  CHECK(summary["final_axial_strain"].get<double>() == Approx(0.04).epsilon(1e-14));

  // Starting the table at 3 kPa while the specimen starts at 1.72 kPa would be a
  // silent jump in the first leg.
  dir.write("jump.csv", std::string(kTableHeader) +
                            "0,3,0,1.72,0,0,0\n"
                            "100,3,0.05,1.72,0,0,0\n");
  dir.write("jump.json", table_path_scene("jump", "jump.csv").dump());
  fs::remove_all(dir.path / "out");
  CHECK(run_ffp(dir, "jump.json") == 2);
  const std::string text = ffp::test_support::read_text(dir.path / "log.txt");
  CHECK(text.find("path.table_csv") != std::string::npos);
  CHECK(text.find("stress_11_kPa") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("point scene: bad input names the key and exits with 2", "[point][scene]") {
  ScratchDirectory dir;
  const std::string scene = std::string(FFP_SOURCE_DIR) + "/data/scenes/point_triaxial_mc.json";
  CHECK(run_ffp(dir, scene, "--set path.cell_presure_kPa=3") == 2);
  std::ifstream log(dir.path / "log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  CHECK(text.find("path.cell_presure_kPa") != std::string::npos);
  CHECK(run_ffp(dir, scene, "--set path.type=triaxial") == 2);
  CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("point scene: a failed step writes a scene that repeats it", "[point][scene]") {
  ScratchDirectory dir;
  // Axial stress beyond the strength under stress control: no stress state can follow.
  const json scene = {{"kind", "point"},
                      {"name", "too_strong"},
                      {"material", {{"model", "mohr_coulomb"}, {"E_kPa", 2500}, {"nu", 0.33}, {"phi_peak_deg", 39}}},
                      {"initial_pressure_kPa", 1.72},
                      {"newton", {{"max_iterations", 8}}},
                      {"path",
                       {{"type", "general"},
                        {"segments",
                         {{{"control", {"stress", "stress", "stress", "strain", "strain", "strain"}},
                           {"target", {1.72, 20, 1.72, 0, 0, 0}},
                           {"increments", 50}}}}}}};
  dir.write("scene.json", scene.dump());
  REQUIRE(run_ffp(dir, "scene.json") == 1);
  REQUIRE(fs::exists(dir.path / "failed-step.json"));
  const json reproducer = read_json(dir.path / "failed-step.json");
  CHECK(reproducer["path"]["segments"][0]["increments"] == 1);
  fs::rename(dir.path / "failed-step.json", dir.path / "repeat.json");
  CHECK(run_ffp(dir, "repeat.json") == 1);  // the same step fails again on its own
}
