#pragma once
/// Whole-body figures of a simulation (full 2π body, not per radian), summed
/// in particle order so that they are reproducible bit for bit.
#include <vector>

#include "models/math_constants.hpp"
#include "mpm/simulation.hpp"

namespace ffp::mpm {

struct Diagnostics {
  double mass_kg = 0.0;
  double momentum_z_N_s = 0.0;    ///< Σ m v_z (the radial sum cancels over a ring)
  double kinetic_energy_J = 0.0;  ///< Σ ½ m |v|²
  double strain_energy_J = 0.0;   ///< Σ V w(σ), w = s:s/(4G) + (tr σ)²/(18K): recoverable elastic energy
  double gravity_energy_J = 0.0;  ///< Σ m g z (zero without gravity)
  double mass_z_kg_m = 0.0;       ///< Σ m z (centre of mass = mass_z / mass)
  double total_energy_J() const { return kinetic_energy_J + strain_energy_J + gravity_energy_J; }
  double max_speed_m_s = 0.0;
};

Diagnostics measure(const Simulation& simulation);
/// The same, for one body's particles.
Diagnostics measure_body(const Simulation& simulation, std::size_t body);
/// measure_body(...).kinetic_energy_J bit for bit (the same sum in the same order), without
/// the other figures: the FFP history takes it at every row, and the elastic energy's law
/// lookup per particle were most of its cost.
double kinetic_energy_body(const Simulation& simulation, std::size_t body);

/// Σ over the given nodes of a field's vertical internal force, full 2π (N):
/// the soil reaction the rigid-body stage (paper eq. 1) sums over contact nodes.
double vertical_internal_force_N(const NodalField& field, const std::vector<std::size_t>& nodes);

}  // namespace ffp::mpm
