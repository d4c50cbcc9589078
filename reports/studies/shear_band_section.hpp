#pragma once
/// The sheared hollow cylinder (verification/shear_band_cylinder.hpp), classical and
/// micropolar, run in the report's own process at a few cell sizes: the shear band's width at
/// each level, the plastic shear strain across the annulus and the wall's force against its
/// travel. Its kinematics (every node column moving as one) is a stage of its own, not a scene.
#include "reports/study.hpp"

namespace ffp {

/// What the section measured that the drop's text uses.
struct ShearBandFindings {
  double micropolar_width_per_length = 0.0;  ///< the finest level's band / ℓ (0 if not run)
  double wall_s = 0.0;                       ///< the cylinder runs' wall time
};

/// Runs the cylinder's levels and writes their table, figures and text into `out`.
ShearBandFindings write_shear_band_section(StudyOutput& out);

}  // namespace ffp
