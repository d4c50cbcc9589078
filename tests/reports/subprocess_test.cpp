// Another program run without a shell: arguments arrive as written, output and errors come back whole.
#include <string>

#include <catch2/catch.hpp>

#include "reports/subprocess.hpp"

TEST_CASE("an argument with quotes, spaces, $ and backslashes reaches the program unchanged", "[reports][subprocess]") {
  const std::string awkward = "O'Brien drops, \"2024\" $HOME \\n `date` ;|&";
  const ffp::ProgramOutput run = ffp::run_program({"printf", "%s", awkward});
  CHECK(run.status == 0);
  CHECK(run.out == awkward);
  CHECK(run.err.empty());
}

TEST_CASE("a program's input, output, errors and exit status all come back", "[reports][subprocess]") {
  // More than a pipe holds each way (64 kB): neither side may wait on the other.
  const std::string input(1 << 20, 'x');
  const ffp::ProgramOutput copy = ffp::run_program({"sh", "-c", "cat; echo complaint >&2; exit 3"}, input);
  CHECK(copy.status == 3);
  CHECK(copy.out == input);
  CHECK(copy.err == "complaint\n");
  const ffp::ProgramOutput killed = ffp::run_program({"sh", "-c", "kill -TERM $$"});
  CHECK(killed.status == 128 + 15);
}

TEST_CASE("a program that is not installed is reported, not run", "[reports][subprocess]") {
  const ffp::ProgramOutput missing = ffp::run_program({"ffp-no-such-program"});
  CHECK(missing.status == -1);
  CHECK(missing.err == "cannot start ffp-no-such-program: no such file or directory");
}
