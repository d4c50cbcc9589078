/// `ffp report`: run the validation studies (cached) and write report.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <thread>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/processor_name.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/scene/scene_error.hpp"
#include "reports/markdown.hpp"
#include "reports/study.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

std::string machine_description() {
  return this_processor() + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return buffer;
}

}  // namespace

int command_report(const ReportOptions& options) {
  try {
    const fs::path& out = options.out;
    const fs::path& cache = options.cache;
    const fs::path scenes = options.scenes.empty() ? default_scenes_folder() : options.scenes;
    const std::string& only = options.only;
    const bool force = options.force;
    const Scheduler scheduler = options.slurm ? Scheduler::slurm : Scheduler::local;
    // One run per core: most runs are small or single-threaded (the MPM
    // calibration specimens), so runs side by side finish the study sooner than
    // one run at a time on two OpenMP threads (the report took 24 against 37 min
    // on a fresh clone here, with the longest runs started first).
    const int jobs =
        options.jobs > 0 ? options.jobs : static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    if (!fs::is_directory(scenes)) throw SceneError("--scenes: '" + scenes.string() + "' is not a folder of scenes");

    // Refuse a folder of the user's, or one another report is writing, before hours of runs, not
    // after; the folder is this report's (its lock) from now on.
    RunDirectory directory(out, "--out", force);
    claim_persistent_folder(cache, "--cache", "run cache", force);

    const auto start = std::chrono::steady_clock::now();
    std::vector<Study> studies = validation_studies(scenes);
    const std::vector<std::string> left_out = select_studies(studies, only);
    if (studies.empty()) throw SceneError("--only: no study title contains '" + only + "'");
    // Every study's own runs, and the runs that need their results (a study's
    // follow-up), made as soon as that study's runs are done, while the others run.
    std::vector<RunRequest> all;
    for (const auto& s : studies) all.insert(all.end(), s.runs.begin(), s.runs.end());
    std::fprintf(stderr, "report: %zu studies, %zu runs\n", studies.size(), all.size());
    std::vector<FollowUp> follow_ups;
    std::vector<std::size_t> follow_up_of(studies.size(), studies.size());  // study → its follow_ups entry
    for (std::size_t k = 0, offset = 0; k < studies.size(); offset += studies[k].runs.size(), ++k) {
      if (!studies[k].follow_up) continue;
      follow_up_of[k] = follow_ups.size();
      follow_ups.push_back({offset,
                            offset + studies[k].runs.size(),
                            [&studies, k](const std::vector<RunOutcome>& outcomes) {
                              return studies[k].follow_up(StudyResults(studies[k].runs, outcomes));
                            },
                            {},
                            {}});
    }
    const std::vector<RunOutcome> first =
        run_all("/proc/self/exe", all, cache, program_version(), jobs, scheduler, follow_ups);
    std::vector<StudyResults> results;
    for (std::size_t k = 0, offset = 0; k < studies.size(); offset += studies[k].runs.size(), ++k) {
      const auto begin = first.begin() + static_cast<long>(offset);
      results.emplace_back(studies[k].runs,
                           std::vector<RunOutcome>(begin, begin + static_cast<long>(studies[k].runs.size())));
      if (follow_up_of[k] < follow_ups.size() && !follow_ups[follow_up_of[k]].requests.empty()) {
        const FollowUp& up = follow_ups[follow_up_of[k]];
        results[k] = results[k].extended(up.requests, up.outcomes);
      }
    }

    fs::create_directories(directory.path() / "figures");
    fs::create_directories(directory.path() / "tables");
    Markdown document;
    document.raw("# ffp validation report\n\n");
    document.paragraph(
        "Reproduction of the studies of Zambrano-Cruzatty & Yerro (2020), *Numerical simulation of a free fall "
        "penetrometer deployment using the material point method*, Soils and Foundations (2020), with the ffp "
        "axisymmetric MPM solver and its constitutive-model testbed. Every number below was computed by the runs "
        "listed at the end; nothing is copied from the paper except the values in the 'paper' columns.");
    document.table({"", ""}, {{"program", version_string()},
                              {"machine", machine_description()},
                              {"generated", today()},
                              {"command", "ffp report --jobs " + std::to_string(jobs)}});

    std::vector<std::vector<std::string>> run_rows;
    int failures = 0;
    for (std::size_t k = 0; k < studies.size(); ++k) {
      const StudyResults& mine = results[k];
      for (std::size_t i = 0; i < mine.size(); ++i) {
        const auto summary = mine.summary(i);
        if (!mine.ok(i)) ++failures;
        run_rows.push_back({mine.request(i).label, mine.ok(i) ? "ok" : "FAILED: " + mine.outcome(i).error,
                            summary.contains("wall_time_s") ? fixed(summary["wall_time_s"].get<double>(), 2) : "–",
                            mine.outcome(i).cached ? "cached" : "ran now",
                            mine.outcome(i).out_dir.filename().string()});
      }
      document.heading(2, studies[k].title);
      StudyOutput output{document, directory.path() / "figures", "figures", directory.path() / "tables"};
      // A study whose runs failed in a way its writer did not foresee is marked
      // failed here; every other study is still written.
      // A figure or table that could not be written (WriteFailure) fails the whole report instead:
      // a report that says done has every figure it names.
      try {
        studies[k].write(mine, output);
      } catch (const Interrupted&) {
        throw;
      } catch (const WriteFailure& e) {
        throw e.moved(directory.path(), out);
      } catch (const std::exception& e) {
        ++failures;
        document.paragraph(
            "**This study could not be written** (a run above failed or gave an incomplete "
            "summary): " +
            std::string(e.what()));
      }
    }

    for (const std::string& title : left_out) {
      document.heading(2, title);
      document.paragraph(
          "Not run in this report: its runs take too long for the main job. Run it with `ffp report "
          "--only \"" +
          title + "\"`.");
    }

    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    document.heading(2, "Runs");
    document.paragraph(
        "Wall time of each run as recorded when it ran (cached runs keep their original time). This "
        "report took " +
        fixed(total, 1) + " s to assemble, including the runs made now.");
    document.table({"run", "status", "wall time [s]", "this time", "folder (in " + cache.string() + ")"}, run_rows);
    try {
      write_file_atomically(directory.path() / "report.md", document.str(), Durability::synced);
      directory.commit("report");
    } catch (const WriteFailure& e) {
      throw e.moved(directory.path(), out);
    }
    std::fprintf(stderr, "wrote %s (%.1f s)%s\n", (out / "report.md").string().c_str(), total,
                 failures ? (" — " + std::to_string(failures) + " run(s) FAILED").c_str() : "");
    return failures == 0 ? 0 : 1;
  } catch (...) {
    return exit_code_of_current_exception("no report written");
  }
}

}  // namespace ffp
