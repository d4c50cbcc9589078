/// The product speaks only of itself: no tracked text file names the issues, stops,
/// reviews, sessions or hours of the host that its work went through
/// (reports/process_words.hpp says what is matched and why).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "reports/process_words.hpp"
#include "tests/support/scratch.hpp"
#include "tests/support/tracked_files.hpp"

namespace fs = std::filesystem;
using ffp::find_process_words;

namespace {

// The words under test are put together here, so that this file passes the scan below.
const std::string kIssue = std::string("iss") + "ue", kStop = std::string("st") + "op",
                  kReview = std::string("rev") + "iew", kSession = std::string("sess") + "ion",
                  kHour = std::string("ho") + "ur";

std::size_t matches(const std::string& text) { return find_process_words(text).size(); }

/// Text a reader meets: not a binary file, not a numeric data table (lab curves, records,
/// fuzz seeds), whose words are columns of numbers.
bool is_prose_or_code(const std::string& name, const std::string& content) {
  if (name.ends_with(".csv") || name.starts_with("fuzz/corpus/")) return false;
  return content.find('\0') == std::string::npos;
}

}  // namespace

TEST_CASE("work-process words: numbered references and the host's hours match, ordinary English does not",
          "[app][words]") {
  CHECK(matches("the bands of README's " + kIssue + " 13 notes") == 1);
  CHECK(matches(kIssue + "s 13 and 15") == 1);
  CHECK(matches("see " + kIssue + " #46") == 1);
  CHECK(matches("(" + kIssue + ": models); 1 %, as the " + kIssue + " asks") == 2);
  CHECK(matches("5 %: the " + kIssue + "'s tolerance") == 1);
  CHECK(matches("the " + kIssue + "’s measure") == 1);
  CHECK(matches("measured at " + kStop + " 43 and " + kStop + "-39") == 2);
  CHECK(matches("(" + kReview + " F2: pushed off the axis)") == 1);
  CHECK(matches("a decision for the " + std::string("own") + "er") == 1);
  CHECK(matches("a quiet " + kHour + ", then a Slower " + kHour) == 2);
  CHECK(matches("several " + kSession + "s; " + kSession + " 3") == 2);
  CHECK(matches("against the before-" + std::string("15") + " build") == 1);
  CHECK(find_process_words("line one\nline two, " + kStop + " 44\n").at(0).line == 2);

  CHECK(matches("an " + kIssue + " with the data; the " + kIssue + " here is the mesh") == 0);
  CHECK(matches("tissue 3, nonstop 4") == 0);
  CHECK(matches("the band " + kStop + "s at 0.175 m; a " + kStop + " 0.5 s later") == 0);
  CHECK(matches(kReview + " Fig. 7; the " + kReview + "er's note") == 0);
  CHECK(matches("the host moves figures from hour to hour; a 24-hour run") == 0);
  CHECK(matches("an ssh " + kSession + "; sessions of Slurm") == 0);
}

TEST_CASE("no tracked file speaks of how the work was organised", "[app][words]") {
  const fs::path root = FFP_SOURCE_DIR;
  const std::vector<std::string> files = ffp::test_support::tracked_files(root);
  if (files.empty()) {
    WARN("not a git checkout (no git ls-files at " << root.string() << "): nothing to scan");
    return;
  }
  std::ostringstream findings;
  std::size_t count = 0, scanned = 0;
  for (const std::string& name : files) {
    const std::string content = ffp::test_support::read_text(root / name);
    if (!is_prose_or_code(name, content)) continue;
    ++scanned;
    for (const auto& hit : find_process_words(content)) {
      findings << name << ":" << hit.line << ": '" << hit.words << "'\n";
      ++count;
    }
  }
  INFO(scanned << " files scanned; say the reason, a paper or a commit hash instead of:\n" << findings.str());
  CHECK(scanned > 100);
  CHECK(count == 0);
}
