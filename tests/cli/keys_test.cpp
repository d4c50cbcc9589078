/// `ffp keys`: the scene reference as the program prints it, and docs/reference/scenes.md,
/// which must be that output to the byte.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "tests/cli/cli_harness.hpp"

namespace fs = std::filesystem;
using ffp::test::run_ffp;
using ffp::test::Scratch;

TEST_CASE("docs/reference/scenes.md is the output of ffp keys --markdown", "[cli][keys]") {
  Scratch dir;
  const auto r = run_ffp({"keys", "--markdown"}, dir.path());
  REQUIRE(r.exit_code == 0);
  std::ifstream in(fs::path(FFP_SOURCE_DIR) / "docs/reference/scenes.md", std::ios::binary);
  REQUIRE(in);
  std::stringstream committed;
  committed << in.rdbuf();
  if (committed.str() == r.out) return;
  std::istringstream a(committed.str()), b(r.out);
  std::string line_a, line_b;
  int line = 0;
  while (true) {
    ++line;
    const bool more_a = static_cast<bool>(std::getline(a, line_a)), more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a || !more_b || line_a != line_b) break;
  }
  FAIL("docs/reference/scenes.md is out of date (first difference at line "
       << line << "): regenerate it with `build/release/drivers/app/ffp keys --markdown > docs/reference/scenes.md`"
       << "\ncommitted: " << line_a << "\nprogram:   " << line_b);
}

TEST_CASE("ffp keys prints one kind's keys, and refuses a kind that does not exist", "[cli][keys]") {
  Scratch dir;
  const auto ffp = run_ffp({"keys", "ffp"}, dir.path());
  REQUIRE(ffp.exit_code == 0);
  CHECK(ffp.out.rfind("ffp: ", 0) == 0);
  CHECK(ffp.out.find("  mesh.min_cell_m\n") != std::string::npos);
  CHECK(ffp.out.find("  ffp.push_velocity_m_s\n") == std::string::npos);  // a cpt key
  CHECK(ffp.out.find("`") == std::string::npos);                          // plain text for a terminal
  CHECK(ffp.err.empty());

  const auto typo = run_ffp({"keys", "fpp"}, dir.path());
  CHECK(typo.exit_code == 2);
  CHECK(typo.out.empty());
  CHECK(typo.err.find("'fpp' is not a scene kind") != std::string::npos);
}
