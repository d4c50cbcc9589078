/// ffp never deletes what it did not write, and a run killed at any moment
/// (SIGKILL included) leaves no folder that looks finished: outputs are
/// written under a hidden temporary name, get a manifest of their files, and
/// are renamed into place only when complete.
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
using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

/// Starts `ffp ARGS` in `cwd` (stderr to /dev/null) and returns its pid.
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

/// Whether some entry under `folder` (recursively) has `fragment` in its name.
bool has_entry(const fs::path& folder, const std::string& fragment, const std::string& except_prefix = "") {
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.find(fragment) != std::string::npos && (except_prefix.empty() || !name.starts_with(except_prefix)))
      return true;
  }
  return false;
}

/// True once has_entry(folder, fragment) holds, within ~10 s.
bool wait_for_entry(const fs::path& folder, const std::string& fragment) {
  for (int i = 0; i < 500; ++i) {
    if (has_entry(folder, fragment)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

/// True once no entry under `folder` has `fragment` in its name, within ~30 s. The runs clean up
/// within a second on an idle machine; under the sanitizers with ctest -j2 on 2 cores a killed
/// sweep's runs took longer than the 5 s this waited before (an intermittent failure), and what
/// the test asserts is that the folders go, not how fast.
bool wait_until_gone(const fs::path& folder, const std::string& fragment, const std::string& except_prefix = "") {
  for (int i = 0; i < 1500; ++i) {
    if (!has_entry(folder, fragment, except_prefix)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

void kill_hard(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

/// A point scene that takes many seconds (far longer than the tests wait).
json slow_point_scene() {
  json scene = good_point_scene();
  scene["path"]["increments"] = 20000000;
  return scene;
}

}  // namespace

TEST_CASE("run --out refuses a folder holding the user's own files and leaves them", "[cli]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "mydata");
  scratch.write("mydata/notes.txt", "field notes");
  const auto file = scratch.write_json("scene.json", good_point_scene());
  const auto r = run_ffp({"run", file.string(), "--out", "mydata", "--quiet"}, scratch.path());
  CHECK(r.exit_code == 2);
  CHECK(lines(r.err) == 1);
  CHECK(r.err.find("--out") != std::string::npos);
  CHECK(r.err.find("notes.txt") != std::string::npos);
  CHECK(r.err.find("--force") != std::string::npos);
  CHECK(read_text(scratch.path() / "mydata" / "notes.txt") == "field notes");
  CHECK_FALSE(fs::exists(scratch.path() / "mydata" / "summary.json"));
  for (const auto& name : scratch.entries()) CHECK((name == "mydata" || name == "scene.json"));
}

TEST_CASE("run --force replaces a folder of the user's", "[cli]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "mydata");
  scratch.write("mydata/notes.txt", "field notes");
  const auto file = scratch.write_json("scene.json", good_point_scene());
  REQUIRE(run_ffp({"run", file.string(), "--out", "mydata", "--quiet", "--force"}, scratch.path()).exit_code == 0);
  CHECK_FALSE(fs::exists(scratch.path() / "mydata" / "notes.txt"));
  CHECK(fs::exists(scratch.path() / "mydata" / "summary.json"));
}

TEST_CASE("a run replaces its own earlier result, but not once the user has added a file", "[cli]") {
  Scratch scratch;
  const auto file = scratch.write_json("scene.json", good_point_scene());
  REQUIRE(run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  REQUIRE(fs::exists(scratch.path() / "result" / ".ffp-output.json"));
  CHECK(run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  scratch.write("result/plots/my_annotations.txt", "mine");
  const auto refused = run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path());
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("plots/my_annotations.txt") != std::string::npos);
  CHECK(read_text(scratch.path() / "result" / "plots" / "my_annotations.txt") == "mine");
}

TEST_CASE("a run folder written before manifests is replaced only if it holds nothing but ffp's files", "[cli]") {
  Scratch scratch;
  const auto file = scratch.write_json("scene.json", good_point_scene());
  fs::create_directories(scratch.path() / "legacy" / "plots");
  scratch.write("legacy/summary.json", R"({"ffp_version": "0.1.0"})");
  scratch.write("legacy/history.csv", "a\n1\n");
  CHECK(run_ffp({"run", file.string(), "--out", "legacy", "--quiet"}, scratch.path()).exit_code == 0);
  fs::create_directories(scratch.path() / "legacy2");
  scratch.write("legacy2/summary.json", R"({"ffp_version": "0.1.0"})");
  scratch.write("legacy2/notes.txt", "mine");
  CHECK(run_ffp({"run", file.string(), "--out", "legacy2", "--quiet"}, scratch.path()).exit_code == 2);
  CHECK(fs::exists(scratch.path() / "legacy2" / "notes.txt"));
}

TEST_CASE("report and sweep refuse folders holding the user's files before any run", "[cli]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "mine");
  scratch.write("mine/notes.txt", "field notes");
  const auto file = scratch.write_json("scene.json", good_point_scene());
  const auto report_out = run_ffp({"report", "--out", "mine", "--cache", "cache"}, scratch.path());
  CHECK(report_out.exit_code == 2);
  CHECK(report_out.err.find("--out") != std::string::npos);
  const auto report_cache = run_ffp({"report", "--out", "rep", "--cache", "mine"}, scratch.path());
  CHECK(report_cache.exit_code == 2);
  CHECK(report_cache.err.find("--cache") != std::string::npos);
  const auto sweep =
      run_ffp({"sweep", file.string(), "--set", "material.E_kPa=1000,2000", "--out", "mine"}, scratch.path());
  CHECK(sweep.exit_code == 2);
  CHECK(sweep.err.find("--out") != std::string::npos);
  CHECK(read_text(scratch.path() / "mine" / "notes.txt") == "field notes");
  for (const auto& name : scratch.entries()) CHECK((name == "mine" || name == "scene.json"));
}

TEST_CASE("SIGKILL during a run leaves no finished-looking folder and a rerun completes", "[cli]") {
  Scratch scratch;
  const auto slow = scratch.write_json("slow.json", slow_point_scene());
  const auto good = scratch.write_json("good.json", good_point_scene());
  // An earlier complete result, which the killed run must not damage.
  REQUIRE(run_ffp({"run", good.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  const std::string before = read_text(scratch.path() / "result" / "summary.json");
  const pid_t child = start_ffp({"run", slow.string(), "--out", "result"}, scratch.path());
  REQUIRE(wait_for_entry(scratch.path(), ".result.tmp-"));
  kill_hard(child);
  CHECK(read_text(scratch.path() / "result" / "summary.json") == before);
  // The killed run's hidden temporary folder is removed by the next run into the same place.
  REQUIRE(run_ffp({"run", good.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  for (const auto& name : scratch.entries()) CHECK((name == "result" || name == "slow.json" || name == "good.json"));
}

TEST_CASE("SIGKILL during a sweep stops its runs, leaves no finished-looking run, and a rerun completes", "[cli]") {
  Scratch scratch;
  const auto slow = scratch.write_json("slow.json", slow_point_scene());
  const pid_t sweep =
      start_ffp({"sweep", slow.string(), "--set", "material.E_kPa=1000,2000", "--out", "sw"}, scratch.path());
  // The first ".tmp-" may be the sweep's own manifest being written: the kill can land between its
  // writing and its renaming (found under the sanitizers on a loaded machine), which the rerun must survive.
  REQUIRE(wait_for_entry(scratch.path() / "sw", ".tmp-"));
  kill_hard(sweep);
  // The runs the sweep started see it die (SIGTERM) and remove their temporary folders (the sweep's
  // own manifest temporary, if the kill left one, is the rerun's to remove).
  CHECK(wait_until_gone(scratch.path() / "sw", ".tmp-", ".ffp-output.json.tmp-"));
  CHECK_FALSE(fs::exists(scratch.path() / "sw" / "sweep.csv"));
  if (fs::exists(scratch.path() / "sw" / "runs"))
    for (const auto& entry : fs::directory_iterator(scratch.path() / "sw" / "runs"))
      if (entry.is_directory()) CHECK_FALSE(fs::exists(entry.path() / "summary.json"));
  // What a SIGKILL between the table's writing and its renaming leaves (a process that no longer
  // exists: pid 999999999 > pid_max); the rerun removes it with any manifest temporary.
  scratch.write("sw/sweep.csv.tmp-999999999", "material.E_kPa,");
  // The same sweep, now quick, completes into the same folder.
  const auto good = scratch.write_json("slow.json", good_point_scene());
  const auto rerun =
      run_ffp({"sweep", good.string(), "--set", "material.E_kPa=1000,2000", "--out", "sw"}, scratch.path());
  INFO(rerun.err);
  CHECK(rerun.exit_code == 0);
  CHECK(lines(read_text(scratch.path() / "sw" / "sweep.csv")) == 3);
  CHECK_FALSE(has_entry(scratch.path() / "sw", ".tmp-"));
}

namespace {

/// The calibration study's scenes and lab curves, copied so a test can break one.
void copy_calibration_scenes(const fs::path& root) {
  const fs::path source = fs::path(FFP_SOURCE_DIR) / "data";
  fs::create_directories(root / "scenes");
  fs::create_directories(root / "lab");
  for (const char* scene : {"calibration_dr00.json", "calibration_dr15.json", "triaxial_ssmc_paper.json"})
    fs::copy_file(source / "scenes" / scene, root / "scenes" / scene);
  for (const char* curve : {"triaxial_dr00.csv", "triaxial_dr15.csv"})
    fs::copy_file(source / "lab" / curve, root / "lab" / curve);
}

const std::vector<std::string> kCalibrationReport = {
    "report", "--scenes", "data/scenes", "--only", "Calibration of the softening", "--cache", "cache",
    "--out",  "rep",      "--jobs",      "2"};

}  // namespace

TEST_CASE("a failing run does not sink the report: it is marked failed and the rest is written", "[cli]") {
  Scratch scratch;
  copy_calibration_scenes(scratch.path() / "data");
  json broken = json::parse(read_text(scratch.path() / "data" / "scenes" / "calibration_dr00.json"));
  broken["lab_curve_csv"] = "../lab/missing.csv";
  scratch.write_json("data/scenes/calibration_dr00.json", broken);
  const auto r = run_ffp(kCalibrationReport, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 1);
  const std::string report = read_text(scratch.path() / "rep" / "report.md");
  CHECK(report.find("FAILED") != std::string::npos);
  CHECK(report.find("missing.csv") != std::string::npos);
  CHECK(report.find("D_r = 15 %") != std::string::npos);  // the other runs' rows are there
}

TEST_CASE("SIGKILL during a report leaves no report, no finished-looking cache entry, and a rerun completes", "[cli]") {
  Scratch scratch;
  copy_calibration_scenes(scratch.path() / "data");
  const std::string real = read_text(scratch.path() / "data" / "scenes" / "calibration_dr00.json");
  scratch.write_json("data/scenes/calibration_dr00.json", slow_point_scene());  // a run that takes long
  const pid_t report = start_ffp(kCalibrationReport, scratch.path());
  // The first ".tmp-" may be the cache's own manifest being written: the kill can land between its
  // writing and its renaming (found under the sanitizers), which the rerun must survive.
  REQUIRE(wait_for_entry(scratch.path() / "cache", ".tmp-"));
  kill_hard(report);
  // The runs the report started see it die (SIGTERM) and remove their temporary folders (the
  // report's own manifest temporary, if the kill left one, is the rerun's to remove).
  CHECK(wait_until_gone(scratch.path() / "cache", ".tmp-", ".ffp-output.json.tmp-"));
  CHECK_FALSE(fs::exists(scratch.path() / "rep"));
  for (const auto& entry : fs::directory_iterator(scratch.path() / "cache"))
    if (entry.is_directory() && entry.path().filename().string().rfind("calibration_dr00", 0) == 0)
      CHECK_FALSE(fs::exists(entry.path() / "summary.json"));
  scratch.write("data/scenes/calibration_dr00.json", real);
  const auto rerun = run_ffp(kCalibrationReport, scratch.path());
  INFO(rerun.err);
  CHECK(rerun.exit_code == 0);
  CHECK(fs::exists(scratch.path() / "rep" / "report.md"));
  CHECK_FALSE(has_entry(scratch.path() / "cache", ".tmp-"));
}

TEST_CASE("a cache whose manifest write was killed midway is still ffp's, and the leftover goes", "[cli]") {
  // What a SIGKILL between write_file_atomically's write and its rename leaves: only the manifest's
  // temporary, named after a process that no longer exists (pid 999999999 > pid_max).
  Scratch scratch;
  copy_calibration_scenes(scratch.path() / "data");
  fs::create_directories(scratch.path() / "cache");
  scratch.write("cache/.ffp-output.json.tmp-999999999", "{\"written_by\": \"ffp\"");
  const auto r = run_ffp(kCalibrationReport, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_FALSE(fs::exists(scratch.path() / "cache" / ".ffp-output.json.tmp-999999999"));
  // A file of the user's is still refused.
  Scratch other;
  copy_calibration_scenes(other.path() / "data");
  fs::create_directories(other.path() / "cache");
  other.write("cache/notes.tmp-1", "mine");
  const auto refused = run_ffp(kCalibrationReport, other.path());
  CHECK(refused.exit_code == 2);
  CHECK(read_text(other.path() / "cache" / "notes.tmp-1") == "mine");
}
