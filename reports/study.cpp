#include "reports/study.hpp"

#include <fstream>

namespace ffp {

nlohmann::json StudyResults::summary(std::size_t i) const {
  if (!ok(i)) return nlohmann::json::object();
  std::ifstream in(outcomes_[i].out_dir / "summary.json");
  if (!in) return nlohmann::json::object();
  return nlohmann::json::parse(in);
}

CsvData StudyResults::history(std::size_t i) const {
  if (!ok(i) || !std::filesystem::exists(outcomes_[i].out_dir / "history.csv")) return {};
  return read_numeric_csv(outcomes_[i].out_dir / "history.csv");
}

StudyResults StudyResults::extended(const std::vector<RunRequest>& requests,
                                    const std::vector<RunOutcome>& outcomes) const {
  StudyResults more = *this;
  more.requests_.insert(more.requests_.end(), requests.begin(), requests.end());
  more.outcomes_.insert(more.outcomes_.end(), outcomes.begin(), outcomes.end());
  return more;
}

std::vector<std::string> select_studies(std::vector<Study>& studies, const std::string& only) {
  std::vector<std::string> left_out;
  if (!only.empty()) {
    std::erase_if(studies, [&](const Study& s) { return s.title.find(only) == std::string::npos; });
    return left_out;
  }
  for (const Study& s : studies)
    if (s.outside_main_job) left_out.push_back(s.title);
  std::erase_if(studies, [](const Study& s) { return s.outside_main_job; });
  return left_out;
}

double StudyResults::total_wall_time_s() const {
  double total = 0.0;
  for (std::size_t i = 0; i < size(); ++i) total += summary(i).value("wall_time_s", 0.0);
  return total;
}

}  // namespace ffp
