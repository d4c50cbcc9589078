#include "reports/studies/study_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "drivers/output/checked_write.hpp"

namespace ffp {

namespace fs = std::filesystem;

bool include_run_figure(const StudyResults& results, std::size_t run, const std::string& relative_png,
                        const std::string& name, const std::string& caption, StudyOutput& out) {
  const fs::path source = results.file(run, relative_png);
  if (!results.ok(run) || !fs::exists(source)) {
    out.document.paragraph("*(Figure missing: " + caption + " — the run failed or gnuplot was not available.)*");
    return false;
  }
  copy_file_atomically(source, out.figures_dir / name);
  out.document.figure(out.figures_relative + "/" + name, caption);
  return true;
}

std::size_t history_row_at(const CsvData& history, double time_s) {
  const auto& t = history.column("time_s");
  std::size_t best = 0;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - time_s) < std::abs(t[best] - time_s)) best = k;
  return best;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.size() < 2 || at < x.front() || at > x.back()) return std::nan("");
  const auto upper = std::upper_bound(x.begin(), x.end(), at);
  if (upper == x.end()) return y.back();
  const std::size_t j = static_cast<std::size_t>(upper - x.begin());
  if (j == 0) return y.front();
  const double w = (at - x[j - 1]) / (x[j] - x[j - 1]);
  return (1 - w) * y[j - 1] + w * y[j];
}

std::string scientific(double value, int digits) {
  if (!std::isfinite(value)) return "–";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, value);
  return buffer;
}

RunRequest scene_run(const fs::path& scenes_dir, const std::string& scene_file, const std::string& label,
                     std::vector<std::string> overrides) {
  return RunRequest{label, scenes_dir / scene_file, std::move(overrides)};
}

RunRequest reference_drop_run(const fs::path& scenes_dir, const std::string& label,
                              std::vector<std::string> overrides) {
  overrides.emplace_back("output.localisation=true");
  return scene_run(scenes_dir, "ffp_reference.json", label, std::move(overrides));
}

RunRequest micropolar_drop_run(const fs::path& scenes_dir, const std::string& label) {
  RunRequest run = scene_run(scenes_dir, "ffp_micropolar.json", label, {"output.localisation=true"});
  run.expected_wall_s = 60.0;  // 79,100 steps of 6,000 particles (docs/verification.md#micropolar)
  return run;
}

Extrapolation richardson(double coarse, double medium, double fine) {
  const double a = coarse - medium, b = medium - fine;
  if (std::isfinite(a) && std::isfinite(b) && a * b > 0 && std::abs(b) < std::abs(a)) {
    const double p = std::log2(a / b);
    if (p > 0.3 && p < 4.0) return {fine - b / (std::pow(2.0, p) - 1.0), p};
  }
  return {fine, std::nan("")};
}

}  // namespace ffp
