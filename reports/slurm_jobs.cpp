#include "reports/slurm_jobs.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include "drivers/scene/scene_error.hpp"
#include "reports/subprocess.hpp"

namespace ffp {

std::string shell_quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string sbatch_quoted(const std::string& value) {
  if (value.find_first_of("\n\r") != std::string::npos)
    throw SceneError("'" + value + "': a path with a line break cannot be handed to Slurm (#SBATCH lines)");
  std::string out = "\"";
  for (char c : value) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string sbatch_folder_lines(const std::filesystem::path& folder, const std::string& output_pattern) {
  const std::string path = folder.string();
  const bool pattern_safe = path.find_first_of("%\\") == std::string::npos;
  return "#SBATCH --chdir=" + sbatch_quoted(path) +
         "\n#SBATCH --output=" + (pattern_safe ? output_pattern : std::string("/dev/null")) + "\n";
}

std::string slurm_submit(const std::filesystem::path& sbatch_file) {
  const ProgramOutput sbatch = run_program({"sbatch", "--parsable", sbatch_file.string()});
  if (sbatch.status != 0)
    throw std::runtime_error("--scheduler slurm: sbatch failed (is this a Slurm login node?): " + sbatch.err +
                             sbatch.out);
  return sbatch.out.substr(0, sbatch.out.find_first_of(";\n"));  // "id" or "id;cluster"
}

void slurm_wait(const std::string& id, const std::function<void()>& poll) {
  while (true) {
    const ProgramOutput squeue = run_program({"squeue", "-h", "-j", id, "-o", "%i"});
    poll();
    // squeue fails for a job that has left the controller's memory: gone as well.
    if (squeue.status != 0 || squeue.out.find_first_not_of(" \n") == std::string::npos) return;
    std::this_thread::sleep_for(std::chrono::seconds(2));
  }
}

void slurm_cancel(const std::string& id) {
  run_program({"scancel", id});
  slurm_wait(id, [] {});
}

}  // namespace ffp
