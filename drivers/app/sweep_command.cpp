/// `ffp sweep`: every combination of --set key=v1,v2,... as an independent run, on
/// this machine's process pool, or emitted for a scheduler (--emit; --scheduler
/// slurm submits and waits); `ffp collect` turns an emitted folder into sweep.csv.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "drivers/app/commands.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/app/sweep_cases.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "reports/run_pool.hpp"
#include "reports/slurm_jobs.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

/// Split "a,b,[1,2]" at the commas outside brackets and quotes.
std::vector<std::string> split_values(const std::string& list) {
  std::vector<std::string> values;
  std::string current;
  int depth = 0;
  bool in_quotes = false;
  for (char c : list) {
    if (c == '"') in_quotes = !in_quotes;
    if (!in_quotes && (c == '[' || c == '{')) ++depth;
    if (!in_quotes && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !in_quotes) {
      values.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  values.push_back(current);
  return values;
}

/// Writes sweep.csv from the collected cases, lists the missing and failed ones; exit 0 only when all finished.
int report_collected(const fs::path& dir, const std::vector<std::string>& keys, const std::vector<CaseResult>& cases) {
  write_file_atomically(dir / kSweepTable, sweep_table(keys, cases), Durability::synced);
  std::size_t missing = 0, failed = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string what;
    for (const auto& o : cases[i].overrides) what += (what.empty() ? "" : " ") + o;
    if (cases[i].exit_code < 0) {
      ++missing;
      std::fprintf(stderr, "  case %04zu (%s): missing\n", i, what.c_str());
    } else if (cases[i].exit_code != 0) {
      ++failed;
      std::fprintf(stderr, "  case %04zu (%s): failed (exit %d): %s\n", i, what.c_str(), cases[i].exit_code,
                   cases[i].error.c_str());
    }
  }
  std::fprintf(stderr, "wrote %s: %zu cases, %zu finished, %zu failed, %zu missing\n",
               (dir / kSweepTable).string().c_str(), cases.size(), cases.size() - missing - failed, failed, missing);
  return missing == 0 && failed == 0 ? 0 : 1;
}

/// Submits DIR/slurm.sbatch, waits until the array has left the queue, then collects.
int run_on_slurm(const fs::path& dir, std::size_t cases) {
  const std::string job = slurm_submit(dir / "slurm.sbatch");
  std::fprintf(stderr, "sweep: Slurm job %s, %zu array tasks; waiting (ffp collect %s gives the table at any time)\n",
               job.c_str(), cases, dir.string().c_str());
  std::size_t last_finished = static_cast<std::size_t>(-1);
  slurm_wait(job, [&] {
    throw_if_interrupted();
    std::vector<std::string> keys;
    std::size_t finished = 0;
    for (const CaseResult& c : collect_sweep(dir, keys)) finished += c.exit_code >= 0;
    if (finished != last_finished) std::fprintf(stderr, "sweep: %zu of %zu cases done\n", finished, cases);
    last_finished = finished;
  });
  std::vector<std::string> keys;
  const std::vector<CaseResult> results = collect_sweep(dir, keys);
  return report_collected(dir, keys, results);
}

}  // namespace

int command_sweep(const SweepOptions& options) {
  try {
    const std::string& scene_file = options.scene_file;
    fs::path out = options.out;
    const fs::path& emit = options.emit;
    const int jobs = options.jobs, threads = options.threads;
    const bool force = options.force, slurm = options.slurm;
    std::vector<SweepAxis> axes;
    for (const std::string& assignment : options.axes) {
      const auto eq = assignment.find('=');
      if (eq == std::string::npos || eq == 0) throw SceneError("--set " + assignment + ": expected key=v1,v2,...");
      axes.push_back({assignment.substr(0, eq), split_values(assignment.substr(eq + 1))});
    }
    if (!emit.empty() && (slurm || !out.empty()))
      throw SceneError("--emit: writes the case folder only; give --out with --scheduler slurm to also submit it");

    std::string name;
    const std::vector<SweepCase> cases = expand_sweep(scene_file, axes, name);
    std::vector<std::string> keys;
    for (const SweepAxis& axis : axes) keys.push_back(axis.key);

    if (!emit.empty() || slurm) {
      const fs::path dir = !emit.empty() ? emit : (out.empty() ? fs::path("results") / (name + "-sweep") : out);
      claim_persistent_folder(dir, !emit.empty() ? "--emit" : "--out", "sweep", force);
      fs::remove(dir / kSweepTable);
      EmitOptions options;
      options.ffp_binary = fs::read_symlink("/proc/self/exe");
      options.threads_per_case = threads;
      options.parallel_jobs = std::max(jobs, 1);
      options.job_name = "ffp-" + name;
      emit_sweep(dir, cases, options);
      std::fprintf(stderr,
                   "sweep: %zu cases in %s (cases.tsv, slurm.sbatch, parallel.sh); ffp collect %s builds sweep.csv\n",
                   cases.size(), dir.string().c_str(), dir.string().c_str());
      return slurm ? run_on_slurm(dir, cases.size()) : 0;
    }

    if (out.empty()) out = fs::path("results") / (name + "-sweep");
    claim_persistent_folder(out, "--out", "sweep", force);
    claim_persistent_folder(out / "runs", "--out", "run cache", force);
    // A table from an earlier sweep into this folder must not pass for this one's.
    fs::remove(out / kSweepTable);
    std::vector<RunRequest> requests;
    for (const SweepCase& c : cases) requests.push_back({c.label, scene_file, c.overrides});
    std::fprintf(stderr, "sweep: %zu runs, %d at a time, into %s\n", requests.size(), jobs, out.string().c_str());
    const auto outcomes = run_all("/proc/self/exe", requests, out / "runs", program_version(), jobs);
    std::vector<CaseResult> results;
    int failures = 0;
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      results.push_back({cases[i].overrides, outcomes[i].out_dir, outcomes[i].exit_code, outcomes[i].error});
      if (outcomes[i].exit_code != 0) {
        ++failures;
        std::fprintf(stderr, "  %s failed (exit %d): %s\n", requests[i].label.c_str(), outcomes[i].exit_code,
                     outcomes[i].error.c_str());
      }
    }
    write_file_atomically(out / kSweepTable, sweep_table(keys, results), Durability::synced);
    std::fprintf(stderr, "wrote %s\n", (out / kSweepTable).string().c_str());
    return failures == 0 ? 0 : 1;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const Interrupted&) {
    std::fputs("interrupted\n", stderr);
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

int command_collect(const fs::path& dir) {
  try {
    std::vector<std::string> keys;
    const std::vector<CaseResult> cases = collect_sweep(dir, keys);
    return report_collected(dir, keys, cases);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

}  // namespace ffp
