// A result that says done is complete: every write is checked, a figure that cannot be drawn or
// written fails the run, and nothing is marked finished. Full disks are real (a small tmpfs), and
// so are full devices (/dev/full) and awkward paths.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "tests/support/small_tmpfs.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
using ffp::test_support::SmallTmpfs;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = std::string(FFP_SOURCE_DIR) + "/data/scenes/";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Whole by its own structure: the PNG signature first, the IEND chunk (with its fixed CRC) last.
bool complete_png(const fs::path& file) {
  const std::string bytes = bytes_of(file);
  const std::string signature("\x89PNG\r\n\x1a\n", 8), end("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return bytes.size() > signature.size() + end.size() && bytes.starts_with(signature) && bytes.ends_with(end);
}

std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

long lines_in(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

/// PATH set for the programs ffp starts, restored afterwards.
class PathFor {
 public:
  explicit PathFor(const std::string& path) : saved_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", path.c_str(), 1);
  }
  ~PathFor() { ::setenv("PATH", saved_.c_str(), 1); }
  PathFor(const PathFor&) = delete;
  PathFor& operator=(const PathFor&) = delete;

 private:
  std::string saved_;
};

bool gnuplot_installed() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE("ffp check into a full device fails with one line instead of printing nothing", "[cli][write]") {
  Scratch scratch;
  const auto r = run_ffp({"check", kScenes + "record_reference.json"}, scratch.path(), "/dev/full");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "error: cannot write to standard output: no space left on device\n");
  const auto fine = run_ffp({"check", kScenes + "record_reference.json"}, scratch.path());
  CHECK(fine.exit_code == 0);
  CHECK(fine.out.find("valid record scene 'record_reference'") != std::string::npos);
}

TEST_CASE("a run onto a nearly full disk fails, names the file and the cause, and leaves nothing finished",
          "[cli][write]") {
  Scratch scratch;
  SmallTmpfs disk(scratch.path() / "disk", "1m");
  if (!disk.mounted()) {
    WARN(disk.why_not());
    return;
  }
  // The 2 cm reference drop writes ~0.8 MB of fields, tables and figures: it runs out of room partway.
  const auto r = run_ffp({"run", kScenes + "ffp_reference.json", "--set", "mesh.min_cell_m=0.02", "--set",
                          "end_time_s=0.05", "--out", "disk/run", "--quiet"},
                         scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK(lines_in(r.err) == 1);
  CHECK(r.err.starts_with("error: cannot write 'disk/run/"));  // where the user looks, not the temporary
  CHECK(r.err.ends_with(": no space left on device\n"));
  CHECK(names_in(disk.path()).empty());  // no folder at the target, no temporary beside it
}

TEST_CASE("a report whose figures do not fit fails instead of writing a report without them", "[cli][write]") {
  Scratch scratch;
  SmallTmpfs disk(scratch.path() / "disk", "16k");
  if (!disk.mounted()) {
    WARN(disk.why_not());
    return;
  }
  if (!gnuplot_installed()) {
    WARN("gnuplot is not installed: the report draws no figures");
    return;
  }
  const fs::path scenes = scratch.path() / "data" / "scenes";
  fs::create_directories(scenes);
  fs::create_directories(scratch.path() / "data" / "lab");
  for (const char* scene : {"calibration_dr00.json", "calibration_dr15.json", "triaxial_ssmc_paper.json"})
    fs::copy_file(kScenes + scene, scenes / scene);
  for (const char* curve : {"triaxial_dr00.csv", "triaxial_dr15.csv"})
    fs::copy_file(fs::path(FFP_SOURCE_DIR) / "data" / "lab" / curve, scratch.path() / "data" / "lab" / curve);
  const auto r = run_ffp({"report", "--scenes", "data/scenes", "--only", "Calibration of the softening", "--cache",
                          "cache", "--out", "disk/rep", "--jobs", "2"},
                         scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("error: cannot write 'disk/rep/figures/") != std::string::npos);
  CHECK(r.err.ends_with(": no space left on device\n"));
  CHECK(names_in(disk.path()).empty());
}

TEST_CASE("an --out path with quotes, a space, a comma, $ and a backslash gets every figure, whole", "[cli][write]") {
  Scratch scratch;
  const auto plain = run_ffp({"run", kScenes + "record_reference.json", "--out", "plain", "--quiet"}, scratch.path());
  REQUIRE(plain.exit_code == 0);
  const std::vector<std::string> figures = names_in(scratch.path() / "plain" / "plots");
  if (figures.empty()) {
    WARN("gnuplot is not installed: no figures to compare (" + plain.err + ")");
    return;
  }
  const std::string awkward = "O'Brien drops, \"2024\" $HOME \\ x";
  const auto r = run_ffp({"run", kScenes + "record_reference.json", "--out", awkward, "--quiet"}, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK(names_in(scratch.path() / awkward / "plots") == figures);
  for (const auto& figure : figures) {
    INFO(figure);
    CHECK(complete_png(scratch.path() / awkward / "plots" / figure));
    CHECK(bytes_of(scratch.path() / awkward / "plots" / figure) ==
          bytes_of(scratch.path() / "plain" / "plots" / figure));
  }
}

TEST_CASE("a gnuplot that fails, or writes a cut-off PNG, fails the run: one line, nothing at the target",
          "[cli][write]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "bin");
  const auto fake_gnuplot = [&](const std::string& body) {
    scratch.write("bin/gnuplot", "#!/bin/sh\n" + body);
    fs::permissions(scratch.path() / "bin" / "gnuplot", fs::perms::owner_all);
  };
  PathFor path((scratch.path() / "bin").string());
  fake_gnuplot("echo '\"/dev/stdin\" line 12: cannot open font' >&2\nexit 1\n");
  const auto failed = run_ffp({"run", kScenes + "record_reference.json", "--out", "failed", "--quiet"}, scratch.path());
  CHECK(failed.exit_code == 1);
  CHECK(failed.err ==
        "error: cannot write 'failed/plots/depth_profiles.png': gnuplot failed (exit status 1): script line 12: "
        "cannot open font\n");
  CHECK_FALSE(fs::exists(scratch.path() / "failed"));
  // A PNG signature and nothing after it, exit status 0: what a terminal that does not check its writes leaves.
  fake_gnuplot("printf '\\211PNG\\r\\n\\032\\n'\nexit 0\n");
  const auto cut = run_ffp({"run", kScenes + "record_reference.json", "--out", "cut", "--quiet"}, scratch.path());
  CHECK(cut.exit_code == 1);
  CHECK(cut.err == "error: cannot write 'cut/plots/depth_profiles.png': gnuplot gave no complete PNG\n");
  CHECK_FALSE(fs::exists(scratch.path() / "cut"));
}

TEST_CASE("without gnuplot the figures are skipped with one warning and the run is done", "[cli][write]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "empty");
  PathFor path((scratch.path() / "empty").string());
  const auto r = run_ffp({"run", kScenes + "record_reference.json", "--out", "out", "--quiet"}, scratch.path());
  CHECK(r.exit_code == 0);
  CHECK(r.err == "warning: gnuplot not found: plots are skipped\n");
  CHECK(fs::exists(scratch.path() / "out" / "summary.json"));
  CHECK(names_in(scratch.path() / "out" / "plots").empty());
}
