#pragma once
/// Runs the `ffp` binary as a user would and captures its exit code and output.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ffp::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// A fresh scratch directory per test, removed afterwards.
class Scratch {
 public:
  Scratch();
  ~Scratch();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& content) const;
  std::filesystem::path write_json(const std::string& name, const nlohmann::json& scene) const;
  /// Entries of the scratch directory (to prove nothing half-written was left).
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

/// Run `ffp ARGS...` inside `cwd`; its standard output goes to `stdout_to` when given
/// (e.g. /dev/full), else into the result. `before`: shell words put before the program, e.g.
/// "timeout 60" (a test that would otherwise hang fails with 124) or "ulimit -v 100000 &&".
CommandResult run_ffp(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                      const std::filesystem::path& stdout_to = {}, const std::string& before = "");

/// A small valid point scene (MC triaxial), for tests to break one key at a time.
nlohmann::json good_point_scene();

}  // namespace ffp::test
