#pragma once
/// Handing work to Slurm: submit a batch script with sbatch, and wait for the
/// job (an array included) to leave the queue, polling squeue. Used by
/// `ffp sweep --scheduler slurm` and `ffp report --scheduler slurm`.
#include <filesystem>
#include <functional>
#include <string>

namespace ffp {

/// sbatch --parsable FILE; the job id. std::runtime_error with sbatch's words when it fails.
std::string slurm_submit(const std::filesystem::path& sbatch_file);

/// Returns once job `id` is no longer in squeue; calls `poll` every couple of seconds
/// (progress lines, and a chance to throw on an interrupt).
void slurm_wait(const std::string& id, const std::function<void()>& poll);

/// scancel ID, then returns once the job has left the queue: Slurm sends its tasks SIGTERM (an ffp run
/// then removes its temporary folder) and, after the cluster's KillWait, SIGKILL.
void slurm_cancel(const std::string& id);

/// A value for an `#SBATCH --option=VALUE` line that sbatch reads back exactly: in
/// double quotes, with `"` and `\` escaped by a backslash (checked against sbatch
/// 22.05: spaces, quotes, '#', ',', '$', '%' and backslashes all survive). Throws
/// SceneError for a line break, which no `#SBATCH` line can hold.
std::string sbatch_quoted(const std::string& value);

/// The `#SBATCH` lines that run a job in `folder` and send its Slurm output to
/// `output_pattern` (e.g. "logs/slurm-%A_%a.out") inside it. slurmd joins the folder
/// and the pattern before it expands '%' symbols, and a '\' anywhere turns the
/// expansion off: for a folder whose path holds either, Slurm's own output goes to
/// /dev/null instead of a wrong file (the scripts keep their logs themselves).
std::string sbatch_folder_lines(const std::filesystem::path& folder, const std::string& output_pattern);

/// A word for a shell script ffp writes (a sweep's run_case.sh, a report's commands.txt):
/// in single quotes, each ' written as '\'' (close, an escaped quote, reopen), so that
/// bash reads back exactly `word`. sbatch and squeue themselves run without a shell.
std::string shell_quoted(const std::string& word);

}  // namespace ffp
