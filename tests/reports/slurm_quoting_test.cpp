// Paths written into the scripts ffp hands to bash and sbatch are read back exactly.
#include <string>

#include <catch2/catch.hpp>

#include "drivers/scene/scene_error.hpp"
#include "reports/slurm_jobs.hpp"
#include "reports/subprocess.hpp"

namespace {
const std::string kAwkward = "/runs/O'Brien drops, \"2024\" #1 $HOME `date` 50% \\ x";
}

TEST_CASE("a shell-quoted word is read back by bash exactly", "[reports][slurm]") {
  const ffp::ProgramOutput echoed = ffp::run_program({"bash", "-c", "printf '%s' " + ffp::shell_quoted(kAwkward)});
  CHECK(echoed.status == 0);
  CHECK(echoed.out == kAwkward);
}

TEST_CASE("an #SBATCH value keeps quotes, '#', '$' and backslashes, and a line break is refused", "[reports][slurm]") {
  CHECK(ffp::sbatch_quoted(kAwkward) == "\"/runs/O'Brien drops, \\\"2024\\\" #1 $HOME `date` 50% \\\\ x\"");
  CHECK_THROWS_AS(ffp::sbatch_quoted("/runs/two\nlines"), ffp::SceneError);
}

TEST_CASE("Slurm's output pattern is used only where the folder's path cannot be read as pattern syntax",
          "[reports][slurm]") {
  CHECK(ffp::sbatch_folder_lines("/runs/O'Brien drops", "logs/slurm-%A_%a.out") ==
        "#SBATCH --chdir=\"/runs/O'Brien drops\"\n#SBATCH --output=logs/slurm-%A_%a.out\n");
  CHECK(ffp::sbatch_folder_lines("/runs/50%", "logs/slurm-%A_%a.out") ==
        "#SBATCH --chdir=\"/runs/50%\"\n#SBATCH --output=/dev/null\n");
  CHECK(ffp::sbatch_folder_lines("/runs/a\\b", "task-%a.out") ==
        "#SBATCH --chdir=\"/runs/a\\\\b\"\n#SBATCH --output=/dev/null\n");
}
