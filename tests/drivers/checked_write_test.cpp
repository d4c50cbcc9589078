// Checked writes: a file is all of its content or a WriteFailure that names it and the system's cause.
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "drivers/output/checked_write.hpp"
#include "tests/support/scratch.hpp"
#include "tests/support/small_tmpfs.hpp"

namespace fs = std::filesystem;
using ffp::test_support::read_text;
using ffp::test_support::Scratch;
using ffp::test_support::SmallTmpfs;

namespace {

/// The entries of a folder (to show that no temporary was left behind).
int entries_in(const fs::path& folder) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++n;
  return n;
}

/// Runs `write` with standard output sent to `file`; standard output (and its error flags) is restored afterwards.
template <class Write>
void with_standard_output_to(const char* file, Write write) {
  std::cout.flush();
  std::fflush(stdout);  // what the test runner printed so far goes where it belongs
  const int saved = ::dup(STDOUT_FILENO);
  const int target = ::open(file, O_WRONLY);
  REQUIRE(saved >= 0);
  REQUIRE(target >= 0);
  ::dup2(target, STDOUT_FILENO);
  ::close(target);
  const auto restore = [&] {
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    std::clearerr(stdout);
    std::cout.clear();
  };
  try {
    write();
  } catch (...) {
    restore();
    throw;
  }
  restore();
}

}  // namespace

TEST_CASE("the cause of a failed write reads as a clause: errno's text in lower case", "[output][write]") {
  CHECK(ffp::cause_of(ENOSPC) == "no space left on device");
  CHECK(ffp::cause_of(ENOENT) == "no such file or directory");
  CHECK(ffp::cause_of(EISDIR) == "is a directory");
  const ffp::WriteFailure failure("out/summary.json", ffp::cause_of(ENOSPC));
  CHECK(std::string(failure.what()) == "cannot write 'out/summary.json': no space left on device");
}

TEST_CASE("a failure in a run's temporary folder is told where the user looks for the file", "[output][write]") {
  const ffp::WriteFailure failure(".run.tmp-42/plots/energy.png", "no space left on device");
  const ffp::WriteFailure moved = failure.moved(".run.tmp-42", "results/run");
  CHECK(moved.file() == fs::path("results/run/plots/energy.png"));
  CHECK(std::string(moved.what()) == "cannot write 'results/run/plots/energy.png': no space left on device");
  CHECK(failure.moved("elsewhere", "results/run").file() == failure.file());  // not under it: unchanged
}

TEST_CASE("a file written atomically holds all its content, cached or synced, and leaves no temporary",
          "[output][write]") {
  Scratch scratch("ffp-checked-write");
  const std::string content(200000, 'x');  // more than any stream buffer
  ffp::write_file_atomically(scratch.path / "cached.txt", content);
  ffp::write_file_atomically(scratch.path / "synced.txt", "done\n", ffp::Durability::synced);
  CHECK(read_text(scratch.path / "cached.txt") == content);
  CHECK(read_text(scratch.path / "synced.txt") == "done\n");
  ffp::write_file_atomically(scratch.path / "synced.txt", "replaced\n", ffp::Durability::synced);
  CHECK(read_text(scratch.path / "synced.txt") == "replaced\n");
  CHECK(entries_in(scratch.path) == 2);
}

TEST_CASE("a write into a missing folder names the file and the cause", "[output][write]") {
  Scratch scratch("ffp-checked-write");
  const fs::path file = scratch.path / "no_such_folder" / "summary.json";
  try {
    ffp::write_file_atomically(file, "{}");
    FAIL("the write did not fail");
  } catch (const ffp::WriteFailure& e) {
    CHECK(e.file() == file);
    CHECK(e.cause() == "no such file or directory");
  }
}

TEST_CASE("on a full disk a write fails with 'no space left on device' and leaves neither file nor temporary",
          "[output][write]") {
  Scratch scratch("ffp-checked-write");
  SmallTmpfs disk(scratch.path / "disk", "16k");  // four pages
  if (!disk.mounted()) {
    WARN(disk.why_not());
    return;
  }
  ffp::write_file_atomically(disk.path() / "small.txt", "fits\n", ffp::Durability::synced);
  const std::string too_large(64 * 1024, 'x');
  for (const auto durability : {ffp::Durability::cached, ffp::Durability::synced}) {
    try {
      ffp::write_file_atomically(disk.path() / "large.txt", too_large, durability);
      FAIL("the write did not fail");
    } catch (const ffp::WriteFailure& e) {
      CHECK(e.file() == disk.path() / "large.txt");
      CHECK(e.cause() == "no space left on device");
    }
    CHECK(entries_in(disk.path()) == 1);  // small.txt only
  }
  CHECK(read_text(disk.path() / "small.txt") == "fits\n");
}

TEST_CASE("standard output that cannot be written fails with its cause", "[output][write]") {
  std::string message = "(it did not fail)";  // checked once standard output is back
  with_standard_output_to("/dev/full", [&] {
    try {
      ffp::write_standard_output("a result\n");
    } catch (const ffp::WriteFailure& e) {
      message = e.what();
    }
  });
  CHECK(message == "cannot write to standard output: no space left on device");
  Scratch scratch("ffp-checked-write");
  const fs::path file = scratch.write("stdout.txt", "");
  with_standard_output_to(file.c_str(), [] { ffp::write_standard_output("a result\n"); });
  CHECK(read_text(file) == "a result\n");
}

TEST_CASE("a copied file has the source's bytes, and an unreadable source is named", "[output][write]") {
  Scratch scratch("ffp-checked-write");
  const std::string bytes("\x89PNG\r\n\x1a\n\0\0 binary", 18);
  const fs::path source = scratch.write("figure.png", bytes);
  ffp::copy_file_atomically(source, scratch.path / "copy.png");
  CHECK(read_text(scratch.path / "copy.png") == bytes);
  CHECK_THROWS_WITH(ffp::copy_file_atomically(scratch.path / "missing.png", scratch.path / "copy.png"),
                    "cannot read '" + (scratch.path / "missing.png").string() + "'");
  CHECK(read_text(scratch.path / "copy.png") == bytes);  // the earlier copy stays
}
