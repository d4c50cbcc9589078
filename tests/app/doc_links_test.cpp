/// The manual's links hold: every relative link in a tracked Markdown file names a file
/// that exists, and a link into a Markdown file's section names an anchor it has (an
/// explicit <a id="…"></a>, or a heading's GitHub slug). The scene reference and the
/// report link into docs/theory.md and docs/verification.md by these anchors.
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "tests/support/scratch.hpp"
#include "tests/support/tracked_files.hpp"

namespace fs = std::filesystem;

namespace {

/// GitHub's anchor of a heading: lower case, spaces to hyphens, punctuation dropped
/// (letters beyond ASCII kept as they are).
std::string slug(const std::string& heading) {
  std::string out;
  for (unsigned char c : heading) {
    if (c >= 0x80 || std::isalnum(c) || c == '-' || c == '_')
      out.push_back(static_cast<char>(c < 0x80 ? std::tolower(c) : c));
    else if (c == ' ')
      out.push_back('-');
  }
  return out;
}

std::set<std::string> anchors_of(const std::string& text) {
  std::set<std::string> anchors;
  static const std::regex explicit_id(R"re(<a id="([^"]+)"></a>)re");
  for (std::sregex_iterator m(text.begin(), text.end(), explicit_id), end; m != end; ++m) anchors.insert((*m)[1]);
  std::istringstream lines(text);
  bool fenced = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("```")) fenced = !fenced;
    if (fenced || !line.starts_with("#")) continue;
    const std::size_t text_start = line.find_first_not_of('#');
    if (text_start == std::string::npos || line[text_start] != ' ') continue;
    anchors.insert(slug(line.substr(text_start + 1)));
  }
  return anchors;
}

}  // namespace

TEST_CASE("the manual's relative links name files and sections that exist", "[app][docs]") {
  const fs::path root = FFP_SOURCE_DIR;
  const std::vector<std::string> files = ffp::test_support::tracked_files(root, "*.md");
  if (files.empty()) {
    WARN("not a git checkout (no git ls-files at " << root.string() << "): nothing to check");
    return;
  }
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  std::ostringstream broken;
  std::size_t checked = 0;
  for (const std::string& name : files) {
    const fs::path file = root / name;
    const std::string text = ffp::test_support::read_text(file);
    for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
      const std::string target = (*m)[1];
      if (target.find("://") != std::string::npos || target.starts_with("mailto:")) continue;
      const std::size_t hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const fs::path resolved = path.empty() ? file : file.parent_path() / path;
      ++checked;
      if (!fs::exists(resolved)) {
        broken << name << ": " << target << " (no such file)\n";
      } else if (hash != std::string::npos && resolved.extension() == ".md") {
        const std::string anchor = target.substr(hash + 1);
        if (!anchors_of(ffp::test_support::read_text(resolved)).contains(anchor))
          broken << name << ": " << target << " (no such section)\n";
      }
    }
  }
  INFO(checked << " links checked; broken:\n" << broken.str());
  CHECK(checked > 50);
  CHECK(broken.str().empty());
}
