#include "drivers/app/sweep_results.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "drivers/app/job.hpp"
#include "drivers/app/sweep_cases.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/scene/scene_hash.hpp"
#include "reports/run_pool.hpp"

namespace ffp {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A figure as sweep.csv has always written it: doubles with 10 significant digits, text quoted by RFC 4180.
std::string csv_cell(const json& v) {
  if (v.is_number_float()) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", v.get<double>());
    return buffer;
  }
  return csv_field(v.is_string() ? v.get<std::string>() : v.dump());
}

/// nlohmann's message without its "[json.exception.parse_error.101] " tag: where and what.
std::string short_reason(const std::exception& e) {
  const std::string what = e.what();
  const auto tag_end = what.find("] ");
  return what.starts_with("[json.exception.") && tag_end != std::string::npos ? what.substr(tag_end + 2) : what;
}

/// The resolved scene of an emitted case's scene file (a folder emitted before hashes has only that);
/// null when it cannot be read.
json resolved_case_scene(const fs::path& scene_file) {
  try {
    json echo;
    make_job(load_scene_file(scene_file.string()), scene_file.parent_path(), echo);
    return echo;
  } catch (const std::exception&) {
    return nullptr;
  }
}

}  // namespace

void read_case_summary(CaseResult& result, const std::string& expected_hash,
                       const std::function<json()>& expected_echo) {
  result.summary = nullptr;
  const fs::path file = result.out_dir / "summary.json";
  std::ifstream in(file);
  if (!in) {
    result.error = file.string() + ": missing";
    return;
  }
  json summary;
  try {
    summary = json::parse(in);
  } catch (const json::exception& e) {
    result.error = file.string() + ": corrupt (" + short_reason(e) + ")";
    return;
  }
  if (!summary.is_object()) {
    result.error = file.string() + ": corrupt (not a JSON object)";
    return;
  }
  if (!expected_hash.empty()) {
    if (!summary.contains("scene")) {
      result.error = file.string() + ": echoes no scene, so nothing shows that it ran this case";
      return;
    }
    if (scene_hash(summary["scene"]) != expected_hash) {
      // The case's scene file names the key that differs, unless it too was changed since the emit.
      const json wanted = expected_echo ? expected_echo() : json(nullptr);
      const bool named = !wanted.is_null() && scene_hash(wanted) == expected_hash;
      result.error = result.out_dir.string() + ": ran with " +
                     (named ? first_difference(summary["scene"], wanted).text("the case") : "another scene") +
                     ": remove that folder and run the case again";
      return;
    }
  }
  result.summary = std::move(summary);
  result.error.clear();
}

std::string sweep_table(const std::vector<std::string>& keys, const std::vector<CaseResult>& cases) {
  std::vector<std::string> figure_columns;
  for (const CaseResult& c : cases) {
    if (!c.finished()) continue;
    for (const auto& [k, v] : c.summary.items())
      if ((v.is_number() || v.is_string()) && k != "ffp_version" &&
          std::find(figure_columns.begin(), figure_columns.end(), k) == figure_columns.end())
        figure_columns.push_back(k);
  }
  std::ostringstream table;
  for (const auto& key : keys) table << csv_field(key) << ",";
  table << "exit_code,out_dir";
  for (const auto& c : figure_columns) table << "," << csv_field(c);
  table << "\n";
  for (const CaseResult& c : cases) {
    for (const auto& o : c.overrides) table << csv_field(o.substr(o.find('=') + 1)) << ",";
    table << (c.exit_code >= 0 && !c.unusable() ? std::to_string(c.exit_code) : "") << ","
          << csv_field(c.out_dir.string());
    for (const auto& f : figure_columns)
      table << "," << (c.finished() && c.summary.contains(f) ? csv_cell(c.summary[f]) : "");
    table << "\n";
  }
  return table.str();
}

std::vector<CaseResult> collect_sweep(const fs::path& dir, std::vector<std::string>& keys) {
  std::vector<CaseResult> results;
  keys.clear();
  for (const CaseRow& row : read_case_list(dir)) {
    CaseResult r;
    r.id = row.id;
    r.overrides = row.overrides;
    if (keys.empty())
      for (const auto& o : r.overrides) keys.push_back(o.substr(0, o.find('=')));
    r.out_dir = dir / row.out_dir;
    const fs::path exit_file = dir / "logs" / ("case_" + row.id + ".exit");
    if (fs::exists(r.out_dir / kOutputManifest)) {
      r.exit_code = 0;
      const fs::path scene_file = dir / row.scene;
      const auto wanted = [&] { return resolved_case_scene(scene_file); };
      // A folder emitted before scene hashes: the case's own scene file gives the hash.
      std::string expected = row.scene_hash;
      if (const json echo = expected.empty() ? wanted() : json(nullptr); !echo.is_null()) expected = scene_hash(echo);
      if (expected.empty())
        r.error =
            scene_file.string() + ": cannot be read, so nothing shows that " + r.out_dir.string() + " ran this case";
      else
        read_case_summary(r, expected, wanted);
    } else if (fs::exists(exit_file)) {
      std::ifstream e(exit_file);
      int code = -1;
      e >> code;
      r.exit_code = code == 0 ? 1 : code;  // 0 without a complete folder is a failure too
      r.error = last_line(dir / "logs" / ("case_" + row.id + ".err"));
      if (r.error.empty()) r.error = code == 0 ? "exit 0 but no complete output folder" : "no message";
    }
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace ffp
