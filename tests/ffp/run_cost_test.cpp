/// The cost probe behind `ffp check`'s estimated wall time and `ffp run`'s
/// refusal of runs above a day (drivers/app/run_cost.hpp): it counts the steps
/// the run will take, measures a rate, and leaves the run exactly as it would
/// have been without it.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "drivers/app/job.hpp"
#include "drivers/app/run_cost.hpp"
#include "ffp_test_support.hpp"
#include "mpm/simulation.hpp"

using namespace ffp;
using ffp::test::scene_path;
using ffp::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

std::unique_ptr<Job> job_of(const std::string& scene, const std::vector<std::string>& overrides) {
  json j = load_scene_file(scene_path(scene));
  for (const std::string& o : overrides) apply_override(j, o);
  json echo;
  return make_job(j, fs::path(scene_path(scene)).parent_path(), echo);
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// history.csv of the job's run into `dir`.
std::string history_of(Job& job, const fs::path& dir) {
  fs::create_directories(dir);
  RunContext context;
  context.out_dir = dir;
  context.show_progress = false;
  job.run(context);
  return read_text(dir / "history.csv");
}

}  // namespace

TEST_CASE("a probed run is the run never probed, to the last digit", "[ffp][cost]") {
  // The probe steps the job's own model, then the job builds it afresh: the run must not see it.
  struct Case {
    std::string scene;
    std::vector<std::string> overrides;
  };
  for (const Case& c :
       {Case{"ffp_reference.json", {"mesh.min_cell_m=0.02", "end_time_s=0.02", "output.field_times_s=[]"}},
        Case{"mpm_wave_column.json", {"end_time_s=0.004", "output.field_interval_s=null"}}}) {
    DYNAMIC_SECTION(c.scene) {
      ScratchDir scratch;
      const std::unique_ptr<Job> plain = job_of(c.scene, c.overrides), probed = job_of(c.scene, c.overrides);
      const std::optional<RunCost> cost = probed->cost(true);
      REQUIRE(cost);
      REQUIRE(cost->seconds_per_particle_step);
      const std::string expected = history_of(*plain, scratch.path() / "plain");
      CHECK(expected.size() > 100);
      CHECK(history_of(*probed, scratch.path() / "probed") == expected);
    }
  }
}

TEST_CASE("the probe counts the steps to end_time_s and measures a rate", "[ffp][cost]") {
  // The wave column's step is the elastic CFL step, the same at every step (the column moves at
  // 0.1 m/s against c_p ≈ 83 m/s): the steps to end_time_s are end_time_s/Δt, rounded up.
  const std::unique_ptr<Job> job = job_of("mpm_wave_column.json", {"end_time_s=0.5"});
  const std::optional<RunCost> planned = job->cost(false);
  REQUIRE(planned);
  CHECK_FALSE(planned->seconds_per_particle_step);
  CHECK(planned->particles == 800);
  const std::optional<RunCost> measured = job->cost(true);
  REQUIRE(measured);
  REQUIRE(measured->seconds_per_particle_step);
  CHECK(*measured->seconds_per_particle_step > 0.0);
  CHECK(measured->probe_steps >= 3);
  CHECK(measured->probe_steps <= 200);
  CHECK(measured->steps == Approx(planned->steps).epsilon(0.01));  // Δt moves by the column's speed only
  CHECK(measured->wall_s() == Approx(measured->steps * 800 * *measured->seconds_per_particle_step).epsilon(1e-12));
  CHECK(describe_cost(*measured).find("estimated wall time") != std::string::npos);
}

TEST_CASE("a run is probed only where it could last a day at the slowest rate of any scene", "[ffp][cost]") {
  RunCost cost;
  cost.particles = 6086;
  cost.steps = 2241;  // the reference FFP: 1.4e7 particle-steps, 3.8 h even at 1 ms each
  CHECK_FALSE(cost.could_last(kLongRun_s));
  cost.steps = 1.43e8;  // the same drop to end_time_s = 1e4 s
  CHECK(cost.could_last(kLongRun_s));
}

TEST_CASE("durations read as a person would say them", "[ffp][cost]") {
  CHECK(format_duration(12.0) == "12 s");
  CHECK(format_duration(210.0) == "3.5 min");
  CHECK(format_duration(5.2 * 3600.0) == "5.2 h");
  CHECK(format_duration(12.3 * 86400.0) == "12.3 days");
}
