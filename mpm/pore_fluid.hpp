#pragma once
/// What a saturated (two-phase) body is made of, beside its solid: the pore fluid
/// that fills it, the body's porosity and permeability, and which grid sides let the
/// fluid through. The single-point, two-velocity formulation (Jassim, Stolle & Vermeer
/// 2013) that uses them is in mpm/two_phase.hpp and docs/theory.md#saturated.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "models/consolidation_solutions.hpp"  // kConductivityGravity_m_s2

namespace ffp::mpm {

/// The pore fluid (water by default), one for the whole model.
struct PoreFluid {
  double bulk_modulus_Pa = 2.2e9;  ///< K_w of water at 20 °C
  double density_kg_m3 = 1000.0;   ///< ρ_w
  /// The absolute pressure of the atmosphere above the water table and the fluid's
  /// vapour pressure (water at 20 °C: 2.34 kPa). Pore pressures are gauge, relative to
  /// the atmosphere; the fluid cavitates when its absolute pressure falls to the vapour
  /// pressure, so the gauge pressure stays ≥ −(p_atm − p_vap) = −98.99 kPa.
  double atmospheric_Pa = 101325.0;
  double vapour_Pa = 2339.0;
  /// The lowest gauge pore pressure (Pa, compression positive): cavitation.
  double cavitation_floor_Pa() const { return -(atmospheric_Pa - vapour_Pa); }
};

/// How the permeability follows the porosity.
enum class PermeabilityLaw : std::uint8_t {
  constant,       ///< k stays the initial value
  kozeny_carman,  ///< k = k_0 · [n³/(1 − n)²] / [n_0³/(1 − n_0)²] (Carman 1937)
};
using PermeabilityLawName = std::pair<PermeabilityLaw, std::string_view>;
/// The scene's names of PermeabilityLaw, in the order messages list them.
inline constexpr auto kPermeabilityLawNames = std::to_array<PermeabilityLawName>(
    {{PermeabilityLaw::constant, "constant"}, {PermeabilityLaw::kozeny_carman, "kozeny_carman"}});
inline std::string to_string(PermeabilityLaw law) {
  return std::string(std::ranges::find(kPermeabilityLawNames, law, &PermeabilityLawName::first)->second);
}

/// A body's pores, full of the model's PoreFluid. The body's density_kg_m3 is then its
/// dry density ρ_d = (1 − n) ρ_s, the grains' mass per unit volume of the mixture (the
/// particle's mass is its solid's); its saturated density is ρ_sat = ρ_d + n ρ_w.
struct SaturatedSoil {
  double porosity = 0.4;           ///< n_0, the initial porosity
  double permeability_m_s = 1e-4;  ///< k_0, the hydraulic conductivity at n_0
  PermeabilityLaw permeability_law = PermeabilityLaw::constant;
  /// p_e at t = 0 over the hydrostatic pressure (Pa), e.g. a consolidation problem's p_0 with
  /// the skeleton unloaded; 0: the body starts hydrostatic.
  double initial_excess_pressure_Pa = 0.0;
};

/// Whether the pore fluid may cross a grid side.
enum class Drainage : std::uint8_t {
  impermeable,  ///< the fluid's normal velocity is zero there (the side must hold the solid's normal velocity)
  drained,      ///< no liquid velocity is fixed; the fluid pressure on the side is hydrostatic (no excess)
};
using DrainageName = std::pair<Drainage, std::string_view>;
/// The scene's names of Drainage, in the order messages list them.
inline constexpr auto kDrainageNames =
    std::to_array<DrainageName>({{Drainage::impermeable, "impermeable"}, {Drainage::drained, "drained"}});
inline std::string to_string(Drainage d) {
  return std::string(std::ranges::find(kDrainageNames, d, &DrainageName::first)->second);
}

/// The drainage of the four grid sides. The symmetry axis lets nothing through (v_r = 0
/// for the fluid as for the solid), whatever `inner` says. The free surface of a body
/// inside the grid is always drained: no fluid traction acts there (p = 0, the water
/// table at the surface).
struct DrainageConditions {
  Drainage inner = Drainage::impermeable;
  Drainage outer = Drainage::impermeable;
  Drainage bottom = Drainage::impermeable;
  Drainage top = Drainage::drained;
};

}  // namespace ffp::mpm
