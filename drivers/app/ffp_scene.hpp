#pragma once
/// Reading the `ffp` and `cpt` scene kinds (shared keys) into the FFP model
/// description (mpm/ffp_model.hpp) and the run's output settings. The keys are
/// listed in ffp_job.cpp (ffp) and cpt_job.cpp (cpt).
#include <memory>
#include <string>
#include <vector>

#include "drivers/app/job.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "mpm/ffp_model.hpp"

namespace ffp {

enum class PenetrometerKind { ffp, cpt };

struct FfpOutput {
  double history_interval_s = 2e-4;
  std::vector<double> field_times_s;  ///< particle fields (VTU + strain PNG) at the first step reaching each
  double strain_colour_max = 0.5;     ///< top of the deviatoric-strain colour scale in the PNGs
};

struct FfpScene {
  PenetrometerKind kind = PenetrometerKind::ffp;
  mpm::FfpDescription model;
  double end_time_s = 0.0;
  FfpOutput output;
};

/// Reads every key after kind/name and finish()es the scene. SceneError on bad input.
FfpScene read_ffp_scene(SceneReader& scene, PenetrometerKind kind);

/// The job that runs an FFP or CPT scene (ffp_job.cpp). SceneError when the model cannot be built.
std::unique_ptr<Job> make_penetrometer_job(FfpScene scene, std::string name);

}  // namespace ffp
