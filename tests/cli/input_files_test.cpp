/// Input files that are not regular files, or are too large, are refused
/// before they are read, in one line naming the file and what it is; running
/// out of memory and absurd thread counts end in a message, not a crash.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include <sys/stat.h>

#include "cli_harness.hpp"

using ffp::test::good_point_scene;
using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

/// A named pipe blocks its reader until a writer comes: without the check ffp would wait forever,
/// so every command here runs under `timeout`, and a hang fails the test (exit 124) instead.
const std::string kNoHang = "timeout 120";

long lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The D_r = 0 % calibration scene with its lab curve at `csv` (relative to the scratch folder).
fs::path calibration_scene(const Scratch& scratch, const std::string& csv) {
  json scene = json::parse(read_text(fs::path(FFP_SOURCE_DIR) / "data/scenes/calibration_dr00.json"));
  scene["lab_curve_csv"] = csv;
  return scratch.write_json("calibration.json", scene);
}

void make_fifo(const fs::path& path) { REQUIRE(::mkfifo(path.c_str(), 0644) == 0); }

/// `ffp check` and `ffp run` both refuse `scene` with exit 2, in one line holding `expected`, and leave nothing.
void both_refuse(const Scratch& scratch, const fs::path& scene, const std::string& expected) {
  const auto before = scratch.entries();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check", scene.string()}, {"run", scene.string(), "--out", "result", "--quiet"}}) {
    const auto r = run_ffp(args, scratch.path(), {}, kNoHang);
    INFO(args[0] << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(expected));
    CHECK(scratch.entries() == before);
  }
}

}  // namespace

TEST_CASE("a named pipe as the scene or as a file it names is refused at once, never read", "[cli]") {
  Scratch scratch;
  make_fifo(scratch.path() / "scene.json");
  both_refuse(scratch, scratch.path() / "scene.json", "scene.json: is a named pipe");

  Scratch lab;
  make_fifo(lab.path() / "lab.csv");
  both_refuse(lab, calibration_scene(lab, "lab.csv"), "lab.csv: is a named pipe (a CSV file must be a regular file)");

  Scratch record;
  make_fifo(record.path() / "drop.csv");
  const auto scene =
      record.write_json("drop.json", {{"kind", "record"}, {"record_csv", "drop.csv"}, {"ffp", {{"mass_kg", 7.71}}}});
  both_refuse(record, scene, "drop.csv' is a named pipe");
}

TEST_CASE("a directory or a device as the scene is refused naming what it is", "[cli]") {
  Scratch scratch;
  fs::create_directories(scratch.path() / "folder.json");
  both_refuse(scratch, scratch.path() / "folder.json", "folder.json: is a directory");
  // /dev/zero never ends: read whole, it took 4.2 GB of memory before the JSON parser gave up.
  both_refuse(scratch, "/dev/zero", "/dev/zero: is a device");
  // A link is judged by what it points to.
  fs::create_symlink("/dev/zero", scratch.path() / "zero.json");
  both_refuse(scratch, scratch.path() / "zero.json", "zero.json: is a device");
}

TEST_CASE("a scene or a CSV beyond its size cap is refused naming the cap", "[cli]") {
  Scratch scratch;
  // Sparse files: the size is what stat() reports; nothing is read or written to disk.
  const fs::path scene = scratch.path() / "huge.json";
  std::ofstream(scene) << "{";
  fs::resize_file(scene, 17u << 20);
  both_refuse(scratch, scene, "huge.json: is 17 MiB: a scene file may be at most 16 MiB");

  Scratch lab;
  const fs::path csv = lab.path() / "lab.csv";
  std::ofstream(csv) << "axial_strain,deviatoric_stress_kPa\n";
  fs::resize_file(csv, 257ull << 20);
  both_refuse(lab, calibration_scene(lab, "lab.csv"), "lab.csv: is 257 MiB: a CSV file may be at most 256 MiB");
}

TEST_CASE("a CSV that starts with a UTF-8 byte-order mark reads as one without", "[cli]") {
  Scratch scratch;
  const std::string curve = read_text(fs::path(FFP_SOURCE_DIR) / "data/lab/triaxial_dr00.csv");
  scratch.write("bom.csv", "\xEF\xBB\xBF" + curve);
  scratch.write("plain.csv", curve);
  const auto with_mark = run_ffp({"check", calibration_scene(scratch, "bom.csv").string()}, scratch.path());
  INFO(with_mark.err);
  CHECK(with_mark.exit_code == 0);
  const auto without = run_ffp({"check", calibration_scene(scratch, "plain.csv").string()}, scratch.path());
  REQUIRE(without.exit_code == 0);
  // The same scene but for the file's name: the same resolved scene.
  std::string expected = without.out;
  for (std::size_t at; (at = expected.find("plain.csv")) != std::string::npos;) expected.replace(at, 9, "bom.csv");
  CHECK(with_mark.out == expected);
  // A scene with the mark reads too, as JSON allows.
  const auto scene = scratch.write("point.json", "\xEF\xBB\xBF" + good_point_scene().dump());
  CHECK(run_ffp({"check", scene.string()}, scratch.path()).exit_code == 0);
}

TEST_CASE("running out of memory says how much may be used and what to make smaller", "[cli]") {
#if defined(__SANITIZE_ADDRESS__)
  WARN("not run under AddressSanitizer: it reserves terabytes of address space, which ulimit -v forbids");
  return;
#endif
  Scratch scratch;
  // A 50 MB record (under the 256 MiB cap) read by a process allowed 100 MB of address space, about
  // 40 MB of it taken by the program and its libraries: its 25 million numbers cannot fit.
  std::string rows = "time_s,deceleration_g\n";
  rows.reserve(50'000'100);
  while (rows.size() < 50'000'000) rows += "1,1\n";
  scratch.write("drop.csv", rows);
  const auto scene =
      scratch.write_json("drop.json", {{"kind", "record"}, {"record_csv", "drop.csv"}, {"ffp", {{"mass_kg", 7.71}}}});
  const auto r = run_ffp({"check", scene.string()}, scratch.path(), {}, "ulimit -v 100000 &&");
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK(lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("out of memory (this process may use"));
  CHECK_THAT(r.err, Catch::Contains("a shorter record or table"));
  CHECK_THAT(r.err, !Catch::Contains("bad_alloc"));
}

TEST_CASE("OMP_NUM_THREADS far beyond the cores is capped with a warning, not a crash", "[cli]") {
  // 100000 threads crashed libgomp at the first parallel region (SIGSEGV); the reference FFP at its
  // 1 cm cells has 6086 particles, enough for the MPM loops to run in parallel.
  Scratch scratch;
  const auto r = run_ffp({"run", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json", "--out", "result", "--quiet",
                          "--set", "end_time_s=0.0005", "--set", "output.field_times_s=[]"},
                         scratch.path(), {}, "OMP_NUM_THREADS=100000");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("warning: OMP_NUM_THREADS=100000 is more than 4 × the"));
  CHECK(fs::exists(scratch.path() / "result" / "summary.json"));
}
