#pragma once
/// The cases of a sweep (every combination of --set key=v1,v2,…) and the files
/// a scheduler runs them from (a case folder: cases.tsv, one resolved scene per
/// case, run_case.sh, slurm.sbatch, parallel.sh). sweep_results.hpp reads the
/// finished cases back.
///
/// Each case carries the hash of its resolved scene (scene_hash.hpp), stored in
/// cases.tsv. A folder emitted again keeps a finished case only where the new
/// case's scene is the one it ran; where it differs, the emit is refused unless
/// the user asks for those cases to run afresh, so that no result is ever
/// labelled with values it did not run with.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ffp {

struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

/// The axes of `--set key=v1,v2,...` arguments (values split at the commas
/// outside brackets and quotes). SceneError on an argument without '=', a key
/// given twice or a value given twice for one key.
std::vector<SweepAxis> sweep_axes(const std::vector<std::string>& arguments);

struct SweepCase {
  std::vector<std::string> overrides;  ///< "key=value", one per axis, in axis order
  std::string label;                   ///< name_value_value…
  nlohmann::json scene;                ///< the scene with the overrides applied (file paths absolute)
  nlohmann::json echo;                 ///< `scene` resolved (defaults filled in), as its run's summary.json echoes it
  std::string scene_hash;              ///< scene_hash(echo)
};

/// Every combination, each validated (SceneError on the first bad one).
std::vector<SweepCase> expand_sweep(const std::filesystem::path& scene_file, const std::vector<SweepAxis>& axes,
                                    std::string& scene_name);

/// How the launch files run each case.
struct EmitOptions {
  std::filesystem::path ffp_binary;  ///< absolute
  int threads_per_case = 1;          ///< OpenMP threads and Slurm --cpus-per-task
  int parallel_jobs = 2;             ///< GNU parallel's default --jobs
  std::string job_name = "ffp-sweep";
  bool allow_long = false;  ///< each case's run takes --allow-long
};

/// What an earlier emit into a folder left that the new cases must not inherit.
struct EarlierCases {
  /// Finished cases whose result ran another scene than the new case of the same number:
  /// "case 0000 ran with material.E_kPa = 1000.0 where this sweep has 50000.0".
  std::vector<std::string> differing_results;
  std::vector<std::filesystem::path> stale;  ///< their run folders, and the logs of every case whose scene changed
  bool any_scene_changed = false;            ///< GNU parallel's joblog then describes other cases
};

/// Reads only: compares each new case with the folder's finished run of the same number (the scene its
/// summary.json echoes) and with the earlier cases.tsv (for the logs of cases that did not finish).
EarlierCases find_earlier_cases(const std::filesystem::path& dir, const std::vector<SweepCase>& cases);

/// Removes what `earlier` found stale, so that those cases run afresh (and GNU parallel's joblog when any
/// case changed: its --resume would skip them; run_case.sh still skips the finished ones).
void retire_earlier_cases(const std::filesystem::path& dir, const EarlierCases& earlier);

/// Writes DIR/cases.tsv, DIR/scenes/case_NNNN.json, DIR/run_case.sh, DIR/slurm.sbatch and
/// DIR/parallel.sh; the cases run into DIR/runs/case_NNNN with logs in DIR/logs.
void emit_sweep(const std::filesystem::path& dir, const std::vector<SweepCase>& cases, const EmitOptions& options);

/// "0003": a case's number as its files name it.
std::string case_id(std::size_t index);

/// cases.tsv's header; a folder emitted before scene hashes has the same without the last column.
inline constexpr const char* kCaseListHeader = "case\toverrides\tscene\tout_dir\tscene_hash";

/// One row of cases.tsv.
struct CaseRow {
  std::string id;
  std::vector<std::string> overrides;
  std::string scene;       ///< relative to the folder
  std::string out_dir;     ///< relative to the folder
  std::string scene_hash;  ///< "" in a folder emitted before scene hashes
};

/// DIR/cases.tsv read back (SceneError naming the file when it is not one).
std::vector<CaseRow> read_case_list(const std::filesystem::path& dir);

}  // namespace ffp
