#include "mpm/two_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ffp::mpm {

namespace {

/// Carman (1937): k ∝ n³/(1 − n)² at a fixed grain size.
double kozeny_carman_factor(double n) { return n * n * n / ((1.0 - n) * (1.0 - n)); }

PoreSpace pore_space(const BodyDescription& d) {
  PoreSpace out;
  if (!d.saturated) return out;
  const SaturatedSoil& soil = *d.saturated;
  if (!(soil.porosity > 0.0 && soil.porosity < 1.0))
    throw std::invalid_argument("body " + d.name + ": the porosity must be in (0, 1)");
  if (!(soil.permeability_m_s > 0.0)) throw std::invalid_argument("body " + d.name + ": the permeability must be > 0");
  out.saturated = true;
  out.grain_density_kg_m3 = d.density_kg_m3 / (1.0 - soil.porosity);
  out.initial_porosity = soil.porosity;
  out.initial_permeability_m_s = soil.permeability_m_s;
  out.permeability_law = soil.permeability_law;
  return out;
}

/// Impermeable sides hold the liquid's normal velocity; the solid's must be held there too
/// (a wall the fluid cannot cross but the grains may leave is no boundary of the mixture).
std::vector<NodeConstraint> liquid_constraints(const ModelDescription& m, int nr, int nz, bool axis) {
  const DrainageConditions& d = m.drainage;
  const std::array<std::pair<Drainage, Fixity>, 4> sides = {{{d.inner, m.boundaries.inner},
                                                             {d.outer, m.boundaries.outer},
                                                             {d.bottom, m.boundaries.bottom},
                                                             {d.top, m.boundaries.top}}};
  const std::array<const char*, 4> names = {"inner", "outer", "bottom", "top"};
  BoundaryConditions liquid{Fixity::free, Fixity::free, Fixity::free, Fixity::free};
  std::array<Fixity*, 4> target = {&liquid.inner, &liquid.outer, &liquid.bottom, &liquid.top};
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const auto [drainage, solid] = sides[k];
    if (solid == Fixity::absorbing)
      throw std::invalid_argument(std::string("the ") + names[k] +
                                  " side is absorbing: a saturated body takes no absorbing sides");
    if (k == 0 && axis) continue;  // the axis: v_r = 0 for both phases (constrained_nodes)
    if (drainage != Drainage::impermeable) continue;
    if (solid == Fixity::free)
      throw std::invalid_argument(std::string("the ") + names[k] +
                                  " side is impermeable but free: it must hold the solid's normal velocity too "
                                  "(roller or fixed), or be drained");
    *target[k] = Fixity::roller;
  }
  return constrained_nodes(liquid, nr, nz, axis);
}

}  // namespace

double TwoPhase::permeability(std::size_t body, double n) const {
  const PoreSpace& b = bodies[body];
  if (b.permeability_law == PermeabilityLaw::constant) return b.initial_permeability_m_s;
  return b.initial_permeability_m_s * kozeny_carman_factor(n) / kozeny_carman_factor(b.initial_porosity);
}

double TwoPhase::hydrostatic_pressure(double z_m) const {
  if (!water_table_z_m) return 0.0;
  return fluid.density_kg_m3 * gravity_m_s2 * (*water_table_z_m - z_m);
}

double geostatic_unit_weight(const BodyDescription& body, const PoreFluid& fluid, double gravity_m_s2) {
  if (!body.saturated) return body.density_kg_m3 * gravity_m_s2;
  return (body.density_kg_m3 - (1.0 - body.saturated->porosity) * fluid.density_kg_m3) * gravity_m_s2;
}

TwoPhase make_two_phase(const ModelDescription& model, const Grid& grid, const Particles& particles) {
  TwoPhase t;
  t.fluid = model.fluid;
  if (!(t.fluid.bulk_modulus_Pa > 0.0 && t.fluid.density_kg_m3 > 0.0))
    throw std::invalid_argument("the pore fluid's bulk modulus and density must be > 0");
  t.gravity_m_s2 = model.gravity_m_s2.value_or(0.0);
  for (const BodyDescription& d : model.bodies) {
    t.bodies.push_back(pore_space(d));
    // One water table for the model: the first saturated body's K0 surface.
    if (d.saturated && d.initial_stress && model.gravity_m_s2 && !t.water_table_z_m)
      t.water_table_z_m = d.initial_stress->surface_z_m;
  }
  if (model.water_table_z_m && t.water_table_z_m) t.water_table_z_m = model.water_table_z_m;
  const std::size_t n = particles.size();
  t.porosity.assign(n, 0.0);
  t.liquid_vr.assign(n, 0.0);
  t.liquid_vz.assign(n, 0.0);
  t.pore_pressure.assign(n, 0.0);
  t.liquid_pressure.assign(n, 0.0);
  t.liquid_strain.assign(n, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t b = particles.body[p];
    if (!t.bodies[b].saturated) continue;
    t.porosity[p] = t.bodies[b].initial_porosity;
    t.liquid_vr[p] = model.bodies[b].initial_velocity_r_m_s;
    t.liquid_vz[p] = model.bodies[b].initial_velocity_z_m_s;
    t.set_pore_pressure(p,
                        t.hydrostatic_pressure(particles.z[p]) + model.bodies[b].saturated->initial_excess_pressure_Pa);
  }
  t.liquid.resize(grid.nodes());
  t.porous_mass.assign(grid.nodes(), 0.0);
  t.drag.assign(grid.nodes(), 0.0);
  t.liquid_constraints = liquid_constraints(model, grid.r.nodes(), grid.z.nodes(), grid.has_axis());
  return t;
}

double mieremet_time_step(const TwoPhaseWave& w, double L) {
  const double n = w.porosity, rho_s = w.grain_density_kg_m3, rho_w = w.fluid_density_kg_m3;
  const double E = w.constrained_modulus_Pa, K = w.fluid_bulk_modulus_Pa;
  const double rho = (1.0 - n) * rho_s + n * rho_w;  // saturated density
  const double a = n * rho * kConductivityGravity_m_s2 / ((1.0 - n) * rho_s * w.permeability_m_s);
  const double b =
      4.0 * (n * rho * K + (1.0 - 2.0 * n) * rho_w * K + n * rho_w * E) / (n * (1.0 - n) * rho_s * rho_w * L * L);
  const double c = 16.0 * E * K / ((1.0 - n) * rho_s * rho_w * L * L * L * L);
  // b² − 4c ≥ 0 always (the eigenvalues of M⁻¹K are real and positive); clamp round-off.
  const double B = b + std::sqrt(std::max(0.0, b * b - 4.0 * c));
  return 8.0 / (2.0 * a + std::sqrt(4.0 * a * a + 8.0 * B));
}

TwoPhaseStepBounds two_phase_step_bounds(const TwoPhaseWave& w, double L) {
  const double n = w.porosity, rho_w = w.fluid_density_kg_m3;
  const double rho = (1.0 - n) * w.grain_density_kg_m3 + n * rho_w;  // saturated density
  const double c_1 = std::sqrt((w.constrained_modulus_Pa + w.fluid_bulk_modulus_Pa / n) / rho);
  const double rho_tilde = rho + (1.0 / n - 2.0) * rho_w;
  return {L / c_1, 2.0 * rho_tilde * w.permeability_m_s / (rho_w * kConductivityGravity_m_s2)};
}

}  // namespace ffp::mpm
