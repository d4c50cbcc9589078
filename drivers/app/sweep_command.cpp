/// `ffp sweep`: every combination of --set key=v1,v2,... as an independent run.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "drivers/app/commands.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/version.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "reports/run_pool.hpp"

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

std::string csv_cell(const json& v) {
  if (v.is_number_float()) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", v.get<double>());
    return buffer;
  }
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace

int command_sweep(const Arguments& args) {
  try {
    std::string scene_file;
    std::vector<std::pair<std::string, std::vector<std::string>>> axes;
    fs::path out;
    int jobs = 1;
    bool force = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= args.size()) throw SceneError(a + ": needs a value");
        return args[++i];
      };
      if (a == "--set") {
        const std::string assignment = value();
        const auto eq = assignment.find('=');
        if (eq == std::string::npos || eq == 0) throw SceneError("--set " + assignment + ": expected key=v1,v2,...");
        axes.emplace_back(assignment.substr(0, eq), split_values(assignment.substr(eq + 1)));
      } else if (a == "--jobs") {
        const std::string n = value();
        jobs = std::atoi(n.c_str());
        if (jobs < 1 || jobs > 256) throw SceneError("--jobs: '" + n + "' must be an integer in [1, 256]");
      } else if (a == "--force") {
        force = true;
      } else if (a == "--out") {
        out = value();
      } else if (!a.empty() && a[0] == '-') {
        throw SceneError("ffp sweep: unknown option '" + a + "' (try ffp --help)");
      } else if (scene_file.empty()) {
        scene_file = a;
      } else {
        throw SceneError("ffp sweep: one scene file at a time");
      }
    }
    if (scene_file.empty()) throw SceneError("ffp sweep: missing SCENE.json");
    if (axes.empty()) throw SceneError("ffp sweep: give at least one --set key=v1,v2,...");

    // Every combination, validated up front so a typo fails before any run starts.
    std::vector<std::vector<std::string>> combinations = {{}};
    for (const auto& [key, values] : axes) {
      std::vector<std::vector<std::string>> grown;
      for (const auto& c : combinations)
        for (const auto& v : values) {
          auto next = c;
          next.push_back(key + "=" + v);
          grown.push_back(next);
        }
      combinations = std::move(grown);
    }
    const json base = load_scene_file(scene_file);
    std::string name;
    std::vector<RunRequest> requests;
    for (const auto& c : combinations) {
      json scene = base;
      for (const auto& o : c) apply_override(scene, o);
      json echo;
      make_job(scene, fs::path(scene_file).parent_path(), echo);
      name = echo.value("name", "sweep");
      std::string label = name;
      for (const auto& o : c) label += "_" + o.substr(o.find('=') + 1);
      requests.push_back({label, scene_file, c});
    }
    if (out.empty()) out = fs::path("results") / (name + "-sweep");
    claim_persistent_folder(out, "--out", "sweep", force);
    claim_persistent_folder(out / "runs", "--out", "run cache", force);
    // A table from an earlier sweep into this folder must not pass for this one's.
    fs::remove(out / "sweep.csv");
    std::fprintf(stderr, "sweep: %zu runs, %d at a time, into %s\n", requests.size(), jobs, out.string().c_str());
    const auto outcomes = run_all("/proc/self/exe", requests, out / "runs", FFP_VERSION, jobs);

    // One row per run: the swept values, the exit code, then every scalar figure.
    std::vector<std::string> figure_columns;
    std::vector<json> summaries;
    for (const auto& o : outcomes) {
      json s = json::object();
      if (o.exit_code == 0) {
        std::ifstream in(o.out_dir / "summary.json");
        s = json::parse(in);
        for (const auto& [k, v] : s.items())
          if ((v.is_number() || v.is_string()) && k != "ffp_version" &&
              std::find(figure_columns.begin(), figure_columns.end(), k) == figure_columns.end())
            figure_columns.push_back(k);
      }
      summaries.push_back(s);
    }
    std::ostringstream table;
    for (const auto& [key, _] : axes) table << key << ",";
    table << "exit_code,out_dir";
    for (const auto& c : figure_columns) table << "," << c;
    table << "\n";
    int failures = 0;
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      for (const auto& o : combinations[i]) table << o.substr(o.find('=') + 1) << ",";
      table << outcomes[i].exit_code << "," << outcomes[i].out_dir.string();
      for (const auto& c : figure_columns) table << "," << (summaries[i].contains(c) ? csv_cell(summaries[i][c]) : "");
      table << "\n";
      if (outcomes[i].exit_code != 0) {
        ++failures;
        std::fprintf(stderr, "  %s failed (exit %d): %s\n", requests[i].label.c_str(), outcomes[i].exit_code,
                     outcomes[i].error.c_str());
      }
    }
    write_file_atomically(out / "sweep.csv", table.str());
    std::fprintf(stderr, "wrote %s\n", (out / "sweep.csv").string().c_str());
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

}  // namespace ffp
