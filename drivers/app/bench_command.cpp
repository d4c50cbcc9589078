/// `ffp bench`: end-to-end speed of representative scenes (median of repeats).
/// The Google Benchmark programs in bench/ measure the kernels (constitutive
/// updates/s, MPM particle-steps/s); this measures what a user waits for.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/processor_name.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/output/checked_write.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/scene/scene_error.hpp"
#include "reports/run_pool.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

/// The middle value; for an even count the mean of the two middle ones (two
/// repeats gave the slower of the two before).
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t half = v.size() / 2;
  return v.size() % 2 == 1 ? v[half] : 0.5 * (v[half - 1] + v[half]);
}

/// printf onto the end of `text`.
[[gnu::format(printf, 2, 3)]] void append(std::string& text, const char* format, ...) {
  char line[512];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(line, sizeof line, format, arguments);
  va_end(arguments);
  text += line;
}

/// The runs' folder of a bench, removed however the bench ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(fs::path path) : path_(std::move(path)) {}
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

 private:
  fs::path path_;
};

}  // namespace

int command_bench(const BenchOptions& options) {
  try {
    const int repeats = options.repeats;
    const fs::path scenes = options.scenes.empty() ? default_scenes_folder() : options.scenes;
    const std::vector<std::string> candidates = {"point_triaxial_ssmc.json", "triaxial_ssmc_paper.json",
                                                 "calibration_dr15.json",    "mpm_geostatic_column.json",
                                                 "ffp_reference.json",       "cpt_reference.json"};
    std::vector<RunRequest> requests;
    for (const auto& c : candidates)
      if (fs::exists(scenes / c)) requests.push_back({fs::path(c).stem().string(), scenes / c, {}});
    if (requests.empty()) throw SceneError("--scenes: no benchmark scenes found in " + scenes.string());

    const fs::path scratch = fs::temp_directory_path() / ("ffp-bench-" + std::to_string(std::random_device{}()));
    const ScratchFolder removed_at_the_end(scratch);  // also when a Ctrl-C or a failure ends the bench
    std::vector<std::vector<nlohmann::json>> summaries(requests.size());
    for (int r = 0; r < repeats; ++r) {
      // A fresh cache root each time: every repeat really runs.
      const auto outcomes = run_all("/proc/self/exe", requests, scratch / std::to_string(r), program_version(), 1);
      for (std::size_t i = 0; i < outcomes.size(); ++i) {
        if (outcomes[i].exit_code != 0) continue;
        std::ifstream in(outcomes[i].out_dir / "summary.json");
        summaries[i].push_back(nlohmann::json::parse(in));
      }
    }

    std::string table;  // the result, written at once and checked
    append(table,
           "%s on %s, %u hardware threads, median of %d run%s (wall time inside the run, without process start)\n\n",
           version_string().c_str(), this_processor().c_str(), std::thread::hardware_concurrency(), repeats,
           repeats == 1 ? "" : "s");
    // The spread, (slowest − fastest)/median, says how far the machine moved between repeats.
    append(table,
           "| scene | wall time [s] | spread [%%] | steps | steps/s | particles | particle-steps/s |\n"
           "|---|---|---|---|---|---|---|\n");
    int failures = 0;
    for (std::size_t i = 0; i < requests.size(); ++i) {
      if (summaries[i].empty()) {
        append(table, "| %s | FAILED | | | | | |\n", requests[i].label.c_str());
        ++failures;
        continue;
      }
      std::vector<double> wall;
      for (const auto& s : summaries[i]) wall.push_back(s.value("wall_time_s", 0.0));
      const double t = median(wall);
      const double steps = summaries[i].front().value("steps", 0.0);
      const double particles = summaries[i].front().value("particles", 0.0);
      char particle_columns[96] = "– | –";
      if (particles > 0)
        std::snprintf(particle_columns, sizeof particle_columns, "%.0f | %.2f M", particles,
                      particles * steps / t / 1e6);
      char spread[32] = "–";
      if (wall.size() > 1 && t > 0.0)
        std::snprintf(spread, sizeof spread, "%.0f",
                      100.0 * (*std::ranges::max_element(wall) - *std::ranges::min_element(wall)) / t);
      append(table, "| %s | %.3f | %s | %.0f | %.3g | %s |\n", requests[i].label.c_str(), t, spread, steps, steps / t,
             particle_columns);
    }
    write_standard_output(table);
    return failures == 0 ? 0 : 1;
  } catch (...) {
    return exit_code_of_current_exception();
  }
}

}  // namespace ffp
