#include "drivers/app/sweep_cases.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "drivers/app/job.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/scene/scene_hash.hpp"
#include "reports/slurm_jobs.hpp"

namespace ffp {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The scene keys that name files, relative to the scene's folder (docs/reference/scenes.md): a case
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

/// The scene a finished run echoes in its summary.json; null when it has none that can be read.
json echoed_scene(const fs::path& run) {
  std::ifstream in(run / "summary.json");
  if (!in) return nullptr;
  const json summary = json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.is_object() || !summary.contains("scene")) return nullptr;
  return summary["scene"];
}

/// The logs run_case.sh leaves for case `id`.
std::vector<fs::path> case_logs(const fs::path& dir, const std::string& id) {
  return {dir / "logs" / ("case_" + id + ".exit"), dir / "logs" / ("case_" + id + ".err")};
}

void write_script(const fs::path& file, const std::string& text) {
  write_file_atomically(file, text);
  fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

}  // namespace

std::string case_id(std::size_t index) {
  char id[24];
  std::snprintf(id, sizeof id, "%04zu", index);
  return id;
}

std::vector<SweepAxis> sweep_axes(const std::vector<std::string>& arguments) {
  std::vector<SweepAxis> axes;
  for (const std::string& assignment : arguments) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw SceneError("--set " + assignment + ": expected key=v1,v2,...");
    SweepAxis axis{assignment.substr(0, eq), split_values(assignment.substr(eq + 1))};
    // Applied in turn, a key's second --set would overwrite the first's value in every case while
    // the table still listed both: each key gets one --set with all its values.
    for (const SweepAxis& earlier : axes)
      if (earlier.key == axis.key)
        throw SceneError("--set " + axis.key + ": given twice; give all its values in one --set " + axis.key +
                         "=v1,v2,...");
    for (std::size_t k = 0; k < axis.values.size(); ++k)
      if (std::find(axis.values.begin(), axis.values.begin() + static_cast<long>(k), axis.values[k]) !=
          axis.values.begin() + static_cast<long>(k))
        throw SceneError("--set " + axis.key + ": the value '" + axis.values[k] + "' is given twice");
    axes.push_back(std::move(axis));
  }
  return axes;
}

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
    make_paths_absolute(one.scene, scene_dir);
    // Validates (a typo fails before any run starts) and resolves the scene as its run will echo it.
    make_job(one.scene, scene_dir, one.echo);
    one.scene_hash = scene_hash(one.echo);
    scene_name = one.echo.value("name", "sweep");
    one.label = scene_name;
    for (const auto& o : c) one.label += "_" + o.substr(o.find('=') + 1);
    cases.push_back(std::move(one));
  }
  return cases;
}

EarlierCases find_earlier_cases(const fs::path& dir, const std::vector<SweepCase>& cases) {
  std::map<std::string, std::string> listed;  // case id → the scene hash the earlier cases.tsv gave it
  try {
    for (const CaseRow& row : read_case_list(dir)) listed[row.id] = row.scene_hash;
  } catch (const SceneError&) {
    // No earlier list (or one that cannot be read): only the finished runs' own summaries can vouch for them.
  }
  EarlierCases earlier;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string id = case_id(i);
    const fs::path run = dir / "runs" / ("case_" + id);
    if (fs::exists(run / kOutputManifest)) {
      const json ran = echoed_scene(run);
      if (!ran.is_null() && scene_hash(ran) == cases[i].scene_hash) continue;
      earlier.differing_results.push_back(
          "case " + id +
          (ran.is_null() ? " has a result whose summary.json names no readable scene"
                         : " ran with " + first_difference(ran, cases[i].echo).text("this sweep")));
      earlier.stale.push_back(run);
    } else if (const auto it = listed.find(id); it != listed.end() && it->second == cases[i].scene_hash) {
      continue;  // the same scene: its logs (a failure, say) are this case's
    }
    earlier.any_scene_changed = true;
    for (const fs::path& log : case_logs(dir, id))
      if (fs::exists(log)) earlier.stale.push_back(log);
  }
  return earlier;
}

void retire_earlier_cases(const fs::path& dir, const EarlierCases& earlier) {
  for (const fs::path& stale : earlier.stale) fs::remove_all(stale);
  if (earlier.any_scene_changed) fs::remove(dir / "logs" / "parallel.joblog");
}

void emit_sweep(const fs::path& dir_in, const std::vector<SweepCase>& cases, const EmitOptions& options) {
  const fs::path dir = fs::absolute(dir_in);
  fs::create_directories(dir / "scenes");
  fs::create_directories(dir / "runs");
  fs::create_directories(dir / "logs");
  std::ostringstream manifest;
  manifest << kCaseListHeader << "\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string id = case_id(i);
    write_file_atomically(dir / "scenes" / ("case_" + id + ".json"), cases[i].scene.dump(2) + "\n");
    manifest << id << "\t" << json(cases[i].overrides).dump() << "\tscenes/case_" << id << ".json\truns/case_" << id
             << "\t" << cases[i].scene_hash << "\n";
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
                   " run \"scenes/case_$n.json\" --out \"runs/case_$n\" --quiet" +
                   (options.allow_long ? " --allow-long" : "") +
                   " 2> \"logs/case_$n.err\"\n"
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

std::vector<CaseRow> read_case_list(const fs::path& dir) {
  const fs::path file = dir / "cases.tsv";
  std::ifstream in(file);
  if (!in) throw SceneError(dir.string() + ": no cases.tsv (make one with ffp sweep … --emit " + dir.string() + ")");
  std::string line;
  std::getline(in, line);
  const std::string header = kCaseListHeader;
  const bool hashed = line == header;
  if (!hashed && line != header.substr(0, header.rfind('\t')))
    throw SceneError(file.string() + ": not a sweep's case list");
  const std::size_t columns = hashed ? 5 : 4;
  std::vector<CaseRow> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, '\t');) fields.push_back(f);
    if (fields.size() != columns)
      throw SceneError(file.string() + ": a row without " + std::to_string(columns) + " tab-separated fields");
    CaseRow r{fields[0], {}, fields[2], fields[3], hashed ? fields[4] : ""};
    try {
      r.overrides = json::parse(fields[1]).get<std::vector<std::string>>();
    } catch (const std::exception&) {
      throw SceneError(file.string() + ": case " + fields[0] + ": unreadable overrides");
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace ffp
