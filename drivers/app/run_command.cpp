/// `ffp run` and `ffp check`.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <thread>

#include <sys/prctl.h>
#include <unistd.h>
#include <csignal>
#include <cstdlib>

#include "drivers/app/commands.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/app/version.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
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
  loaded.job = make_job(scene, loaded.scene_dir, loaded.echo);
  const std::string name = loaded.echo.value("name", "");
  const auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  };
  const bool safe = !name.empty() && name.size() <= 100 && std::isalnum(static_cast<unsigned char>(name[0])) &&
                    std::all_of(name.begin(), name.end(), allowed);
  if (!safe)
    throw SceneError("name: '" + name +
                     "' must be 1–100 letters, digits, '_', '-' or '.' (it names the output folder)");
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

int report_error(const std::exception& e, int code) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return code;
}

}  // namespace

int command_run(const RunOptions& a) {
  stop_with_parent_run_pool();
  try {
    LoadedScene loaded = load(a);
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
  } catch (const SceneError& e) {
    return report_error(e, 2);
  } catch (const Interrupted& e) {
    std::fputs("interrupted: no result written\n", stderr);
    return 130;
  } catch (const RunFailure& e) {
    if (!e.reproducer().is_object()) return report_error(e, 1);
    const fs::path file = fs::path("failed-step.json");
    try {
      write_file_atomically(file, e.reproducer().dump(2) + "\n");
      std::fprintf(stderr, "error: %s\n  a scene that repeats the failing step: %s\n", e.what(), file.string().c_str());
    } catch (const WriteFailure& unsaved) {
      std::fprintf(stderr, "error: %s\n  (the scene that repeats the failing step was not saved: %s)\n", e.what(),
                   unsaved.what());
    }
    return 1;
  } catch (const std::exception& e) {
    return report_error(e, 1);
  }
}

int command_check(const RunOptions& a) {
  try {
    LoadedScene loaded = load(a);
    std::ostringstream text;  // check's result, written at once and checked: `ffp check S > /dev/full` fails
    text << a.scene_file << ": valid " << loaded.echo["kind"].get<std::string>() << " scene '"
         << loaded.echo["name"].get<std::string>() << "'\n";
    loaded.job->describe(text);
    text << "resolved scene (defaults filled in):\n" << loaded.echo.dump(2) << "\n";
    write_standard_output(text.str());
    return 0;
  } catch (const SceneError& e) {
    return report_error(e, 2);
  } catch (const std::exception& e) {
    return report_error(e, 1);
  }
}

}  // namespace ffp
