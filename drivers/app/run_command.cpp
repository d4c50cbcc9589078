/// `ffp run` and `ffp check`.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string_view>
#include <thread>

#include <sys/prctl.h>
#include <unistd.h>
#include <csignal>
#include <cstdlib>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/app/version.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/output/set_up_notice.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace fs = std::filesystem;

std::string version_string() { return std::string("ffp ") + program_version(); }

fs::path default_scenes_folder() {
  return fs::exists("data/scenes") ? fs::path("data/scenes") : fs::path(FFP_SOURCE_DIR) / "data/scenes";
}

namespace {

struct LoadedScene {
  std::unique_ptr<Job> job;
  json echo;
  fs::path scene_dir;
};

LoadedScene load(const RunOptions& a) {
  json scene = load_scene_file(a.scene_file);
  for (const auto& assignment : a.overrides) apply_override(scene, assignment);
  LoadedScene loaded;
  loaded.scene_dir = fs::path(a.scene_file).parent_path();
  loaded.job = make_job(scene, loaded.scene_dir, loaded.echo);  // the name too: it names the output folder
  return loaded;
}

/// A run started by a run pool (ffp report, ffp sweep) stops when the pool's
/// process dies, even by SIGKILL: SIGTERM then removes its temporary output,
/// so no orphan keeps writing into a cache that a rerun is filling again.
void stop_with_parent_run_pool() {
  const char* parent = std::getenv("FFP_RUN_POOL_PID");
  if (parent == nullptr) return;
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (std::to_string(::getppid()) != parent) std::raise(SIGTERM);  // the pool died before prctl
}

/// Runs the job into `directory` and marks it finished: its figures, summary.json and the
/// folder's manifest, each write checked. A file that cannot be written fails the run
/// (WriteFailure, named where the user will look for it); the target is then left as it was.
/// Returns the run's wall time.
double run_into(RunDirectory& directory, LoadedScene& loaded, RunContext& context) {
  try {
    const auto start = std::chrono::steady_clock::now();
    {
      // The run's figures, drawn by one gnuplot process once it has finished (an FFP run's six
      // took ~0.8 s CPU in six processes, ~0.4 s in one); none if it fails.
      PlotBatch figures;
      loaded.job->run(context);
      figures.finish();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    json summary = context.summary;
    summary["wall_time_s"] = wall;
    summary["steps"] = context.steps;
    summary["ffp_version"] = program_version();
    summary["threads"] = std::max(1u, std::thread::hardware_concurrency());
    summary["scene"] = loaded.echo;
    write_file_atomically(directory.path() / "summary.json", summary.dump(2) + "\n", Durability::synced);
    throw_if_interrupted();
    directory.commit(loaded.echo["kind"].get<std::string>() + " run");
    return wall;
  } catch (const WriteFailure& e) {
    throw e.moved(directory.path(), directory.target());
  }
}

/// --allow-long, or FFP_ALLOW_LONG=1 in the environment: how `ffp run --allow-long` of an
/// inverse fit and `ffp sweep --allow-long` pass it to the runs they start.
bool long_runs_allowed(const RunOptions& a) {
  const char* allowed = std::getenv("FFP_ALLOW_LONG");
  return a.allow_long || (allowed != nullptr && std::string_view(allowed) == "1");
}

/// Says what an MPM run will cost before it starts, and refuses one estimated above a day
/// unless the user allows it. The probe behind the estimate (0.2 s and a second build of the
/// model) is spent only where the run could last a day even at the slowest rate of any scene.
void weigh_cost(Job& job, const RunOptions& a, const std::string& what) {
  std::optional<RunCost> cost = job.cost(false);
  if (!cost || !cost->could_last(kLongRun_s)) return;
  cost = job.cost(true);
  if (cost->wall_s() > kLongRun_s && !long_runs_allowed(a))
    throw SceneError("end_time_s: " + describe_cost(*cost) +
                     ", above a day; pass --allow-long to run it anyway, or shorten end_time_s or coarsen the mesh");
  if (!a.quiet) std::fprintf(stderr, "%s: %s\n", what.c_str(), describe_cost(*cost).c_str());
}

}  // namespace

int command_run(const RunOptions& a) {
  stop_with_parent_run_pool();
  try {
    if (a.allow_long) ::setenv("FFP_ALLOW_LONG", "1", 1);  // for the runs this one starts
    std::optional<SetUpNotice> setting_up;
    if (!a.quiet) setting_up.emplace("setting up " + a.scene_file);
    LoadedScene loaded = load(a);
    weigh_cost(*loaded.job, a, loaded.echo["kind"].get<std::string>() + " " + loaded.echo["name"].get<std::string>());
    setting_up.reset();
    const fs::path out = a.out.value_or(fs::path("results") / loaded.echo["name"].get<std::string>());
    RunDirectory directory(out, "--out", a.force);
    RunContext context;
    context.out_dir = directory.path();
    context.scene_dir = loaded.scene_dir;
    context.show_progress = !a.quiet;
    context.jobs = a.jobs;
    context.slurm = a.slurm;
    const double wall = run_into(directory, loaded, context);
    if (!a.quiet) std::fprintf(stderr, "wrote %s (%.2f s)\n", out.string().c_str(), wall);
    return 0;
  } catch (...) {
    return exit_code_of_current_exception("no result written");
  }
}

int command_check(const RunOptions& a) {
  try {
    LoadedScene loaded = load(a);
    std::ostringstream text;  // check's result, written at once and checked: `ffp check S > /dev/full` fails
    text << a.scene_file << ": valid " << loaded.echo["kind"].get<std::string>() << " scene '"
         << loaded.echo["name"].get<std::string>() << "'\n";
    loaded.job->describe(text);
    if (const std::optional<RunCost> cost = loaded.job->cost(true)) text << "cost: " << describe_cost(*cost) << "\n";
    text << "resolved scene (defaults filled in):\n" << loaded.echo.dump(2) << "\n";
    write_standard_output(text.str());
    return 0;
  } catch (...) {
    return exit_code_of_current_exception();
  }
}

}  // namespace ffp
