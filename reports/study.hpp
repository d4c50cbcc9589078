#pragma once
/// A study of the validation report: the runs it needs and how it turns their
/// outputs into figures, tables and text.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/output/csv_writer.hpp"
#include "reports/markdown.hpp"
#include "reports/run_pool.hpp"

namespace ffp {

/// What a study's writer sees: its own runs' outcomes, in the order it asked.
class StudyResults {
 public:
  StudyResults(std::vector<RunRequest> requests, std::vector<RunOutcome> outcomes)
      : requests_(std::move(requests)), outcomes_(std::move(outcomes)) {}
  std::size_t size() const { return outcomes_.size(); }
  bool ok(std::size_t i) const { return outcomes_[i].exit_code == 0; }
  const RunRequest& request(std::size_t i) const { return requests_[i]; }
  const RunOutcome& outcome(std::size_t i) const { return outcomes_[i]; }
  nlohmann::json summary(std::size_t i) const;  ///< {} when the run failed
  CsvData history(std::size_t i) const;         ///< empty when the run failed
  std::filesystem::path file(std::size_t i, const std::string& relative) const {
    return outcomes_[i].out_dir / relative;
  }
  /// Sum of the run wall times recorded in the summaries.
  double total_wall_time_s() const;
  /// These results followed by more runs' (a study's follow-up runs).
  StudyResults extended(const std::vector<RunRequest>& requests, const std::vector<RunOutcome>& outcomes) const;

 private:
  std::vector<RunRequest> requests_;
  std::vector<RunOutcome> outcomes_;
};

struct StudyOutput {
  Markdown& document;
  std::filesystem::path figures_dir;  ///< write PNGs here
  std::string figures_relative;       ///< how report.md refers to figures_dir
  std::filesystem::path tables_dir;   ///< write CSV tables here
};

struct Study {
  std::string title;
  std::vector<RunRequest> runs;
  /// Runs that need the results of `runs` (e.g. an FFP run fed the η a
  /// calibration found): asked for once `runs` are done; their outcomes follow
  /// those of `runs` in what `write` sees. Empty: none.
  std::function<std::vector<RunRequest>(const StudyResults&)> follow_up;
  std::function<void(const StudyResults&, StudyOutput&)> write;
  /// Too long for the main job: run only when `ffp report --only` names it; the report lists it
  /// with that command otherwise.
  bool outside_main_job = false;
};

/// Every study of the validation report, reading scenes from `scenes_dir`.
std::vector<Study> validation_studies(const std::filesystem::path& scenes_dir);

/// Keeps the studies whose title contains `only`, or with `only` empty those of the main job.
/// Returns the titles of the studies left out for being outside the main job (none with `only`).
std::vector<std::string> select_studies(std::vector<Study>& studies, const std::string& only);

}  // namespace ffp
