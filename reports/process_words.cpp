#include "reports/process_words.hpp"

#include <algorithm>
#include <regex>

namespace ffp {

namespace {

// One alternative per kind of reference, each on its line below:
// - "issue" or "issues" and a number (with or without #); the possessive of "issue"; "issue:"
//   as a parenthesised label; what it asked or said;
// - "stop" with a whole number (followed by a decimal it is a time), or hyphenated before a number;
// - a review's lettered finding; a build named by the number it preceded; whose issue it is;
// - a numbered session, or one pointed at ("this", "several", ...); an hour named by the
//   host's load.
// \b keeps words that merely end in one of them out ("tissue", "nonstop").
const std::regex& process_words_pattern() {
  static const std::regex pattern(
      R"(\bissues? #?[0-9]+|\bissue(?:'|’)s\b|\((?:issue):)"
      R"(|\bthe issue (?:asks|asked|says|said|wants|wanted|requires|required|lists|states)\b)"
      R"(|\bstops? [0-9]+\b(?![.,][0-9])|\bstop-[0-9]+)"
      R"(|\breview F[0-9]+|\bbefore-[0-9]+\b|\bthe owner\b)"
      R"(|\bsessions? [0-9]+|\b(?:this|that|the|a|one|several|earlier|previous|next|last|each|every) sessions?\b)"
      R"(|\b(?:quiet|quieter|quietest|slow|slower|busy|busier|noisy|noisier|fast|faster) hours?\b)",
      std::regex::ECMAScript | std::regex::icase | std::regex::optimize);
  return pattern;
}

}  // namespace

std::vector<ProcessWord> find_process_words(std::string_view text) {
  std::vector<ProcessWord> found;
  std::size_t line = 1, start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view row = text.substr(start, end - start);
    for (std::cregex_iterator m(row.data(), row.data() + row.size(), process_words_pattern()), last; m != last; ++m)
      found.push_back({line, m->str()});
    if (end == text.size()) break;
    start = end + 1;
    ++line;
  }
  return found;
}

}  // namespace ffp
