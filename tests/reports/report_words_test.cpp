/// The generated report speaks only of the product: report.md, as `ffp report` writes
/// it, holds none of the work-process words of reports/process_words.hpp. The study run
/// here is the quickest (two element-test calibrations); the text of every study is
/// also in the tracked sources, which tests/app/process_words_test.cpp scans.
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <catch2/catch.hpp>

#include "reports/process_words.hpp"
#include "tests/support/scratch.hpp"

namespace fs = std::filesystem;

TEST_CASE("the report the calibration study writes has no work-process words", "[reports][words]") {
  ffp::test_support::Scratch scratch("ffp-report-words");
  const fs::path scenes = fs::path(FFP_SOURCE_DIR) / "data" / "scenes";
  const std::string command = "cd '" + scratch.path.string() + "' && '" + FFP_BINARY + "' report --scenes '" +
                              scenes.string() +
                              "' --only 'Calibration of the softening' --cache cache --out rep --jobs 2"
                              " > log.txt 2>&1";
  const int status = std::system(command.c_str());
  INFO(ffp::test_support::read_text(scratch.path / "log.txt"));
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  const std::string report = ffp::test_support::read_text(scratch.path / "rep" / "report.md");
  REQUIRE(report.find("Calibration of the softening") != std::string::npos);
  std::ostringstream findings;
  for (const auto& hit : ffp::find_process_words(report))
    findings << "report.md:" << hit.line << ": '" << hit.words << "'\n";
  INFO(findings.str());
  CHECK(findings.str().empty());
}
