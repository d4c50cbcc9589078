/// Output paths a user may give by mistake or on purpose: a symbolic link, a
/// file of theirs, a name too long, a place where nothing can be written, a
/// folder another run is writing. Each is refused before the run, in one line
/// (exit 2), and nothing of the user's changes.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_harness.hpp"

using ffp::test::good_point_scene;
using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

long lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string shell_quote(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Starts `ffp ARGS` in `cwd` (its output discarded) and returns its process id.
pid_t start_ffp(const std::vector<std::string>& args, const fs::path& cwd) {
  const pid_t child = ::fork();
  if (child == 0) {
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
  return child;
}

/// Refused: exit 2, one line holding `expected`, and the scratch folder as it was.
void check_refused(const ffp::test::CommandResult& r, const std::string& expected, const Scratch& scratch,
                   const std::vector<std::string>& before) {
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(expected));
  CHECK(scratch.entries() == before);
}

}  // namespace

TEST_CASE("a symbolic link given as --out is never replaced, --force or not", "[cli]") {
  Scratch scratch;
  const auto scene = scratch.write_json("scene.json", good_point_scene());
  REQUIRE(run_ffp({"run", scene.string(), "--out", "run_old", "--quiet"}, scratch.path()).exit_code == 0);
  const std::string old_summary = read_text(scratch.path() / "run_old" / "summary.json");
  fs::create_directory_symlink("run_old", scratch.path() / "latest");
  fs::create_symlink("nowhere", scratch.path() / "dangling");
  const auto before = scratch.entries();
  for (const std::vector<std::string>& extra : {std::vector<std::string>{}, {"--force"}}) {
    std::vector<std::string> args = {"run", scene.string(), "--out", "latest", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    check_refused(run_ffp(args, scratch.path()), "--out: 'latest' is a symbolic link (to 'run_old')", scratch, before);
    args[3] = "dangling";
    check_refused(run_ffp(args, scratch.path()), "'dangling' is a symbolic link (to 'nowhere')", scratch, before);
  }
  // A report folder is replaced as a run's is: the same rule, before any run.
  check_refused(run_ffp({"report", "--out", "latest", "--cache", "cache"}, scratch.path()),
                "--out: 'latest' is a symbolic link", scratch, before);
  CHECK(fs::read_symlink(scratch.path() / "latest") == "run_old");
  CHECK(fs::read_symlink(scratch.path() / "dangling") == "nowhere");
  CHECK(read_text(scratch.path() / "run_old" / "summary.json") == old_summary);
}

TEST_CASE("a file given as --out is never replaced, even with --force", "[cli]") {
  Scratch scratch;
  const auto scene = scratch.write_json("scene.json", good_point_scene());
  scratch.write("notes.txt", "field notes");
  const auto before = scratch.entries();
  check_refused(run_ffp({"run", scene.string(), "--out", "notes.txt", "--quiet", "--force"}, scratch.path()),
                "--out: 'notes.txt' is a file, not a folder (--force replaces only folders)", scratch, before);
  CHECK(read_text(scratch.path() / "notes.txt") == "field notes");
}

TEST_CASE("an --out folder holding named pipes is judged without opening them", "[cli]") {
  // ffp reads a folder's manifest and summary.json to decide whether it wrote it: a pipe there
  // would keep it waiting for a writer (timeout: a hang fails the test instead).
  Scratch scratch;
  const auto scene = scratch.write_json("scene.json", good_point_scene());
  fs::create_directories(scratch.path() / "out");
  for (const char* name : {"summary.json", ".ffp-output.json", "report.md"})
    REQUIRE(::mkfifo((scratch.path() / "out" / name).c_str(), 0644) == 0);
  const auto before = scratch.entries();
  check_refused(run_ffp({"run", scene.string(), "--out", "out", "--quiet"}, scratch.path(), {}, "timeout 120"),
                "--out: 'out' holds 'report.md' and 1 more, which ffp did not write", scratch, before);
}

TEST_CASE("a name too long for the file system is refused in one line, one that fits is written", "[cli]") {
  Scratch scratch;
  const auto scene = scratch.write_json("scene.json", good_point_scene());
  // ffp writes ".NAME.tmp-PID" beside the target while it runs: 13 bytes more than NAME.
  const long name_max = ::pathconf(scratch.path().c_str(), _PC_NAME_MAX);
  REQUIRE(name_max > 20);
  const std::size_t longest = static_cast<std::size_t>(name_max) - 13;
  const auto before = scratch.entries();
  check_refused(run_ffp({"run", scene.string(), "--out", std::string(300, 'x'), "--quiet"}, scratch.path()),
                "is 300 bytes long; at most " + std::to_string(longest) + " fit here", scratch, before);
  check_refused(run_ffp({"run", scene.string(), "--out", std::string(longest + 1, 'y'), "--quiet"}, scratch.path()),
                "at most " + std::to_string(longest) + " fit here", scratch, before);
  const std::string fits(longest, 'z');
  const auto r = run_ffp({"run", scene.string(), "--out", fits, "--quiet"}, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(scratch.path() / fits / "summary.json"));
}

TEST_CASE("a place where nothing can be written is refused in one line before the run", "[cli]") {
  Scratch scratch;
  const auto scene = scratch.write_json("scene.json", good_point_scene());
  // /proc takes no new files, from anyone.
  const auto before = scratch.entries();
  check_refused(run_ffp({"run", scene.string(), "--out", "/proc/ffp-result", "--quiet"}, scratch.path()),
                "--out: cannot write in '/proc'", scratch, before);

  // A read-only folder: by its permissions for a user; for root, whom permissions do not stop, a
  // read-only tmpfs mounted in a mount namespace of its own (gone with the command).
  fs::create_directories(scratch.path() / "locked");
  const std::string locked = (scratch.path() / "locked").string();
  std::string command;
  if (::geteuid() != 0) {
    fs::permissions(scratch.path() / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    command = shell_quote(FFP_BINARY);
  } else {
    const std::string probe = "unshare -m sh -c " + shell_quote("mount -t tmpfs -o ro none " + locked) + " 2>/dev/null";
    if (std::system(probe.c_str()) != 0) {
      WARN("no read-only folder to try as root: this machine lets root neither unshare a mount namespace nor mount");
      return;
    }
    command = "unshare -m sh -c " +
              shell_quote("mount -t tmpfs -o ro none " + locked + " && exec " + FFP_BINARY + " \"$@\"") + " ffp";
  }
  const fs::path err = scratch.path() / "err.txt";
  command = "cd " + shell_quote(scratch.path().string()) + " && " + command + " run " + shell_quote(scene.string()) +
            " --out locked/result --quiet 2> " + shell_quote(err.string());
  const int status = std::system(command.c_str());
  const std::string message = read_text(err);
  fs::remove(err);
  fs::permissions(scratch.path() / "locked", fs::perms::owner_all);
  INFO(message);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  CHECK(lines(message) == 1);
  CHECK_THAT(message, Catch::Contains("--out: cannot write in 'locked'"));
  CHECK(fs::is_empty(scratch.path() / "locked"));
}

TEST_CASE("a second run into the same --out while the first runs is refused by its lock, and the first completes",
          "[cli]") {
  Scratch scratch;
  json slow = good_point_scene();
  slow["path"]["increments"] = 2000000;  // about a second: long enough to be caught holding the folder
  const auto slow_file = scratch.write_json("slow.json", slow);
  const auto quick_file = scratch.write_json("quick.json", good_point_scene());
  // A lock file a killed run left behind (no process holds it) stops no one.
  scratch.write(".result.lock", "999999999\n");
  const pid_t first = start_ffp({"run", slow_file.string(), "--out", "result", "--quiet"}, scratch.path());
  // The holder writes its process id once it holds the lock.
  const fs::path lock = scratch.path() / ".result.lock";
  bool held = false;
  for (int i = 0; i < 3000 && !held; ++i) {
    held = read_text(lock) == std::to_string(first) + "\n";
    if (!held) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(held);
  // The first is held still while the second tries, so the outcome does not depend on how long it runs.
  ::kill(first, SIGSTOP);
  const auto second = run_ffp({"run", quick_file.string(), "--out", "result", "--quiet"}, scratch.path());
  ::kill(first, SIGCONT);
  int status = 0;
  REQUIRE(::waitpid(first, &status, 0) == first);
  INFO(second.err);
  CHECK(second.exit_code == 2);
  CHECK(lines(second.err) == 1);
  CHECK_THAT(second.err, Catch::Contains("--out: 'result' is being written by another ffp (process " +
                                         std::to_string(first) + "): wait for it to finish"));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  const json summary = json::parse(read_text(scratch.path() / "result" / "summary.json"));
  CHECK(summary["scene"]["path"]["increments"] == 2000000);  // the first's result
  // No lock file, no temporary folder left.
  CHECK(scratch.entries() == std::vector<std::string>{"quick.json", "result", "slow.json"});
}
