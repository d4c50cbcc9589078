#pragma once
/// Shared by the tests that run scenes through the ffp program: a scratch
/// folder removed afterwards, `ffp run` inside it, and reading a file whole.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace ffp::test_support {

/// A fresh folder under the system's temporary directory, removed with its contents.
struct Scratch {
  std::filesystem::path path;
  explicit Scratch(const std::string& prefix = "ffp-test") {
    std::random_device seed;
    path = std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(seed()));
    std::filesystem::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
};

/// `ffp run SCENE --out out --quiet EXTRA` inside the scratch folder (output in log.txt); the exit code.
inline int run_ffp(const Scratch& dir, const std::string& scene, const std::string& extra = "") {
  const std::string command = "cd '" + dir.path.string() + "' && '" + FFP_BINARY + "' run '" + scene +
                              "' --out out --quiet " + extra + " > log.txt 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace ffp::test_support
