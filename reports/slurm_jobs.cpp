#include "reports/slurm_jobs.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace ffp {

namespace {

/// Runs `command` through the shell; its stdout, and its exit status in `status`.
std::string capture(const std::string& command, int& status) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    status = -1;
    return out;
  }
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
  status = ::pclose(pipe);
  return out;
}

}  // namespace

std::string shell_quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string slurm_submit(const std::filesystem::path& sbatch_file) {
  int status = 0;
  const std::string out = capture("sbatch --parsable " + shell_quoted(sbatch_file.string()) + " 2>&1", status);
  if (status != 0) throw std::runtime_error("--scheduler slurm: sbatch failed (is this a Slurm login node?): " + out);
  return out.substr(0, out.find_first_of(";\n"));  // "id" or "id;cluster"
}

void slurm_wait(const std::string& id, const std::function<void()>& poll) {
  while (true) {
    int status = 0;
    const std::string queued = capture("squeue -h -j " + shell_quoted(id) + " -o %i 2>/dev/null", status);
    poll();
    // squeue fails for a job that has left the controller's memory: gone as well.
    if (status != 0 || queued.find_first_not_of(" \n") == std::string::npos) return;
    std::this_thread::sleep_for(std::chrono::seconds(2));
  }
}

}  // namespace ffp
