/// Ctrl-C in the middle of a sweep or a report: exit 130, and no hidden
/// temporary folder (".NAME.tmp-PID", ".NAME.old-PID") left anywhere, in the
/// run cache or beside the outputs. A terminal's Ctrl-C goes to the whole
/// foreground process group, so the tests send SIGINT to the group of a real
/// `ffp` process started in a group of its own, as a shell's job control does,
/// and also to the process alone, as `kill -INT` does.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_harness.hpp"

using ffp::test::good_point_scene;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

/// Starts `ffp ARGS` in `cwd` as the leader of a new process group (a shell's job), output to /dev/null.
pid_t start_job(const std::vector<std::string>& args, const fs::path& cwd) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);
    if (::chdir(cwd.c_str()) != 0) ::_exit(99);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDERR_FILENO);
    ::dup2(devnull, STDOUT_FILENO);
    std::vector<char*> argv = {const_cast<char*>(FFP_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(FFP_BINARY, argv.data());
    ::_exit(98);
  }
  ::setpgid(child, child);  // also here: the signal must not find the group missing
  return child;
}

/// The temporary entries under `root`: a run's hidden ".NAME.tmp-PID" folder, a replaced result's
/// ".NAME.old-PID", a file being written ("FILE.tmp-PID").
std::vector<std::string> temporary_entries(const fs::path& root) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.find(".old-") != std::string::npos)
      found.push_back(fs::relative(it->path(), root).string());
  }
  return found;
}

/// True once a run's temporary folder exists under `root`, within `seconds`: runs start in well under a second
/// on an idle machine; the margin is for a loaded one under the sanitizers, or a Slurm node busy with other jobs.
bool wait_for_a_run(const fs::path& root, int seconds = 20) {
  for (int i = 0; i < seconds * 50; ++i) {
    for (const auto& name : temporary_entries(root))
      if (fs::is_directory(root / name)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

/// Sends SIGINT to the job's group (a terminal's Ctrl-C) or to its leader alone; its exit code.
int interrupt(pid_t job, bool whole_group) {
  ::kill(whole_group ? -job : job, SIGINT);
  int status = 0;
  ::waitpid(job, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// A point scene that takes many seconds (far longer than the tests wait).
json slow_point_scene() {
  json scene = good_point_scene();
  scene["path"]["increments"] = 20000000;
  return scene;
}

/// The calibration study's scenes under data/, one of them made slow so that a run is under way when the
/// signal comes; returns the arguments of a report of that study alone into rep/, its runs cached in cache/.
std::vector<std::string> slow_calibration_report(const Scratch& scratch) {
  const fs::path source = fs::path(FFP_SOURCE_DIR) / "data";
  fs::create_directories(scratch.path() / "data" / "scenes");
  fs::create_directories(scratch.path() / "data" / "lab");
  for (const char* scene : {"calibration_dr15.json", "triaxial_ssmc_paper.json"})
    fs::copy_file(source / "scenes" / scene, scratch.path() / "data" / "scenes" / scene);
  for (const char* curve : {"triaxial_dr00.csv", "triaxial_dr15.csv"})
    fs::copy_file(source / "lab" / curve, scratch.path() / "data" / "lab" / curve);
  scratch.write_json("data/scenes/calibration_dr00.json", slow_point_scene());
  return {"report",  "--scenes", "data/scenes", "--only", "Calibration of the softening",
          "--cache", "cache",    "--out",       "rep"};
}

/// The one-node test cluster, started if it is not running (scripts/slurm_local.sh); false, with the
/// reason, where it cannot run.
bool slurm_cluster_up() {
  const std::string start = "bash " + std::string(FFP_SOURCE_DIR) + "/scripts/slurm_local.sh start > /dev/null 2>&1";
  if (std::system("command -v sbatch > /dev/null 2>&1") == 0 && std::system(start.c_str()) == 0) return true;
  WARN(
      "skipped: no Slurm here (needs root and Debian's slurm-wlm and munge: bash scripts/setup.sh; "
      "scripts/slurm_local.sh start says why it cannot start)");
  return false;
}

}  // namespace

TEST_CASE("Ctrl-C during a sweep stops its runs, exits 130 and leaves no temporary entry", "[cli][interrupt]") {
  bool whole_group = true;
  SECTION("to the process group, as a terminal sends it") { whole_group = true; }
  SECTION("to the sweep's process alone") { whole_group = false; }
  Scratch scratch;
  const fs::path slow = scratch.write_json("slow.json", slow_point_scene());
  const pid_t sweep = start_job(
      {"sweep", slow.string(), "--set", "material.E_kPa=1000,2000", "--jobs", "2", "--out", "sw"}, scratch.path());
  const bool started = wait_for_a_run(scratch.path() / "sw");
  const int code = interrupt(sweep, whole_group);
  REQUIRE(started);
  CHECK(code == 130);
  // Checked as soon as the sweep has exited: it waits for its runs, and they clean up before they exit.
  CHECK(temporary_entries(scratch.path()) == std::vector<std::string>{});
  CHECK_FALSE(fs::exists(scratch.path() / "sw" / "sweep.csv"));
}

TEST_CASE("Ctrl-C during a report's runs exits 130 and leaves no temporary entry in the cache", "[cli][interrupt]") {
  bool whole_group = true;
  SECTION("to the process group, as a terminal sends it") { whole_group = true; }
  SECTION("to the report's process alone") { whole_group = false; }
  Scratch scratch;
  std::vector<std::string> args = slow_calibration_report(scratch);
  args.insert(args.end(), {"--jobs", "2"});
  const pid_t report = start_job(args, scratch.path());
  const bool started = wait_for_a_run(scratch.path() / "cache");
  const int code = interrupt(report, whole_group);
  REQUIRE(started);
  CHECK(code == 130);
  CHECK(temporary_entries(scratch.path()) == std::vector<std::string>{});
  CHECK_FALSE(fs::exists(scratch.path() / "rep"));
}

TEST_CASE("Ctrl-C during a report's Slurm runs cancels the job and leaves no temporary entry in the cache",
          "[cli][interrupt][slurm]") {
  if (!slurm_cluster_up()) return;
  Scratch scratch;
  std::vector<std::string> args = slow_calibration_report(scratch);
  args.insert(args.end(), {"--scheduler", "slurm"});
  const pid_t report = start_job(args, scratch.path());
  const bool started = wait_for_a_run(scratch.path() / "cache", 300);  // a task runs on the node
  const int code = interrupt(report, true);
  REQUIRE(started);
  CHECK(code == 130);
  // The report waits for the cancelled job to leave the queue: its tasks have removed their temporary
  // folders, and the report has removed the array's own folder (".slurm-PID-N").
  CHECK(temporary_entries(scratch.path()) == std::vector<std::string>{});
  for (const auto& entry : fs::directory_iterator(scratch.path() / "cache"))
    CHECK_FALSE(entry.path().filename().string().starts_with(".slurm-"));
  CHECK_FALSE(fs::exists(scratch.path() / "rep"));
}

TEST_CASE("Ctrl-C during a sweep on Slurm cancels its job and leaves no temporary entry", "[cli][interrupt][slurm]") {
  if (!slurm_cluster_up()) return;
  Scratch scratch;
  const fs::path slow = scratch.write_json("slow.json", slow_point_scene());
  const pid_t sweep =
      start_job({"sweep", slow.string(), "--set", "material.E_kPa=1000,2000", "--scheduler", "slurm", "--out", "sw"},
                scratch.path());
  const bool started = wait_for_a_run(scratch.path() / "sw" / "runs", 300);  // a task runs on the node
  const int code = interrupt(sweep, true);
  REQUIRE(started);
  CHECK(code == 130);
  CHECK(temporary_entries(scratch.path()) == std::vector<std::string>{});
  CHECK_FALSE(fs::exists(scratch.path() / "sw" / "sweep.csv"));
}
