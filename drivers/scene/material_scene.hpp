#pragma once
/// The `material` object of a scene, read into one of the laws' parameter sets.
///
/// Keys (geotechnical units): model ∈ {linear_elastic, mohr_coulomb, ssmc},
/// E_kPa, nu, density_kg_m3 (only where the kind has inertia or gravity),
/// phi_peak_deg, psi_peak_deg, c_peak_kPa (MC and SSMC), and for SSMC
/// phi_residual_deg, psi_residual_deg, c_residual_kPa, eta, relative_density
/// (Bolton transient dilatancy instead of psi_peak_deg) and an optional
/// rate_dependence {alpha_phi, reference_strain_rate_per_s, smoothing_increments}.
/// Each model accepts only its own keys.
#include <optional>
#include <string>
#include <variant>

#include "drivers/scene/scene_reader.hpp"
#include "models/elastic.hpp"
#include "models/material_law.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"
#include "models/math_constants.hpp"  // kDegree: scenes give angles in degrees

namespace ffp {


struct MaterialSpec {
  std::string model;  ///< linear_elastic | mohr_coulomb | ssmc
  MaterialParameters parameters;
  std::optional<double> density_kg_m3;  ///< present only when the kind asked for it

  const ElasticConstants& elastic() const;
  MaterialLaw law() const { return make_law(parameters); }
  double at_rest_k0() const { return ffp::at_rest_k0(parameters); }
};

enum class DensityRule { not_used, required };

/// Reads and validates a material object (reader positioned on it); finish()es it.
MaterialSpec read_material(SceneReader& material, DensityRule density);

}  // namespace ffp
