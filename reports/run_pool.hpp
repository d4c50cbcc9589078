#pragma once
/// Runs scenes as independent `ffp run` processes, a few at a time, with a
/// cache keyed by the scene's content and the program version. Each run is a
/// separate process so a study can be handed to a cluster scheduler unchanged.
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace ffp {

struct RunRequest {
  std::string label;  ///< shown in progress and tables
  std::filesystem::path scene_file;
  std::vector<std::string> overrides;  ///< "key=value", as for --set
  /// A rough cost (a wall time measured here) used only to start the longest
  /// runs first, so that no long run is left alone at the end on one core.
  double expected_wall_s = 0.0;
};

struct RunOutcome {
  std::filesystem::path out_dir;  ///< where summary.json and history.csv are
  int exit_code = -1;
  bool cached = false;
  double wall_time_s = 0.0;  ///< of this invocation (0 when cached)
  std::string error;         ///< last stderr line when it failed
};

/// The last non-empty line of a run's log (its error message when it failed); "" if none.
std::string last_line(const std::filesystem::path& log);

/// Content key of a run: the scene JSON with the overrides applied (numbers
/// normalised, the description left out), the content of every file the scene
/// names (e.g. a lab CSV) and the program's identity.
std::string run_key(const RunRequest& request, const std::string& program_identity);

/// The version string and a hash of the program's binary: a rebuild changes it.
std::string program_identity(const std::filesystem::path& binary, const std::string& program_version);

/// Where the runs that are not cached run: this machine's process pool, or a
/// Slurm job array (one task per run, sbatch from this machine, then waited for).
enum class Scheduler { local, slurm };

/// Runs that need the outcomes of others (a study's follow-up: e.g. an FFP with the η
/// that its calibration runs fitted). `make` is called once, when every request in
/// [first, last) has finished (on the pool's thread, with their outcomes in order),
/// and the runs it gives join the queue at once, while the others still run.
struct FollowUp {
  std::size_t first = 0, last = 0;
  std::function<std::vector<RunRequest>(const std::vector<RunOutcome>&)> make;
  // Filled by run_all: the runs `make` gave and their outcomes, in its order.
  std::vector<RunRequest> requests;
  std::vector<RunOutcome> outcomes;
};

/// Run every request (at most `jobs` at once) into cache_root/<label-slug>-<key>/
/// (key: run_key with program_identity(ffp_binary, program_version)),
/// skipping those whose summary.json already exists; the longest expected runs
/// start first, the others in the given order, and so do the follow-ups' runs
/// among those not started yet. Progress lines go to stderr. On Slurm the
/// follow-ups' runs are a second job array, after the first.
std::vector<RunOutcome> run_all(const std::filesystem::path& ffp_binary, const std::vector<RunRequest>& requests,
                                const std::filesystem::path& cache_root, const std::string& program_version, int jobs,
                                Scheduler scheduler = Scheduler::local, std::span<FollowUp> follow_ups = {});

}  // namespace ffp
