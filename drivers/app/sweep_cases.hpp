#pragma once
/// The cases of a sweep (every combination of --set key=v1,v2,…) and the two
/// ways of running them: this machine's process pool, or a scheduler through
/// files a cluster can run (a case folder: cases.tsv, one resolved scene per
/// case, run_case.sh, slurm.sbatch, parallel.sh), collected afterwards into
/// the same sweep.csv.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ffp {

struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

struct SweepCase {
  std::vector<std::string> overrides;  ///< "key=value", one per axis, in axis order
  std::string label;                   ///< name_value_value…
  nlohmann::json scene;                ///< the scene with the overrides applied (file paths absolute)
};

/// Every combination, each validated (SceneError on the first bad one).
std::vector<SweepCase> expand_sweep(const std::filesystem::path& scene_file, const std::vector<SweepAxis>& axes,
                                    std::string& scene_name);

/// One finished, failed or missing case, as the table needs it.
struct CaseResult {
  std::vector<std::string> overrides;
  std::filesystem::path out_dir;
  int exit_code = -1;  ///< -1: missing (never ran, or still running)
  std::string error;   ///< last stderr line of a failed case
};

/// sweep.csv: the swept values, exit_code, out_dir, then every scalar figure of the summaries.
std::string sweep_table(const std::vector<std::string>& keys, const std::vector<CaseResult>& cases);

/// How the launch files run each case.
struct EmitOptions {
  std::filesystem::path ffp_binary;  ///< absolute
  int threads_per_case = 1;          ///< OpenMP threads and Slurm --cpus-per-task
  int parallel_jobs = 2;             ///< GNU parallel's default --jobs
  std::string job_name = "ffp-sweep";
};

/// Writes DIR/cases.tsv, DIR/scenes/case_NNNN.json, DIR/run_case.sh, DIR/slurm.sbatch and
/// DIR/parallel.sh; the cases run into DIR/runs/case_NNNN with logs in DIR/logs.
void emit_sweep(const std::filesystem::path& dir, const std::vector<SweepCase>& cases, const EmitOptions& options);

/// Reads an emitted folder back: one result per case of cases.tsv (SceneError if it is not one).
std::vector<CaseResult> collect_sweep(const std::filesystem::path& dir, std::vector<std::string>& keys);

}  // namespace ffp
