#include "mpm/micropolar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mpm/simulation.hpp"
#include "mpm/stages.hpp"

namespace ffp::mpm {

namespace {

/// The friction angle the micro terms slip at: MC's φ', SSMC's residual φ'_r; an elastic law has none.
double law_friction_rad(const MaterialLaw& law) {
  if (const auto* mc = std::get_if<MohrCoulomb>(&law)) return mc->parameters().friction_angle_rad;
  if (const auto* ss = std::get_if<StrainSofteningMohrCoulomb>(&law)) return ss->parameters().friction_residual_rad;
  throw std::invalid_argument("micropolar friction_limited needs a frictional law (mc or ssmc)");
}

MicropolarGroup group_constants(const BodyDescription& body, std::size_t group) {
  const MicropolarParameters& m = *body.micropolar;
  if (!(m.length_m >= 0.0 && std::isfinite(m.length_m)))
    throw std::invalid_argument("body " + body.name + ": the micropolar length must be ≥ 0");
  if (!(m.cosserat_shear_ratio >= 0.0 && std::isfinite(m.cosserat_shear_ratio)))
    throw std::invalid_argument("body " + body.name + ": the Cosserat shear ratio must be ≥ 0");
  if (!(m.micro_inertia_m2 > 0.0 && std::isfinite(m.micro_inertia_m2)))
    throw std::invalid_argument("body " + body.name + ": the micro-inertia must be > 0");
  const double G = elastic_constants(body.law).shear_modulus();
  return {group,
          m.cosserat_shear_modulus(G),
          m.couple_modulus(G),
          m.micro_inertia_m2,
          m.length_m,
          m.friction_limited ? std::tan(law_friction_rad(body.law)) : 0.0};
}

/// The axis, and every node whose velocity is fixed in both directions (docs/theory.md#micropolar).
std::vector<std::uint32_t> rotation_fixed_nodes(const Grid& grid) {
  std::vector<std::uint32_t> fixed;
  for (const NodeConstraint& c : grid.constraints)
    if (c.bits == (constrain_r | constrain_z)) fixed.push_back(c.node);
  if (grid.has_axis())
    for (int j = 0; j < grid.z.nodes(); ++j) fixed.push_back(static_cast<std::uint32_t>(grid.node(0, j)));
  // std::unique rather than std::ranges::unique: clang 14 with libstdc++ 12 cannot form the
  // latter's subrange (the fuzz build compiles with clang).
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  return fixed;
}

}  // namespace

MicropolarFields make_micropolar_fields(const ModelDescription& model, const Simulation& s) {
  MicropolarFields f;
  f.group_of_body.assign(model.bodies.size(), -1);
  double lightest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!model.bodies[b].micropolar) continue;
    const std::size_t group = s.bodies[b].group;
    f.group_of_body[b] = static_cast<int>(f.groups.size());
    f.groups.push_back(group_constants(model.bodies[b], group));
    const MaterialGroup& g = s.groups[group];
    for (std::size_t p = g.begin; p < g.end; ++p)
      lightest = std::min(lightest, s.particles.mass[p] * f.groups.back().micro_inertia_m2);
  }
  if (!f.active()) return f;
  const std::size_t nodes = s.grid.nodes(), particles = s.particles.size();
  for (auto* a : {&f.rotational_mass, &f.angular_momentum, &f.couple_force, &f.spin, &f.spin_new})
    a->assign(nodes, 0.0);
  for (auto* a :
       {&f.rotation, &f.rotation_rate, &f.macro_rotation, &f.skew_stress, &f.couple_r, &f.couple_z, &f.couple_hoop})
    a->assign(particles, 0.0);
  f.fixed_nodes = rotation_fixed_nodes(s.grid);
  f.rotational_mass_floor = 1e-12 * lightest;  // as Simulation::mass_floor_kg: only truly empty nodes
  return f;
}

double micropolar_wave_modulus(const Simulation& s, std::size_t group) {
  for (const MicropolarGroup& g : s.micropolar.groups)
    if (g.group == group) return g.wave_modulus(s.grid.min_spacing());
  return 0.0;
}

void insert_micropolar_stages(StageList& stages, Transfer transfer) {
  stages.insert_after("compute_internal_forces", {"map_micropolar_to_grid", map_micropolar_to_grid});
  stages.insert_after("integrate_grid", {"integrate_micro_rotation", integrate_micro_rotation});
  stages.insert_after("update_particles", {"update_particle_micro_rotation", update_particle_micro_rotation});
  if (transfer != Transfer::usl)
    stages.insert_after("map_velocities_to_grid", {"map_micro_spin_to_grid", map_micro_spin_to_grid});
  stages.insert_before("update_stresses", {"update_micropolar_stresses", update_micropolar_stresses});
}

}  // namespace ffp::mpm
