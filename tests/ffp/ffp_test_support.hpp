#pragma once
/// Running the `ffp` program from the FFP tests (FFP_BINARY) and reading its
/// outputs back: the FFP's checks are stated on history.csv and summary.json,
/// what a user reads, so they are tested there.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "drivers/output/csv_writer.hpp"

namespace ffp::test {

/// A scratch directory removed at the end of the test.
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("ffp-ffp-test-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct ProgramResult {
  int exit_code = -1;
  std::string err;
  std::string out;
};

inline std::string quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// `ffp ARGS…` with stdout and stderr captured. One OpenMP thread:
/// ctest runs tests side by side, and two programs with two spinning threads
/// each on two cores wait a scheduler quantum at every barrier (measured: 60×
/// slower); the results do not depend on the thread count (mpm/parallel.hpp).
inline ProgramResult run_program(const std::vector<std::string>& args, const std::filesystem::path& scratch) {
  const std::filesystem::path err = scratch / "stderr.txt", out = scratch / "stdout.txt";
  // Appended, not "literal" + std::string&&: GCC 12 warns falsely on that (-Wstringop-overflow, GCC bug 105329).
  std::string command = "OMP_NUM_THREADS=1 ";
  command += quoted(FFP_BINARY);
  for (const std::string& a : args) (command += ' ') += quoted(a);
  ((command += " > ") += quoted(out.string())) += " 2> ";
  command += quoted(err.string());
  const int status = std::system(command.c_str());
  ProgramResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const auto slurp = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  r.err = slurp(err);
  r.out = slurp(out);
  std::filesystem::remove(out);
  return r;
}

inline std::string scene_path(const std::string& name) {
  std::string path = FFP_SOURCE_DIR;
  (path += "/data/scenes/") += name;  // appended: see run_program
  return path;
}

inline nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

/// Mean reaction over rows with penetration in [from, to]: the impulse
/// difference over the time difference (reaction_N rows are interval means).
inline double mean_reaction(const CsvData& history, double from_m, double to_m) {
  const auto& depth = history.column("penetration_m");
  const auto& time = history.column("time_s");
  const auto& impulse = history.column("impulse_N_s");
  std::size_t first = depth.size(), last = 0;
  for (std::size_t k = 0; k < depth.size(); ++k) {
    if (depth[k] < from_m || depth[k] > to_m) continue;
    first = std::min(first, k);
    last = std::max(last, k);
  }
  if (first >= last) return 0.0;
  return (impulse[last] - impulse[first]) / (time[last] - time[first]);
}

}  // namespace ffp::test
