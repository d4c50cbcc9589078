/// Cost before commitment: `ffp check` says how long an MPM run will take on
/// this machine, and `ffp run` refuses one estimated above a day unless the user
/// asks for it (--allow-long), before anything is written.
#include <catch2/catch.hpp>

#include <algorithm>

#include "cli_harness.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
namespace fs = std::filesystem;

namespace {

/// The reference drop at 5 mm cells to end_time_s = 1e4 s: about 3e8 steps × 24300 particles,
/// two days and more even at the kernel's fastest rate measured here (35 M particle-steps/s, two
/// threads, an idle machine: docs/kernel-speed.md), which leaves out contact and output.
const std::vector<std::string> kDaysLong = {FFP_SOURCE_DIR "/data/scenes/ffp_reference.json",
                                            "--set",
                                            "mesh.min_cell_m=0.005",
                                            "--set",
                                            "end_time_s=1e4",
                                            "--set",
                                            "output.history_interval_s=1"};

std::vector<std::string> command(const std::string& name, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {name};
  args.insert(args.end(), kDaysLong.begin(), kDaysLong.end());
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

}  // namespace

TEST_CASE("ffp check prints an MPM run's estimated wall time beside its step count", "[cli][cost]") {
  Scratch scratch;
  const auto r = run_ffp({"check", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto line = r.out.find("cost: about ");
  REQUIRE(line != std::string::npos);
  const std::string cost = r.out.substr(line, r.out.find('\n', line) - line);
  INFO(cost);
  CHECK_THAT(cost, Catch::Contains("steps to end_time_s × 6086 particles × ") &&
                       Catch::Contains("µs per particle-step") && Catch::Contains("estimated wall time "));
  // An inverse fit says it per model run and for the fit's most runs.
  const auto inverse = run_ffp({"check", FFP_SOURCE_DIR "/data/scenes/inverse_reference.json"}, scratch.path());
  INFO(inverse.err);
  REQUIRE(inverse.exit_code == 0);
  CHECK_THAT(inverse.out, Catch::Contains("per model run; at most about 48 runs"));
}

TEST_CASE("a run estimated above a day is refused before it starts, unless --allow-long", "[cli][cost]") {
  Scratch scratch;
  const auto check = run_ffp(command("check"), scratch.path());
  REQUIRE(check.exit_code == 0);
  CHECK_THAT(check.out, Catch::Contains("days"));

  const auto refused = run_ffp(command("run", {"--out", "long"}), scratch.path());
  CHECK(refused.exit_code == 2);
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK_THAT(refused.err, Catch::StartsWith("error: end_time_s: ") && Catch::Contains("estimated wall time ") &&
                              Catch::Contains("days") && Catch::Contains("--allow-long"));
  CHECK(scratch.entries().empty());
  // --allow-long lets it start (tests/cli/interrupt_test.cpp stops such a run with Ctrl-C).
}
