#pragma once
/// `git ls-files` of the source tree, for the tests that scan what the repository tracks.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ffp::test_support {

/// The tracked files matching `pathspec` (all with an empty one), relative to `root`;
/// empty when `root` is not a git checkout.
inline std::vector<std::string> tracked_files(const std::filesystem::path& root, const std::string& pathspec = "") {
  std::vector<std::string> files;
  if (!std::filesystem::exists(root / ".git")) return files;
  std::string command = "git -C '" + root.string() + "' ls-files -z";
  if (!pathspec.empty()) command += " '" + pathspec + "'";
  command += " 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return files;
  std::string name;
  for (int c; (c = std::fgetc(pipe.get())) != EOF;) {
    if (c != '\0') {
      name.push_back(static_cast<char>(c));
    } else {
      files.push_back(name);
      name.clear();
    }
  }
  return files;
}

}  // namespace ffp::test_support
