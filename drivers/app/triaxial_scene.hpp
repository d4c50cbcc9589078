#pragma once
/// Reading the `triaxial` scene kind: the drained triaxial element test on the
/// paper's weightless specimen (drivers/triaxial_test.hpp; triaxial_job.cpp runs it).
///
/// Its keys, each declared where triaxial_scene.cpp reads it: `ffp keys triaxial`
/// (docs/reference/scenes.md).
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
