// The report's and the sweep's run cache: a run is identified by the scene it
// will really run and by the program that runs it, nothing else.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "reports/run_pool.hpp"

namespace fs = std::filesystem;
using ffp::run_key;
using ffp::RunRequest;

namespace {

struct Scratch {
  fs::path dir;
  Scratch() : dir(fs::temp_directory_path() / ("ffp_run_pool_" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
};

constexpr const char* kScene = R"({"kind": "triaxial", "name": "t", "description": "first words",
  "material": {"model": "mohr_coulomb", "E_kPa": 2500, "nu": 0.33, "phi_peak_deg": 39}})";

}  // namespace

TEST_CASE("run key: an override equal to the scene's value shares the plain run's key", "[reports]") {
  Scratch s;
  const fs::path scene = s.write("t.json", kScene);
  const std::string plain = run_key({"a", scene, {}}, "v1");
  CHECK(run_key({"b", scene, {"material.E_kPa=2500"}}, "v1") == plain);
  CHECK(run_key({"c", scene, {"material.E_kPa=2500.0"}}, "v1") == plain);    // 2500 and 2500.0 are one number
  CHECK(run_key({"d", scene, {"description=other words"}}, "v1") == plain);  // prose does not change a run
}

TEST_CASE("run key: a changed value, a changed referenced file or another program is a new run", "[reports]") {
  Scratch s;
  const fs::path scene = s.write("t.json", kScene);
  const std::string plain = run_key({"a", scene, {}}, "v1");
  CHECK(run_key({"a", scene, {"material.E_kPa=5000"}}, "v1") != plain);
  CHECK(run_key({"a", scene, {"material.model=ssmc"}}, "v1") != plain);
  CHECK(run_key({"a", scene, {}}, "v2") != plain);

  s.write("lab.csv", "axial_strain,deviatoric_stress_kPa\n0,0\n0.01,1\n");
  const fs::path with_csv = s.write("c.json", R"({"kind": "calibration", "lab_curve_csv": "lab.csv"})");
  const std::string before = run_key({"a", with_csv, {}}, "v1");
  s.write("lab.csv", "axial_strain,deviatoric_stress_kPa\n0,0\n0.01,2\n");
  CHECK(run_key({"a", with_csv, {}}, "v1") != before);
}

TEST_CASE("program identity changes with the binary's bytes, not only with the version string", "[reports]") {
  Scratch s;
  const fs::path a = s.write("a.bin", "one build");
  const fs::path b = s.write("b.bin", "another build");
  CHECK(ffp::program_identity(a, "0.1.0") == ffp::program_identity(a, "0.1.0"));
  CHECK(ffp::program_identity(a, "0.1.0") != ffp::program_identity(b, "0.1.0"));
}

TEST_CASE("a sweep runs each distinct combination once and a repeated sweep comes from the cache", "[reports]") {
  Scratch s;
  const fs::path scene = fs::path(FFP_SOURCE_DIR) / "data/scenes/triaxial_mc.json";
  const fs::path out = s.dir / "sweep";
  const std::string command = std::string(FFP_BINARY) + " sweep " + scene.string() +
                              " --set material.phi_peak_deg=30,39 --jobs 2 --out " + out.string() + " 2>" +
                              (s.dir / "log").string();
  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream table(out / "sweep.csv");
  std::string header, row;
  std::getline(table, header);
  int rows = 0;
  while (std::getline(table, row)) ++rows;
  CHECK(rows == 2);
  CHECK(header.find("peak_q_kPa") != std::string::npos);

  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream log(s.dir / "log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  CHECK(text.find("0 to do, 2 cached") != std::string::npos);
}

TEST_CASE("the runs expected to take longest start first, the others in the given order", "[reports]") {
  Scratch s;
  const fs::path scene = fs::path(FFP_SOURCE_DIR) / "data/scenes/triaxial_mc.json";
  std::vector<RunRequest> requests = {{"first", scene, {"material.phi_peak_deg=30"}},
                                      {"long", scene, {"material.phi_peak_deg=35"}},
                                      {"third", scene, {"material.phi_peak_deg=40"}},
                                      {"long again", scene, {"material.phi_peak_deg=35"}}};
  requests[3].expected_wall_s = 100;  // the estimate of a shared run counts for it
  const auto outcomes = ffp::run_all(FFP_BINARY, requests, s.dir / "cache", "v1", 1);
  REQUIRE(outcomes.size() == 4);
  for (const auto& o : outcomes) REQUIRE(o.exit_code == 0);
  // One at a time: the order they started is the order their summaries were written.
  auto written = [&](std::size_t i) { return fs::last_write_time(outcomes[i].out_dir / "summary.json"); };
  CHECK(written(1) < written(0));
  CHECK(written(0) < written(2));
  CHECK(outcomes[3].out_dir == outcomes[1].out_dir);
}

TEST_CASE("a follow-up's runs start once its inputs are done, before the runs that do not concern it", "[reports]") {
  // One at a time: "input" first (longest), then the follow-up's run, made from the
  // input's outcome, goes ahead of "other" (expected longer than it, but queued later
  // only if it were a second round).
  Scratch s;
  const fs::path scene = fs::path(FFP_SOURCE_DIR) / "data/scenes/triaxial_mc.json";
  std::vector<RunRequest> requests = {{"input", scene, {"material.phi_peak_deg=30"}, 10.0},
                                      {"other", scene, {"material.phi_peak_deg=35"}, 5.0},
                                      {"later", scene, {"material.phi_peak_deg=36"}, 1.0}};
  std::vector<ffp::FollowUp> follow_ups(2);
  int made = 0;
  follow_ups[0] = {0, 1, [&](const std::vector<ffp::RunOutcome>& inputs) {
                     ++made;
                     REQUIRE(inputs.size() == 1);
                     CHECK(inputs[0].exit_code == 0);
                     CHECK(fs::exists(inputs[0].out_dir / "summary.json"));  // its results are there to read
                     return std::vector<RunRequest>{{"made from input", scene, {"material.phi_peak_deg=31"}, 7.0},
                                                    {"shared", scene, {"material.phi_peak_deg=36"}, 0.0}};
                   }};
  follow_ups[1] = {1, 3, [&](const std::vector<ffp::RunOutcome>& inputs) {
                     ++made;
                     CHECK(inputs.size() == 2);
                     return std::vector<RunRequest>{};
                   }};
  const auto outcomes = ffp::run_all(FFP_BINARY, requests, s.dir / "cache", "v1", 1, ffp::Scheduler::local, follow_ups);
  CHECK(made == 2);
  REQUIRE(outcomes.size() == 3);
  REQUIRE(follow_ups[0].requests.size() == 2);
  REQUIRE(follow_ups[0].outcomes.size() == 2);
  CHECK(follow_ups[1].outcomes.empty());
  for (const auto& o : follow_ups[0].outcomes) CHECK(o.exit_code == 0);
  auto written = [](const ffp::RunOutcome& o) { return fs::last_write_time(o.out_dir / "summary.json"); };
  CHECK(written(outcomes[0]) < written(follow_ups[0].outcomes[0]));
  CHECK(written(follow_ups[0].outcomes[0]) < written(outcomes[1]));
  // A follow-up's run equal to a given one runs once.
  CHECK(follow_ups[0].outcomes[1].out_dir == outcomes[2].out_dir);
  CHECK(follow_ups[0].outcomes[1].cached);

  // Again: everything from the cache, the follow-ups made all the same.
  std::vector<ffp::FollowUp> again = {follow_ups[0]};
  again[0].requests.clear();
  again[0].outcomes.clear();
  const auto cached = ffp::run_all(FFP_BINARY, requests, s.dir / "cache", "v1", 1, ffp::Scheduler::local, again);
  CHECK(made == 3);
  REQUIRE(again[0].outcomes.size() == 2);
  CHECK(again[0].outcomes[0].cached);
  CHECK(again[0].outcomes[0].out_dir == follow_ups[0].outcomes[0].out_dir);
}
