#pragma once
/// Reading the `triaxial` scene kind: the drained triaxial element test on the
/// paper's weightless specimen (drivers/triaxial_test.hpp; triaxial_job.cpp runs it).
///
/// Scene (geotechnical units, compression positive):
///   material             see drivers/scene/material_scene.hpp (no density: weightless)
///   cell_pressure_kPa    σ3 (default 1.72, the paper's)
///   axial_strain_max     default 0.2
///   increments           equal axial-strain increments (default 2000)
///   strain_rate_per_s    only the rate law sees it (default 1e-4, quasi-static)
///   specimen             {height_m: 0.15, diameter_m: 0.07}
///   newton               {max_iterations, relative_tolerance}
///   output_every_increments  rows of history.csv (the work integral uses every increment)
#include <string>

#include "drivers/scene/material_scene.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "drivers/triaxial_test.hpp"

namespace ffp {

struct TriaxialScene {
  std::string name;
  MaterialSpec material;
  TriaxialTestConfig config;  ///< SI: what run_triaxial_test takes
  long output_every = 1;      ///< every n-th increment is a row of history.csv (the last one always)
};

/// Reads every key after kind and finish()es the scene. SceneError on bad input.
TriaxialScene read_triaxial_scene(SceneReader& scene);

}  // namespace ffp
