/// `ffp sweep`: every combination of --set key=v1,v2,... as an independent run, on
/// this machine's process pool, or emitted for a scheduler (--emit; --scheduler
/// slurm submits and waits); `ffp collect` turns an emitted folder into sweep.csv.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/app/sweep_cases.hpp"
#include "drivers/app/sweep_results.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "reports/run_pool.hpp"
#include "reports/slurm_jobs.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

/// Writes sweep.csv from the collected cases and lists every missing, failed and unusable one (a finished
/// run whose summary is missing, corrupt or of another scene); exit 0 only when all finished.
int report_collected(const fs::path& dir, const std::vector<std::string>& keys, const std::vector<CaseResult>& cases) {
  write_file_atomically(dir / kSweepTable, sweep_table(keys, cases), Durability::synced);
  std::size_t missing = 0, failed = 0, unusable = 0;
  for (const CaseResult& c : cases) {
    std::string what;
    for (const auto& o : c.overrides) what += (what.empty() ? "" : " ") + o;
    if (c.exit_code < 0) {
      ++missing;
      std::fprintf(stderr, "  case %s (%s): missing\n", c.id.c_str(), what.c_str());
    } else if (c.unusable()) {
      ++unusable;
      std::fprintf(stderr, "  case %s (%s): unusable: %s\n", c.id.c_str(), what.c_str(), c.error.c_str());
    } else if (c.exit_code != 0) {
      ++failed;
      std::fprintf(stderr, "  case %s (%s): failed (exit %d): %s\n", c.id.c_str(), what.c_str(), c.exit_code,
                   c.error.c_str());
    }
  }
  const std::size_t finished = cases.size() - missing - failed - unusable;
  std::fprintf(stderr, "wrote %s: %zu cases, %zu finished, %zu failed, %zu missing%s\n",
               (dir / kSweepTable).string().c_str(), cases.size(), finished, failed, missing,
               unusable ? (", " + std::to_string(unusable) + " unusable").c_str() : "");
  return finished == cases.size() ? 0 : 1;
}

/// Submits DIR/slurm.sbatch, waits until the array has left the queue, then collects.
int run_on_slurm(const fs::path& dir, std::size_t cases) {
  const std::string job = slurm_submit(dir / "slurm.sbatch");
  std::fprintf(stderr, "sweep: Slurm job %s, %zu array tasks; waiting (ffp collect %s gives the table at any time)\n",
               job.c_str(), cases, dir.string().c_str());
  std::size_t last_finished = static_cast<std::size_t>(-1);
  try {
    slurm_wait(job, [&] {
      throw_if_interrupted();
      std::vector<std::string> keys;
      std::size_t finished = 0;
      for (const CaseResult& c : collect_sweep(dir, keys)) finished += c.exit_code >= 0;
      if (finished != last_finished) std::fprintf(stderr, "sweep: %zu of %zu cases done\n", finished, cases);
      last_finished = finished;
    });
  } catch (const Interrupted&) {
    // Ctrl-C stops the runs this command started, as a local sweep's (each removes its temporary
    // folder on Slurm's SIGTERM); the finished cases stay, and a resubmission runs only the rest.
    std::fprintf(stderr, "sweep: cancelling Slurm job %s (finished cases stay; sbatch %s runs the rest)\n", job.c_str(),
                 (dir / "slurm.sbatch").string().c_str());
    slurm_cancel(job);
    throw;
  }
  std::vector<std::string> keys;
  const std::vector<CaseResult> results = collect_sweep(dir, keys);
  return report_collected(dir, keys, results);
}

/// --emit DIR, or --scheduler slurm --out DIR: the case folder and its launch files. A finished case of an
/// earlier emit into DIR is kept only where its scene is unchanged; where it differs, the emit is refused
/// (before anything in DIR changes) unless --force asks for those cases to run afresh. Refusing is the
/// default because the results at stake may be hours of a cluster's time, and another folder keeps them.
int emit_cases(const fs::path& dir, const std::string& option, const std::vector<SweepCase>& cases,
               const SweepOptions& options, const std::string& name) {
  claim_persistent_folder(dir, option, "sweep", options.force);
  const EarlierCases earlier = find_earlier_cases(dir, cases);
  const std::size_t differing = earlier.differing_results.size();
  if (differing > 0 && !options.force)
    throw SceneError(option + " " + dir.string() + ": " + earlier.differing_results.front() +
                     (differing > 1 ? " (" + std::to_string(differing) + " finished cases differ)" : "") +
                     ": choose another folder, or pass --force to discard those results and run them afresh");
  fs::remove(dir / kSweepTable);
  retire_earlier_cases(dir, earlier);
  if (differing > 0)
    std::fprintf(stderr, "sweep: discarded the results of %zu finished case(s) that ran other scenes\n", differing);
  EmitOptions emit;
  emit.ffp_binary = fs::read_symlink("/proc/self/exe");
  emit.threads_per_case = options.threads;
  emit.parallel_jobs = std::max(options.jobs, 1);
  emit.job_name = "ffp-" + name;
  emit.allow_long = options.allow_long;
  emit_sweep(dir, cases, emit);
  std::fprintf(stderr,
               "sweep: %zu cases in %s (cases.tsv, slurm.sbatch, parallel.sh); ffp collect %s builds sweep.csv\n",
               cases.size(), dir.string().c_str(), dir.string().c_str());
  return options.slurm ? run_on_slurm(dir, cases.size()) : 0;
}

/// The cases on this machine's process pool, into out/runs (a cache keyed by each scene's content and the
/// program, run_key: a finished run is reused only for the same scene), then out/sweep.csv.
int run_here(const fs::path& out, const std::vector<SweepCase>& cases, const std::vector<std::string>& keys,
             const SweepOptions& options) {
  claim_persistent_folder(out, "--out", "sweep", options.force);
  claim_persistent_folder(out / "runs", "--out", "run cache", options.force);
  // A table from an earlier sweep into this folder must not pass for this one's.
  fs::remove(out / kSweepTable);
  std::vector<RunRequest> requests;
  for (const SweepCase& c : cases) requests.push_back({c.label, options.scene_file, c.overrides});
  std::fprintf(stderr, "sweep: %zu runs, %d at a time, into %s\n", requests.size(), options.jobs, out.string().c_str());
  const auto outcomes = run_all("/proc/self/exe", requests, out / "runs", program_version(), options.jobs);
  std::vector<CaseResult> results;
  int failures = 0;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    CaseResult r;
    r.overrides = cases[i].overrides;
    r.out_dir = outcomes[i].out_dir;
    r.exit_code = outcomes[i].exit_code;
    r.error = outcomes[i].error;
    if (r.exit_code == 0) read_case_summary(r);
    if (!r.finished()) {
      ++failures;
      if (r.unusable())
        std::fprintf(stderr, "  %s unusable: %s\n", requests[i].label.c_str(), r.error.c_str());
      else
        std::fprintf(stderr, "  %s failed (exit %d): %s\n", requests[i].label.c_str(), r.exit_code, r.error.c_str());
    }
    results.push_back(std::move(r));
  }
  write_file_atomically(out / kSweepTable, sweep_table(keys, results), Durability::synced);
  std::fprintf(stderr, "wrote %s\n", (out / kSweepTable).string().c_str());
  return failures == 0 ? 0 : 1;
}

}  // namespace

int command_sweep(const SweepOptions& options) {
  try {
    if (options.allow_long) ::setenv("FFP_ALLOW_LONG", "1", 1);  // read by every case's `ffp run`
    const std::vector<SweepAxis> axes = sweep_axes(options.axes);
    if (!options.emit.empty() && (options.slurm || !options.out.empty()))
      throw SceneError("--emit: writes the case folder only; give --out with --scheduler slurm to also submit it");
    std::string name;
    const std::vector<SweepCase> cases = expand_sweep(options.scene_file, axes, name);
    std::vector<std::string> keys;
    for (const SweepAxis& axis : axes) keys.push_back(axis.key);
    const fs::path out = options.out.empty() ? fs::path("results") / (name + "-sweep") : options.out;
    if (!options.emit.empty()) return emit_cases(options.emit, "--emit", cases, options, name);
    if (options.slurm) return emit_cases(out, "--out", cases, options, name);
    return run_here(out, cases, keys, options);
  } catch (...) {
    return exit_code_of_current_exception();
  }
}

int command_collect(const fs::path& dir) {
  try {
    std::vector<std::string> keys;
    const std::vector<CaseResult> cases = collect_sweep(dir, keys);
    return report_collected(dir, keys, cases);
  } catch (...) {
    return exit_code_of_current_exception();
  }
}

}  // namespace ffp
