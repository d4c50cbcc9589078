#pragma once
/// The `material` object of a scene, read into one of the laws' parameter sets.
///
/// Each model accepts only its own keys, and each key is declared where it is
/// read (`ffp keys KIND` lists them under `material`). Geotechnical units:
/// kPa and degrees.
///
/// This file and models/ are the only places that know which laws there are:
/// the scene keys of each law's parameters and of its state (a point scene's
/// initial_state), and the scene units of what a law reports of its state.
#include <optional>
#include <string>
#include <variant>

#include "drivers/scene/scene_reader.hpp"
#include "models/elastic.hpp"
#include "models/material_law.hpp"
#include "models/math_constants.hpp"
#include "models/micropolar.hpp"  // kDegree: scenes give angles in degrees
#include "models/state_output.hpp"

namespace ffp {

struct MaterialSpec {
  std::string model;  ///< linear_elastic | mohr_coulomb | ssmc
  MaterialParameters parameters;
  std::optional<double> density_kg_m3;             ///< present only when the kind asked for it
  std::optional<MicropolarParameters> micropolar;  ///< the micropolar option (MPM kinds only)

  const ElasticConstants& elastic() const { return elastic_constants(parameters); }
  MaterialLaw law() const { return make_law(parameters); }
  double at_rest_k0() const { return ffp::at_rest_k0(parameters); }
  double peak_cohesion_Pa() const { return ffp::peak_cohesion_Pa(parameters); }
};

/// MaterialSpec::at_rest_k0 in words, for the scene reference.
inline constexpr std::string_view kAtRestK0Words = "Jaky's 1 − sin φ'_p (linear_elastic: ν/(1 − ν))";

enum class DensityRule { not_used, required };
/// The micropolar option needs a continuum with gradients: the MPM kinds take it, the
/// material-point kinds refuse it.
enum class MicropolarRule { refused, allowed };

/// Reads and validates a material object (reader positioned on it); finish()es it.
MaterialSpec read_material(SceneReader& material, DensityRule density,
                           MicropolarRule micropolar = MicropolarRule::refused);

/// The material as scene keys again (for the reproducer of a failed step).
json material_json(const MaterialSpec& spec);

/// The scene's optional `initial_state` object (reader positioned on the scene
/// that holds it): the internal variables of the law's state, each defaulting
/// to the virgin state's; absent, the virgin state. A law without internal
/// variables refuses the key.
MaterialState read_initial_state(SceneReader& scene, const MaterialLaw& law);
/// A state as the keys of `initial_state` again; null for a law without internal variables.
json initial_state_json(const MaterialState& state);

/// A law's state output as drivers print it: the column name with its unit
/// ("friction_angle_deg", "strain_rate_per_s") and the value in that unit.
std::string output_column(StateOutput output);
double output_value(StateOutput output, double value_in_si_units);

}  // namespace ffp
