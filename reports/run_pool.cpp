#include "reports/run_pool.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <span>
#include <sstream>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "drivers/output/interrupt.hpp"
#include "drivers/output/run_directory.hpp"
#include "drivers/scene/scene_hash.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "reports/slurm_jobs.hpp"

extern char** environ;

namespace ffp {

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Contents of the files a scene refers to by relative or absolute path.
void collect_referenced_files(const nlohmann::json& node, const fs::path& scene_dir, std::string& out) {
  if (node.is_object() || node.is_array()) {
    for (const auto& child : node) collect_referenced_files(child, scene_dir, out);
  } else if (node.is_string()) {
    const std::string value = node.get<std::string>();
    if (value.size() > 4 && (value.ends_with(".csv") || value.ends_with(".json"))) {
      const fs::path candidate = fs::path(value).is_absolute() ? fs::path(value) : scene_dir / value;
      if (fs::is_regular_file(candidate)) out += read_file(candidate);
    }
  }
}

std::string slug(const std::string& label) {
  std::string s;
  for (char c : label) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return s.substr(0, 60);
}

std::string hex_key(const std::string& material) { return hex_digits(fnv1a_64(material)); }

/// The pending runs as one Slurm job array: each task runs one `ffp run` (the command
/// line on its row of commands.txt) with the threads Slurm gives it, and leaves its
/// exit code beside its log. Returns once the array has left the queue.
void run_on_slurm(const fs::path& ffp_binary, const std::vector<RunRequest>& requests,
                  const std::vector<std::size_t>& pending, std::vector<RunOutcome>& outcomes,
                  const fs::path& cache_root) {
  static int arrays = 0;  // a report submits one array per round: each its own folder
  const fs::path batch =
      fs::absolute(cache_root / (".slurm-" + std::to_string(::getpid()) + "-" + std::to_string(arrays++)));
  fs::create_directories(batch);
  std::ostringstream commands;
  for (std::size_t t = 0; t < pending.size(); ++t) {
    const RunRequest& r = requests[pending[t]];
    commands << shell_quoted(fs::canonical(ffp_binary).string()) << " run "
             << shell_quoted(fs::absolute(r.scene_file).string()) << " --out "
             << shell_quoted(fs::absolute(outcomes[pending[t]].out_dir).string()) << " --quiet";
    for (const auto& o : r.overrides) commands << " --set " << shell_quoted(o);
    commands << "\n";
  }
  write_file_atomically(batch / "commands.txt", commands.str());
  write_file_atomically(batch / "batch.sbatch",
                        "#!/usr/bin/env bash\n#SBATCH --job-name=ffp-report\n#SBATCH --array=0-" +
                            std::to_string(pending.size() - 1) + "\n" + sbatch_folder_lines(batch, "task-%a.out") +
                            "set -u\ncd " + shell_quoted(batch.string()) +
                            "\nexport OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n"
                            "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" commands.txt)\n"
                            "eval \"$line\" 2> \"task-$SLURM_ARRAY_TASK_ID.err\"\n"
                            "echo $? > \"task-$SLURM_ARRAY_TASK_ID.exit\"\n");
  const auto start = std::chrono::steady_clock::now();
  const std::string job = slurm_submit(batch / "batch.sbatch");
  std::fprintf(stderr, "runs: Slurm job %s, %zu array tasks (%s)\n", job.c_str(), pending.size(), batch.c_str());
  std::size_t reported = 0;
  try {
    slurm_wait(job, [&] {
      throw_if_interrupted();
      std::size_t done = 0;
      for (std::size_t t = 0; t < pending.size(); ++t)
        done += fs::exists(batch / ("task-" + std::to_string(t) + ".exit"));
      if (done != reported) std::fprintf(stderr, "  %zu of %zu runs done\n", done, pending.size());
      reported = done;
    });
  } catch (const Interrupted&) {
    // Ctrl-C stops these runs as it stops a local pool's: cancelled, waited for (each removes its
    // temporary folder on Slurm's SIGTERM), and the batch's folder goes with them.
    std::fprintf(stderr, "runs: cancelling Slurm job %s\n", job.c_str());
    slurm_cancel(job);
    std::error_code ignored;
    fs::remove_all(batch, ignored);
    throw;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t t = 0; t < pending.size(); ++t) {
    RunOutcome& o = outcomes[pending[t]];
    std::ifstream exit_file(batch / ("task-" + std::to_string(t) + ".exit"));
    int code = -1;
    if (!(exit_file >> code)) code = 125;  // the task never ran to its end (cancelled, node lost)
    o.exit_code = code;
    o.wall_time_s = wall;  // of the whole array: Slurm ran them side by side
    if (code != 0) {
      o.error = last_line(batch / ("task-" + std::to_string(t) + ".err"));
      if (o.error.empty()) o.error = "the Slurm task did not finish (see " + batch.string() + ")";
    }
  }
  std::error_code ignored;
  bool all_ok = true;
  for (std::size_t t : pending) all_ok = all_ok && outcomes[t].exit_code == 0;
  if (all_ok) fs::remove_all(batch, ignored);  // kept when something failed: its logs say why
}

/// The next run that ends (waitpid's answer), or 0 once an interrupt is asked for. Polls rather than
/// blocks: a Ctrl-C landing between a check of the flag and a blocking waitpid would go unseen until
/// some run ended, minutes later. A poll every 20 ms costs nothing beside the runs.
pid_t wait_for_a_run(int& status) {
  while (!interrupt_requested()) {
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid != 0) return pid;  // a run ended, or no child is left (-1)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return 0;
}

}  // namespace

std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::string run_key(const RunRequest& request, const std::string& program_version) {
  // The scene as it will run: overrides applied, so that an override equal to the
  // file's value (a sweep's reference point) shares the plain run's cache entry.
  nlohmann::json scene = load_scene_file(request.scene_file.string());  // a regular file within its cap
  for (const auto& o : request.overrides) apply_override(scene, o);
  // The description left out (prose only) and integers as doubles, so that a scene's 2500 and an
  // override's 2500.0 give the same key.
  std::string material = canonical_scene(scene).dump();
  collect_referenced_files(scene, request.scene_file.parent_path(), material);
  material += "\n" + program_version;
  return hex_key(material);
}

std::string program_identity(const fs::path& binary, const std::string& program_version) {
  // The version string alone misses a rebuild without a new commit; the binary's
  // bytes do not (a few MB: milliseconds).
  return program_version + " " + hex_key(read_file(binary));
}

namespace {

/// The runs of one run_all: the requests given, then the follow-ups' as they come
/// (requests_[i] ↔ outcomes_[i]). A run whose key an earlier request has is that
/// request's duplicate and runs once (studies may share a run).
class RunPool {
 public:
  RunPool(const fs::path& ffp_binary, const std::vector<RunRequest>& requests, const fs::path& cache_root,
          std::string identity, std::span<FollowUp> follow_ups)
      : binary_(ffp_binary),
        cache_root_(cache_root),
        identity_(std::move(identity)),
        given_(requests.size()),
        requests_(requests),
        follow_ups_(follow_ups),
        made_(follow_ups.size(), 0),
        follow_up_runs_(follow_ups.size()) {
    enqueue(0);
    std::fprintf(stderr, "runs: %zu to do, %zu cached\n", pending_.size(), cached_);
  }

  /// One job array for the given runs, then one for the follow-ups' (they need the first's results).
  std::vector<RunOutcome> on_slurm() {
    if (!pending_.empty()) ffp::run_on_slurm(binary_, requests_, pending_, outcomes_, cache_root_);
    std::fill(done_.begin(), done_.end(), 1);
    next_ = pending_.size();
    make_follow_ups(true);
    const std::vector<std::size_t> second(pending_.begin() + static_cast<long>(next_), pending_.end());
    if (!second.empty()) ffp::run_on_slurm(binary_, requests_, second, outcomes_, cache_root_);
    return finish();
  }

  /// At most `jobs` runs at once on this machine, the follow-ups' runs joining the queue as
  /// their inputs finish.
  std::vector<RunOutcome> on_this_machine(int jobs) {
    const std::size_t parallel = static_cast<std::size_t>(std::max(1, jobs));
    set_child_environment(parallel);
    make_follow_ups(false);  // those whose inputs were all cached
    while (finished_ < pending_.size()) {
      while (running_.size() < parallel && next_ < pending_.size()) launch(pending_[next_++]);
      if (running_.empty()) continue;
      int status = 0;
      const pid_t pid = wait_for_a_run(status);
      if (interrupt_requested()) {
        stop_running();
        throw_if_interrupted();
      }
      if (pid < 0) {
        if (errno == EINTR) continue;
        break;
      }
      const auto it = running_.find(pid);
      if (it == running_.end()) continue;
      record_exit(it->second, status);
      running_.erase(it);
      try {
        make_follow_ups(false);
      } catch (...) {
        stop_running();  // a follow-up that cannot be made stops the report, and its runs with it
        throw;
      }
    }
    return finish();
  }

 private:
  struct Running {
    std::size_t index;
    std::chrono::steady_clock::time_point start;
    fs::path log;
  };

  /// Keys, duplicates and cache for requests_[from, end); the new pending runs go among
  /// those not started yet, longest first (stable: else in the given order). Returns how
  /// many are to run.
  std::size_t enqueue(std::size_t from) {
    const std::size_t n = requests_.size();
    outcomes_.resize(n);
    done_.resize(n, 0);
    original_.resize(n);
    expected_wall_s_.resize(n, 0.0);
    std::vector<std::size_t> fresh;
    for (std::size_t i = from; i < n; ++i) {
      const std::string key = run_key(requests_[i], identity_);
      const auto [it, inserted] = first_with_key_.emplace(key, i);
      original_[i] = it->second;
      expected_wall_s_[it->second] = std::max(expected_wall_s_[it->second], requests_[i].expected_wall_s);
      if (!inserted) {
        ++duplicates_;
        continue;
      }
      outcomes_[i].out_dir = cache_root_ / (slug(requests_[i].label) + "-" + key);
      // Complete when its manifest is there (written last, then the folder renamed
      // into place); summary.json alone marks a run cached before manifests.
      if (fs::exists(outcomes_[i].out_dir / kOutputManifest) || fs::exists(outcomes_[i].out_dir / "summary.json")) {
        outcomes_[i].cached = true;
        outcomes_[i].exit_code = 0;
        done_[i] = 1;
        ++cached_;
      } else {
        fresh.push_back(i);
      }
    }
    pending_.insert(pending_.end(), fresh.begin(), fresh.end());
    std::stable_sort(pending_.begin() + static_cast<long>(next_), pending_.end(),
                     [&](std::size_t a, std::size_t b) { return expected_wall_s_[a] > expected_wall_s_[b]; });
    return fresh.size();
  }

  /// Request i's outcome: its own, or (a duplicate) its original's, marked cached.
  RunOutcome outcome_of(std::size_t i) const {
    RunOutcome o = outcomes_[original_[i]];
    if (original_[i] != i) o.cached = true;
    return o;
  }

  /// The follow-ups whose inputs are all done (or all of them) make their runs.
  void make_follow_ups(bool all_done) {
    for (std::size_t f = 0; f < follow_ups_.size(); ++f) {
      if (made_[f]) continue;
      FollowUp& up = follow_ups_[f];
      bool ready = true;
      for (std::size_t i = up.first; i < up.last && ready; ++i) ready = done_[original_[i]] != 0;
      if (!ready && !all_done) continue;
      made_[f] = 1;
      std::vector<RunOutcome> inputs;
      for (std::size_t i = up.first; i < up.last; ++i) inputs.push_back(outcome_of(i));
      up.requests = up.make(inputs);
      const std::size_t from = requests_.size();
      requests_.insert(requests_.end(), up.requests.begin(), up.requests.end());
      const std::size_t to_run = enqueue(from);
      for (std::size_t i = from; i < requests_.size(); ++i) follow_up_runs_[f].push_back(i);
      if (!up.requests.empty())
        std::fprintf(stderr, "runs: %zu more that use the results of earlier runs, %zu to do\n", up.requests.size(),
                     to_run);
    }
  }

  /// The follow-ups' outcomes into them; the given requests' outcomes returned.
  std::vector<RunOutcome> finish() {
    for (std::size_t f = 0; f < follow_ups_.size(); ++f) {
      follow_ups_[f].outcomes.clear();
      for (const std::size_t i : follow_up_runs_[f]) follow_ups_[f].outcomes.push_back(outcome_of(i));
    }
    std::vector<RunOutcome> given(given_);
    for (std::size_t i = 0; i < given_; ++i) given[i] = outcome_of(i);
    return given;
  }

  /// The children's environment: this one's, with each run's share of OpenMP threads
  /// (spinning threads on an oversubscribed machine slow everything down) unless the
  /// user chose OMP_NUM_THREADS, and this process's id, so that the runs stop when it
  /// dies, however it dies (see command_run).
  void set_child_environment(std::size_t parallel) {
    for (char** e = environ; *e != nullptr; ++e)
      if (std::string_view(*e).rfind("FFP_RUN_POOL_PID=", 0) != 0) environment_.emplace_back(*e);
    if (std::getenv("OMP_NUM_THREADS") == nullptr) {
      const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
      environment_.push_back("OMP_NUM_THREADS=" + std::to_string(std::max<std::size_t>(1, cores / parallel)));
    }
    environment_.push_back("FFP_RUN_POOL_PID=" + std::to_string(::getpid()));
    for (auto& e : environment_) child_environ_.push_back(e.data());
    child_environ_.push_back(nullptr);
  }

  void launch(std::size_t i) {
    const RunRequest& r = requests_[i];
    std::vector<std::string> args = {
        binary_.string(), "run", r.scene_file.string(), "--out", outcomes_[i].out_dir.string(), "--quiet"};
    for (const auto& o : r.overrides) {
      args.push_back("--set");
      args.push_back(o);
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const fs::path log = cache_root_ / ("." + slug(r.label) + ".log");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    // Each run in a process group of its own: a terminal's Ctrl-C reaches only this process, which
    // then stops every run once (stop_running). Were the runs in the terminal's group, each would get
    // the SIGINT and then that SIGTERM, and a second signal ends a run at once, leaving its
    // temporary folder behind (interrupt.cpp).
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), child_environ_.data());
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
      outcomes_[i].exit_code = 127;
      outcomes_[i].error = "could not start " + args[0];
      done_[i] = 1;
      ++finished_;
      return;
    }
    running_[pid] = Running{i, std::chrono::steady_clock::now(), log};
  }

  /// A run's exit: its outcome, its log kept only when it failed, a progress line.
  void record_exit(const Running& run, int status) {
    const std::size_t i = run.index;
    RunOutcome& o = outcomes_[i];
    o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    o.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.start).count();
    if (o.exit_code != 0) o.error = last_line(run.log);
    std::error_code ignored;
    if (o.exit_code == 0) fs::remove(run.log, ignored);
    done_[i] = 1;
    ++finished_;
    std::fprintf(stderr, "  [%zu/%zu] %-40s %s (%.1f s)\n", finished_ + cached_, requests_.size() - duplicates_,
                 requests_[i].label.c_str(), o.exit_code == 0 ? "done" : "FAILED", o.wall_time_s);
  }

  void stop_running() {
    int status = 0;
    for (const auto& [child, _] : running_) ::kill(child, SIGTERM);
    while (::waitpid(-1, &status, 0) > 0) {
    }
  }

  const fs::path binary_, cache_root_;
  const std::string identity_;
  const std::size_t given_;  ///< the requests given; the follow-ups' come after them
  std::vector<RunRequest> requests_;
  std::vector<RunOutcome> outcomes_;
  std::vector<std::size_t> pending_;  ///< to run; [next_, end) not started yet
  std::size_t next_ = 0, finished_ = 0;
  std::vector<char> done_;                             ///< finished or cached (a duplicate: see original_)
  std::vector<std::size_t> original_;                  ///< a request's first request with the same key (itself if none)
  std::map<std::string, std::size_t> first_with_key_;  ///< studies may share a run: run it once
  std::vector<double> expected_wall_s_;                ///< a shared run keeps the largest estimate
  std::size_t duplicates_ = 0, cached_ = 0;
  std::span<FollowUp> follow_ups_;
  std::vector<char> made_;                                ///< per follow-up: its runs made
  std::vector<std::vector<std::size_t>> follow_up_runs_;  ///< per follow-up: where its runs went
  std::map<pid_t, Running> running_;
  std::vector<std::string> environment_;  ///< the children's, and the pointers posix_spawn takes
  std::vector<char*> child_environ_;
};

}  // namespace

std::vector<RunOutcome> run_all(const fs::path& ffp_binary, const std::vector<RunRequest>& requests,
                                const fs::path& cache_root, const std::string& program_version, int jobs,
                                Scheduler scheduler, std::span<FollowUp> follow_ups) {
  fs::create_directories(cache_root);
  RunPool pool(ffp_binary, requests, cache_root, program_identity(ffp_binary, program_version), follow_ups);
  return scheduler == Scheduler::slurm ? pool.on_slurm() : pool.on_this_machine(jobs);
}

}  // namespace ffp
