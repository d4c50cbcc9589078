#pragma once
/// Reading the `point` scene kind: one material point along a stress/strain
/// path (point_job.cpp runs it).
///
/// Scene (geotechnical units: kPa, compression positive for stress and strain):
///   material            see drivers/scene/material_scene.hpp (density not used)
///   initial_stress_kPa  [σ11, σ22, σ33, σ12, σ23, σ13], or initial_pressure_kPa
///                       (default: the path's confining stress, else 0)
///   initial_state       the law's internal variables, e.g. {plastic_deviatoric_strain,
///                       strain_rate_per_s} (read_initial_state in material_scene.hpp)
///   path.type           isotropic | oedometric | triaxial_compression |
///                       triaxial_extension | simple_shear | general
///   newton              {max_iterations, relative_tolerance}
///   output_every_increments
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
