/// Ctrl-C as a terminal sends it: SIGINT to the whole foreground process group,
/// once the command has shown that it is at work: an inverse fit, a bench and
/// an FFP run exit 130 and leave no result behind (sweeps and reports:
/// interrupt_test.cpp).
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_harness.hpp"

using ffp::test::good_point_scene;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// `ffp ARGS` in `cwd`, leader of a process group of its own (as a shell starts a foreground
/// job), stderr to `err`, TMPDIR `tmp` if given.
class Command {
 public:
  Command(const std::vector<std::string>& args, const fs::path& cwd, fs::path err, const fs::path& tmp = {})
      : err_(std::move(err)) {
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setpgid(0, 0);
      if (!tmp.empty()) ::setenv("TMPDIR", tmp.c_str(), 1);
      if (::chdir(cwd.c_str()) != 0) ::_exit(99);
      const int devnull = ::open("/dev/null", O_WRONLY);
      const int log = ::open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(devnull, STDOUT_FILENO);
      ::dup2(log, STDERR_FILENO);
      std::vector<char*> argv = {const_cast<char*>(FFP_BINARY)};
      for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(FFP_BINARY, argv.data());
      ::_exit(98);
    }
    ::setpgid(pid_, pid_);  // also here: the signal must not race the child's own setpgid
  }
  Command(const Command&) = delete;
  Command& operator=(const Command&) = delete;
  ~Command() {
    if (exit_code_ < 0) {  // a test that failed before the end: leave no process behind
      ::kill(-pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
  }

  /// True once stderr holds `text`, within five minutes (the sanitizer build on two busy cores
  /// is many times slower than a release build on an idle one; what is asserted is that the
  /// command shows its work, not how soon).
  bool wait_for(const std::string& text) const {
    for (int i = 0; i < 3000; ++i) {
      if (read_text(err_).find(text) != std::string::npos) return true;
      siginfo_t ended{};
      if (::waitid(P_PID, static_cast<id_t>(pid_), &ended, WEXITED | WNOHANG | WNOWAIT) == 0 && ended.si_pid != 0)
        return read_text(err_).find(text) != std::string::npos;  // it ended without showing it
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  /// Ctrl-C: SIGINT to the whole group; then the exit code (128 + signal if a signal ended it).
  int interrupt() {
    ::kill(-pid_, SIGINT);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return exit_code_;
  }

  std::string err() const { return read_text(err_); }

 private:
  fs::path err_;
  pid_t pid_ = -1;
  int exit_code_ = -1;
};

/// A point scene that takes far longer than the tests wait (many seconds per run).
json slow_point_scene() {
  json scene = good_point_scene();
  scene["path"]["increments"] = 20000000;
  return scene;
}

}  // namespace

TEST_CASE("Ctrl-C during an inverse fit exits 130 and writes no fit", "[cli][interrupt]") {
  Scratch work, logs;
  Command fit({"run", FFP_SOURCE_DIR "/data/scenes/inverse_reference.json", "--out", "fit", "--jobs", "2"}, work.path(),
              logs.path() / "err");
  REQUIRE(fit.wait_for("runs:"));  // the first batch's model runs have started
  CHECK(fit.interrupt() == 130);
  INFO(fit.err());
  CHECK(fit.err().find("interrupted") != std::string::npos);
  CHECK(fit.err().find("error") == std::string::npos);
  CHECK(work.entries().empty());
}

TEST_CASE("Ctrl-C during ffp bench exits 130 and leaves no runs in the temporary folder", "[cli][interrupt]") {
  Scratch work, logs, tmp;
  fs::create_directories(work.path() / "scenes");
  // A scene under a name bench measures, that runs far longer than the test waits.
  json slow = slow_point_scene();
  slow["name"] = "point_triaxial_ssmc";
  work.write_json("scenes/point_triaxial_ssmc.json", slow);
  Command bench({"bench", "--scenes", "scenes", "--repeat", "1"}, work.path(), logs.path() / "err", tmp.path());
  REQUIRE(bench.wait_for("runs:"));
  CHECK(bench.interrupt() == 130);
  INFO(bench.err());
  CHECK(bench.err().find("interrupted") != std::string::npos);
  CHECK(tmp.entries().empty());  // the bench's runs went to TMPDIR/ffp-bench-N
}

TEST_CASE("an FFP run shows progress within seconds, and Ctrl-C then exits 130 and writes no result",
          "[cli][interrupt]") {
  // The reference drop to end_time_s = 1e4 s at 5 mm cells, estimated at days (so refused
  // without --allow-long: tests/cli/run_cost_test.cpp): its first 10 % takes hours, and its
  // progress must not wait for them.
  Scratch work, logs;
  Command run(
      {"run", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json", "--out", "result", "--set", "mesh.min_cell_m=0.005",
       "--set", "end_time_s=1e4", "--set", "output.history_interval_s=1", "--allow-long"},
      work.path(), logs.path() / "err");
  REQUIRE(run.wait_for("%  t = "));  // a progress line: percent, simulated time, steps/s, ETA
  INFO(run.err());
  CHECK_THAT(run.err(), Catch::Contains("ffp ffp_reference: about ") && Catch::Contains("estimated wall time"));
  CHECK(run.interrupt() == 130);
  CHECK_THAT(run.err(), Catch::Contains("interrupted: no result written"));
  CHECK(work.entries().empty());
}
