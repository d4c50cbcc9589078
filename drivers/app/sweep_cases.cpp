#include "drivers/app/sweep_cases.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "drivers/app/job.hpp"
#include "drivers/output/run_directory.hpp"
#include "reports/run_pool.hpp"
#include "reports/slurm_jobs.hpp"

namespace ffp {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The scene keys that name files, relative to the scene's folder (README, Scenes): a case
/// scene lives in another folder, so they become absolute there.
void make_paths_absolute(json& scene, const fs::path& scene_dir) {
  auto fix = [&](json& holder, const char* key) {
    if (!holder.is_object() || !holder.contains(key) || !holder[key].is_string()) return;
    const fs::path p = holder[key].get<std::string>();
    if (p.is_relative()) holder[key] = fs::weakly_canonical(fs::absolute(scene_dir / p)).string();
  };
  fix(scene, "lab_curve_csv");
  fix(scene, "record_csv");     // a record
  fix(scene, "forward_scene");  // an inverse fit, and its record
  if (scene.contains("record")) fix(scene["record"], "record_csv");
  if (scene.contains("path")) fix(scene["path"], "table_csv");
}

std::string case_id(std::size_t i) {
  char id[24];
  std::snprintf(id, sizeof id, "%04zu", i);
  return id;
}

std::string csv_cell(const json& v) {
  if (v.is_number_float()) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", v.get<double>());
    return buffer;
  }
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

void write_script(const fs::path& file, const std::string& text) {
  write_file_atomically(file, text);
  fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

}  // namespace

std::vector<SweepCase> expand_sweep(const fs::path& scene_file, const std::vector<SweepAxis>& axes,
                                    std::string& scene_name) {
  std::vector<std::vector<std::string>> combinations = {{}};
  for (const SweepAxis& axis : axes) {
    std::vector<std::vector<std::string>> grown;
    for (const auto& c : combinations)
      for (const auto& v : axis.values) {
        auto next = c;
        next.push_back(axis.key + "=" + v);
        grown.push_back(next);
      }
    combinations = std::move(grown);
  }
  const json base = load_scene_file(scene_file.string());
  const fs::path scene_dir = scene_file.parent_path();
  std::vector<SweepCase> cases;
  for (const auto& c : combinations) {
    SweepCase one;
    one.overrides = c;
    one.scene = base;
    for (const auto& o : c) apply_override(one.scene, o);
    json echo;
    make_job(one.scene, scene_dir, echo);  // validates: a typo fails before any run starts
    scene_name = echo.value("name", "sweep");
    one.label = scene_name;
    for (const auto& o : c) one.label += "_" + o.substr(o.find('=') + 1);
    make_paths_absolute(one.scene, scene_dir);
    cases.push_back(std::move(one));
  }
  return cases;
}

std::string sweep_table(const std::vector<std::string>& keys, const std::vector<CaseResult>& cases) {
  std::vector<std::string> figure_columns;
  std::vector<json> summaries;
  for (const CaseResult& c : cases) {
    json s = json::object();
    if (c.exit_code == 0) {
      std::ifstream in(c.out_dir / "summary.json");
      s = json::parse(in);
      for (const auto& [k, v] : s.items())
        if ((v.is_number() || v.is_string()) && k != "ffp_version" &&
            std::find(figure_columns.begin(), figure_columns.end(), k) == figure_columns.end())
          figure_columns.push_back(k);
    }
    summaries.push_back(s);
  }
  std::ostringstream table;
  for (const auto& key : keys) table << key << ",";
  table << "exit_code,out_dir";
  for (const auto& c : figure_columns) table << "," << c;
  table << "\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (const auto& o : cases[i].overrides) table << o.substr(o.find('=') + 1) << ",";
    table << (cases[i].exit_code >= 0 ? std::to_string(cases[i].exit_code) : "") << "," << cases[i].out_dir.string();
    for (const auto& c : figure_columns) table << "," << (summaries[i].contains(c) ? csv_cell(summaries[i][c]) : "");
    table << "\n";
  }
  return table.str();
}

void emit_sweep(const fs::path& dir_in, const std::vector<SweepCase>& cases, const EmitOptions& options) {
  const fs::path dir = fs::absolute(dir_in);
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "runs");
  fs::create_directories(dir / "logs");
  std::ostringstream manifest;
  manifest << "case\toverrides\tscene\tout_dir\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string id = case_id(i);
    write_file_atomically(dir / "scenes" / ("case_" + id + ".json"), cases[i].scene.dump(2) + "\n");
    manifest << id << "\t" << json(cases[i].overrides).dump() << "\tscenes/case_" << id << ".json\truns/case_" << id
             << "\n";
  }
  write_file_atomically(dir / "cases.tsv", manifest.str());

  const std::string n = std::to_string(cases.size());
  const std::string last = std::to_string(cases.empty() ? 0 : cases.size() - 1);
  const std::string threads = std::to_string(options.threads_per_case);
  write_script(dir / "run_case.sh",
               "#!/usr/bin/env bash\n"
               "# Runs case K (0-based) of this sweep: bash run_case.sh K. A finished case is skipped, so a\n"
               "# resubmission runs only what is missing. Exit code and stderr go to logs/ for `ffp collect`.\n"
               "set -u\n"
               "cd \"$(dirname \"$0\")\"\n"
               "n=$(printf '%04d' \"$1\")\n"
               "if [ -e \"runs/case_$n/" +
                   std::string(kOutputManifest) +
                   "\" ]; then echo \"case $n: already finished\"; exit 0; fi\n"
                   "mkdir -p logs\n"
                   "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-" +
                   threads + "}\"\n" + shell_quoted(options.ffp_binary.string()) +
                   " run \"scenes/case_$n.json\" --out \"runs/case_$n\" --quiet 2> \"logs/case_$n.err\"\n"
                   "status=$?\n"
                   "echo \"$status\" > \"logs/case_$n.exit\"\n"
                   "exit \"$status\"\n");
  write_script(dir / "slurm.sbatch",
               "#!/usr/bin/env bash\n"
               "#SBATCH --job-name=" +
                   options.job_name +
                   "\n"
                   "#SBATCH --array=0-" +
                   last +
                   "\n"
                   "#SBATCH --cpus-per-task=" +
                   threads + "\n" + sbatch_folder_lines(dir, "logs/slurm-%A_%a.out") + "# " + n +
                   " cases, one per array task: sbatch slurm.sbatch (from any folder), then ffp collect " +
                   dir.string() +
                   "\n"
                   "exec bash " +
                   shell_quoted((dir / "run_case.sh").string()) + " \"$SLURM_ARRAY_TASK_ID\"\n");
  write_script(dir / "parallel.sh",
               "#!/usr/bin/env bash\n"
               "# GNU parallel on one machine or inside one allocation: bash parallel.sh [JOBS]. The joblog\n"
               "# records each case and --resume skips those already in it (--resume-failed reruns failures).\n"
               "set -eu\n"
               "cd \"$(dirname \"$0\")\"\n"
               "mkdir -p logs\n"
               "parallel --jobs \"${1:-" +
                   std::to_string(options.parallel_jobs) +
                   "}\" --joblog logs/parallel.joblog --resume bash run_case.sh {} ::: $(seq 0 " + last + ")\n");
}

std::vector<CaseResult> collect_sweep(const fs::path& dir, std::vector<std::string>& keys) {
  std::ifstream in(dir / "cases.tsv");
  if (!in) throw SceneError(dir.string() + ": no cases.tsv (make one with ffp sweep … --emit " + dir.string() + ")");
  std::string line;
  std::getline(in, line);
  if (line != "case\toverrides\tscene\tout_dir")
    throw SceneError((dir / "cases.tsv").string() + ": not a sweep's case list");
  std::vector<CaseResult> results;
  keys.clear();
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, '\t');) fields.push_back(f);
    if (fields.size() != 4) throw SceneError((dir / "cases.tsv").string() + ": a row without 4 tab-separated fields");
    CaseResult r;
    try {
      r.overrides = json::parse(fields[1]).get<std::vector<std::string>>();
    } catch (const std::exception&) {
      throw SceneError((dir / "cases.tsv").string() + ": case " + fields[0] + ": unreadable overrides");
    }
    if (keys.empty())
      for (const auto& o : r.overrides) keys.push_back(o.substr(0, o.find('=')));
    r.out_dir = dir / fields[3];
    const fs::path exit_file = dir / "logs" / ("case_" + fields[0] + ".exit");
    if (fs::exists(r.out_dir / kOutputManifest)) {
      r.exit_code = 0;
    } else if (fs::exists(exit_file)) {
      std::ifstream e(exit_file);
      int code = -1;
      e >> code;
      r.exit_code = code == 0 ? 1 : code;  // 0 without a complete folder is a failure too
      r.error = last_line(dir / "logs" / ("case_" + fields[0] + ".err"));
      if (r.error.empty()) r.error = code == 0 ? "exit 0 but no complete output folder" : "no message";
    }
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace ffp
