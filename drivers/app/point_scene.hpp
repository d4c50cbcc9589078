#pragma once
/// Reading the `point` scene kind: one material point along a stress/strain
/// path (point_job.cpp runs it).
///
/// Its keys, each declared where point_scene.cpp reads it: `ffp keys point`
/// (docs/reference/scenes.md). Stresses in kPa and strains are compression positive.
/// Axial is component 22 (z in axisymmetry); shear strains are tensor
/// components ε_ij except simple_shear's shear_strain_max (engineering γ).
#include <array>
#include <filesystem>
#include <string>

#include "drivers/point_integrator.hpp"
#include "drivers/scene/material_scene.hpp"
#include "drivers/scene/scene_reader.hpp"

namespace ffp {

/// Voigt component names in the scenes' order (11, 22, 33, 12, 23, 13).
inline constexpr std::array<const char*, 6> kPointComponents = {"11", "22", "33", "12", "23", "13"};

struct PointScene {
  std::string name;
  MaterialSpec material;
  PointConfig config;  ///< SI, tension positive: what integrate_point takes
  std::string
      path_type;  ///< isotropic | oedometric | triaxial_compression | triaxial_extension | simple_shear | general
};

/// The `newton` object of the element kinds (point, triaxial): {max_iterations, relative_tolerance}.
NewtonSettings read_newton_settings(SceneReader& scene);

/// Reads every key after kind and finish()es the scene; relative table_csv
/// paths start at `scene_dir`. SceneError on bad input.
PointScene read_point_scene(SceneReader& scene, const std::filesystem::path& scene_dir);

}  // namespace ffp
