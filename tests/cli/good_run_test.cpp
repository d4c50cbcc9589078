/// A good scene runs, writes summary.json with the scene echoed back (defaults
/// filled in), and replaces an older result only when complete.
#include <catch2/catch.hpp>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
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

TEST_CASE("a good scene writes summary.json with the scene and its defaults", "[cli]") {
  Scratch scratch;
  const auto file = scratch.write_json("scene.json", good_point_scene());
  const auto r = run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(scratch.path() / "result" / "summary.json");
  const json summary = json::parse(in);
  CHECK(summary["scene"]["kind"] == "point");
  CHECK(summary["scene"]["material"]["E_kPa"] == 2500.0);
  // Defaults the scene left out are written back.
  CHECK(summary["scene"]["material"]["c_peak_kPa"] == 0.0);
  CHECK(summary["scene"]["material"]["psi_peak_deg"] == 0.0);
  CHECK(summary.contains("wall_time_s"));
  CHECK(summary["steps"].get<long>() > 0);
  CHECK(fs::exists(scratch.path() / "result" / "history.csv"));
  // Only the result itself is left beside it: no temporary directories.
  for (const auto& name : scratch.entries()) CHECK((name == "result" || name == "scene.json"));
}

TEST_CASE("a set override changes a key and the summary echoes it", "[cli]") {
  Scratch scratch;
  const auto file = scratch.write_json("scene.json", good_point_scene());
  const auto r =
      run_ffp({"run", file.string(), "--out", "result", "--quiet", "--set", "material.E_kPa=5000"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(scratch.path() / "result" / "summary.json");
  CHECK(json::parse(in)["scene"]["material"]["E_kPa"] == 5000.0);
}

TEST_CASE("a complete run replaces an older result", "[cli]") {
  Scratch scratch;
  const auto file = scratch.write_json("scene.json", good_point_scene());
  REQUIRE(run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  const auto first = fs::last_write_time(scratch.path() / "result" / "summary.json");
  REQUIRE(run_ffp({"run", file.string(), "--out", "result", "--quiet", "--set", "material.E_kPa=5000"}, scratch.path())
              .exit_code == 0);
  std::ifstream in(scratch.path() / "result" / "summary.json");
  CHECK(json::parse(in)["scene"]["material"]["E_kPa"] == 5000.0);
  CHECK(fs::last_write_time(scratch.path() / "result" / "summary.json") >= first);
}

TEST_CASE("SIGTERM during a run leaves no result directory", "[cli]") {
  Scratch scratch;
  json scene = good_point_scene();
  scene["path"]["increments"] = 10000000;  // ~10 s of work, far longer than the test waits
  const auto file = scratch.write_json("scene.json", scene);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    if (::chdir(scratch.path().c_str()) != 0) ::_exit(99);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDERR_FILENO);
    ::execl(FFP_BINARY, FFP_BINARY, "run", file.c_str(), "--out", "result", static_cast<char*>(nullptr));
    ::_exit(98);
  }
  // Wait until the run has started writing into its temporary directory.
  bool started = false;
  for (int i = 0; i < 200 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    for (const auto& name : scratch.entries()) started = started || name.find(".result.tmp-") == 0;
  }
  CHECK(started);
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  for (const auto& name : scratch.entries()) CHECK(name == "scene.json");
}

TEST_CASE("version and help answer and succeed", "[cli]") {
  Scratch scratch;
  const auto v = run_ffp({"--version"}, scratch.path());
  CHECK(v.exit_code == 0);
  CHECK(v.out.rfind("ffp ", 0) == 0);
  const auto h = run_ffp({"--help"}, scratch.path());
  CHECK(h.exit_code == 0);
  CHECK(h.out.find("run SCENE.json") != std::string::npos);
}

// The version is `git describe` at build time, not at configure time: a commit after
// configuring must not leave the program (and every summary.json) naming an older one.
TEST_CASE("the version names the commit the program was built from, in summary.json too", "[cli]") {
  std::string head;
  if (FILE* git = popen("git -C \"" FFP_SOURCE_DIR "\" rev-parse HEAD 2>/dev/null", "r")) {
    char line[128] = {};
    if (std::fgets(line, sizeof line, git)) head = line;
    pclose(git);
  }
  if (head.size() < 40) {
    WARN("the source tree is not a git checkout: nothing to compare the version with");
    return;
  }
  Scratch scratch;
  const auto v = run_ffp({"--version"}, scratch.path());
  REQUIRE(v.exit_code == 0);
  INFO("ffp --version: " << v.out << "HEAD: " << head << "(fails on a program built before HEAD's commit: rebuild it)");
  CHECK(v.out.find(head.substr(0, 7)) != std::string::npos);
  const auto file = scratch.write_json("scene.json", good_point_scene());
  REQUIRE(run_ffp({"run", file.string(), "--out", "result", "--quiet"}, scratch.path()).exit_code == 0);
  std::ifstream in(scratch.path() / "result" / "summary.json");
  const std::string version = json::parse(in).at("ffp_version").get<std::string>();
  CHECK(v.out.rfind("ffp " + version, 0) == 0);
}

TEST_CASE("an FFP run's particle fields carry the stress components beside p and q", "[cli]") {
  Scratch scratch;
  const auto r =
      run_ffp({"run", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json", "--out", "result", "--quiet", "--set",
               "mesh.min_cell_m=0.02", "--set", "end_time_s=0.004", "--set", "output.field_times_s=[0.002]"},
              scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(scratch.path() / "result" / "fields" / "particles_0000.vtu");
  const std::string vtu((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* name :
       {"sigma_rr_kPa", "sigma_zz_kPa", "sigma_tt_kPa", "sigma_rz_kPa", "p_kPa", "q_kPa", "plastic_deviatoric_strain"})
    CHECK(vtu.find(std::string("Name=\"") + name + "\"") != std::string::npos);
}
