#pragma once
/// Reading the `ffp` and `cpt` scene kinds (shared keys) into the FFP model
/// description (mpm/ffp_model.hpp) and the run's output settings. Each key is
/// declared where it is read: `ffp keys ffp`, `ffp keys cpt`.
#include <memory>
#include <optional>
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
  /// The soil's loss of ellipticity (mpm/localisation_map.hpp) in the history rows, the fields
  /// and the summary. Off unless asked for, so that a scene's outputs keep their columns.
  bool localisation = false;
};

/// The bearing benchmark of a flat punch on a Tresca soil (cpt, tip flat, φ' = 0, c' > 0): the
/// plateau mean pressure is the mean over a settlement window, read from the exact impulse.
struct BearingPlateau {
  double cohesion_Pa = 0.0;
  double from_ratio = 0.04, to_ratio = 0.06;  ///< settlement window / base radius
};

struct FfpScene {
  PenetrometerKind kind = PenetrometerKind::ffp;
  mpm::FfpDescription model;
  double end_time_s = 0.0;
  FfpOutput output;
  std::optional<BearingPlateau> bearing;  ///< flat-tip cpt in a cohesive soil only
};

/// Reads every key after kind/name and finish()es the scene. SceneError on bad input.
FfpScene read_ffp_scene(SceneReader& scene, PenetrometerKind kind);

/// The job that runs an FFP or CPT scene (ffp_job.cpp). SceneError when the model cannot be built.
std::unique_ptr<Job> make_penetrometer_job(FfpScene scene, std::string name);

}  // namespace ffp
