#pragma once
/// A sweep's cases read back, as sweep.csv and `ffp collect` need them: each
/// finished case's summary.json, checked before its figures are put beside
/// its values. A summary that is missing, corrupt, or echoes another scene
/// than the case's (its stored scene hash) makes the case unusable, never a row
/// of numbers under the wrong label.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ffp {

/// One finished, failed, unusable or missing case.
struct CaseResult {
  std::string id;  ///< "0003" in an emitted sweep; "" for a local one
  std::vector<std::string> overrides;
  std::filesystem::path out_dir;
  int exit_code = -1;      ///< of its run; -1: missing (never ran, or still running)
  std::string error;       ///< why it failed, or why its finished result cannot be used
  nlohmann::json summary;  ///< its summary.json once read and checked; null otherwise

  bool finished() const { return exit_code == 0 && !summary.is_null(); }
  bool unusable() const { return exit_code == 0 && summary.is_null(); }
};

/// Reads a run's summary.json into `result.summary` (exit_code 0 and out_dir set). When it is missing or
/// cannot be parsed, or (if `expected_hash` is given) echoes a scene with another hash, leaves the summary
/// null and says why in `result.error`, naming the file; `expected_echo` (called only then, may be empty)
/// gives the case's resolved scene, to name the first key that differs.
void read_case_summary(CaseResult& result, const std::string& expected_hash = "",
                       const std::function<nlohmann::json()>& expected_echo = {});

/// sweep.csv (RFC 4180): the swept values, exit_code (empty unless the run ended and its result is
/// usable or it failed), out_dir, then every scalar figure of the usable summaries.
std::string sweep_table(const std::vector<std::string>& keys, const std::vector<CaseResult>& cases);

/// Reads an emitted folder back: one result per case of cases.tsv (SceneError if it is not one), each
/// finished case's summary read and checked against the case's scene hash.
std::vector<CaseResult> collect_sweep(const std::filesystem::path& dir, std::vector<std::string>& keys);

}  // namespace ffp
