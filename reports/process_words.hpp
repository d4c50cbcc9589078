#pragma once
/// Words that speak of how the work on ffp was organised rather than of ffp itself:
/// numbered issues and stops, review findings, what an issue or its owner asked,
/// working sessions, and the host's hours of light or heavy load. The product gives a
/// number's reason, a paper or a commit hash instead. The tracked files and the
/// generated report are both scanned for them (tests/app/process_words_test.cpp,
/// tests/reports/report_words_test.cpp).
///
/// The patterns are narrow on purpose, so that ordinary English passes: "issue" is
/// matched only with a number or as a possessive, "stop" only with a whole number,
/// "review" only with a finding's letter and number, "hour" only after an adjective of
/// the host's load (process_words.cpp lists them). "An issue with the data", "the band
/// stops at 0.175 m" and "from hour to hour" are not matched.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ffp {

/// One match: its line (1-based) and the words matched.
struct ProcessWord {
  std::size_t line = 0;
  std::string words;
};

/// Every match in `text`, in order (case-insensitive).
std::vector<ProcessWord> find_process_words(std::string_view text);

}  // namespace ffp
