#pragma once
/// Reading an `mpm` verification scene into the MPM model description and the
/// run's output settings. Each key is declared where it is read: `ffp keys mpm`.
#include <string>
#include <vector>

#include "drivers/scene/scene_reader.hpp"
#include "mpm/model.hpp"

namespace ffp {

struct MpmProbe {
  std::string name;
  double r_m = 0.0, z_m = 0.0;  ///< the particle nearest to this point at the start is followed
};

struct MpmOutput {
  double history_interval_s = 0.0;
  std::vector<std::string> history;   ///< quantity columns after time_s
  std::vector<double> field_times_s;  ///< particle fields written at the first step reaching each
  std::vector<MpmProbe> probes;
};

struct MpmScene {
  mpm::ModelDescription model;
  double end_time_s = 0.0;
  MpmOutput output;
  std::vector<std::string> body_names;
};

/// Reads every key of the scene after kind/name and finish()es it. SceneError on bad input.
MpmScene read_mpm_scene(SceneReader& scene);

/// The solver keys the mpm and ffp/cpt scenes share, each read (and documented) here once.
mpm::ShapeFunction read_shape_function(SceneReader& solver);
mpm::Transfer read_transfer(SceneReader& solver, mpm::Transfer fallback);
double read_flip_fraction(SceneReader& solver);
double read_courant(SceneReader& solver);
double read_local_damping(SceneReader& solver);

/// solver.strain_smoothing (mpm and ffp/cpt scenes): a mode name (off, volumetric, full),
/// or true/false as before the modes (true: volumetric, false: off).
mpm::StrainSmoothing read_strain_smoothing(SceneReader& solver);

/// The history quantities a scene may ask for (body-wise ones are `<body>_<quantity>`).
std::vector<std::string> mpm_history_quantities(const std::vector<std::string>& body_names);

}  // namespace ffp
