// The report's runs as its studies ask for them: the run cache runs equal scenes once,
// so a study that asks for the reference drop differently would run its physics twice.
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "reports/run_pool.hpp"
#include "reports/studies/study_helpers.hpp"
#include "reports/study.hpp"

namespace fs = std::filesystem;

namespace {

/// How many of the report's runs ask for exactly `drop`, checking that none asks for the scene
/// `plain` as shipped (the report adds its own settings, so a plain run would be a second run).
int runs_asking_for(const fs::path& scenes, const std::string& plain, const std::string& drop) {
  int asking = 0;
  for (const ffp::Study& study : ffp::validation_studies(scenes))
    for (const ffp::RunRequest& run : study.runs) {
      INFO(study.title << ": " << run.label);
      const std::string key = ffp::run_key(run, "v");
      CHECK(key != plain);
      asking += key == drop;
    }
  return asking;
}

}  // namespace

TEST_CASE("the report runs the shipped reference drop once, with its localisation output", "[reports]") {
  const fs::path scenes = fs::path(FFP_SOURCE_DIR) / "data" / "scenes";
  const std::string plain = ffp::run_key(ffp::scene_run(scenes, "ffp_reference.json", "plain"), "v");
  const std::string drop = ffp::run_key(ffp::reference_drop_run(scenes, "drop"), "v");
  REQUIRE(plain != drop);
  // The summary's reference drop, the localisation study, the two sands side by side, E' = 2500 kPa,
  // δ = 20° and the saturated drop's dry run.
  CHECK(runs_asking_for(scenes, plain, drop) == 6);
}

TEST_CASE("the report runs the shipped micropolar drop once, for the summary and the sands side by side", "[reports]") {
  const fs::path scenes = fs::path(FFP_SOURCE_DIR) / "data" / "scenes";
  const std::string plain = ffp::run_key(ffp::scene_run(scenes, "ffp_micropolar.json", "plain"), "v");
  const std::string drop = ffp::run_key(ffp::micropolar_drop_run(scenes, "drop"), "v");
  REQUIRE(plain != drop);
  CHECK(runs_asking_for(scenes, plain, drop) == 2);  // a minute of steps each time it were asked differently
}

TEST_CASE("the main job's report leaves out the studies too long for it and names them", "[reports]") {
  const fs::path scenes = fs::path(FFP_SOURCE_DIR) / "data" / "scenes";
  std::vector<ffp::Study> main_job = ffp::validation_studies(scenes);
  const std::size_t all = main_job.size();
  const std::vector<std::string> left_out = ffp::select_studies(main_job, "");
  CHECK(left_out ==
        std::vector<std::string>{"Saturated drop", "Mesh convergence of the softening run (SSMC φ'_p = 60°)"});
  CHECK(main_job.size() + left_out.size() == all);
  for (const ffp::Study& study : main_job) CHECK_FALSE(study.outside_main_job);

  std::vector<ffp::Study> asked = ffp::validation_studies(scenes);
  CHECK(ffp::select_studies(asked, "Saturated drop").empty());  // named: run, not left out
  REQUIRE(asked.size() == 1);
  CHECK(asked[0].outside_main_job);
}
