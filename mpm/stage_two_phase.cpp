/// The stages of saturated bodies (mpm/two_phase.hpp; docs/theory.md#saturated), in the
/// order of a step: the liquid's transfer, the pore pressure's force on both phases, the
/// liquid's grid update (then the solid's, by integrate_grid), the liquid's particle update
/// and remap, its strain, the storage equation, the two-phase time step. Written plainly,
/// one visit of a particle's support per transfer; every nodal sum runs in ParticleBins
/// order (deterministic) and every cell sum in particle order.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mpm/stages.hpp"
#include "mpm/support_row.hpp"

namespace ffp::mpm {

namespace {

/// fn(i, S_ip, G_ip,r, G_ip,z) over particle p's support, linear hats or GIMP.
template <class Fn>
void visit_support(const Simulation& s, std::size_t p, Fn&& fn) {
  if (s.settings.shape_function == ShapeFunction::linear) {
    for_support<2>(s.grid, s.weights[p], fn);
  } else {
    for_support<3>(s.grid, s.weights[p], fn);
  }
}

/// The velocity field of the saturated bodies' solid: one for all of them, since the liquid has one field.
NodalField& solid_field(Simulation& s) {
  const TwoPhase& t = *s.two_phase;
  std::size_t field = s.bodies.size();
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (!t.bodies[b].saturated) continue;
    if (field != s.bodies.size() && s.bodies[b].field != field)
      throw StepFailure("the saturated bodies map to different velocity fields: the pore fluid has one");
    field = s.bodies[b].field;
  }
  return s.grid.fields[field];
}

bool smoothed(const Simulation& s) { return s.settings.strain_smoothing != StrainSmoothing::off; }

/// The particle's (cell, body) slot of cell_sums.
std::size_t cell_slot(const Simulation& s, std::size_t p) { return s.cell[p] * s.bodies.size() + s.particles.body[p]; }

/// Per (cell, body) slot of the particles that take part in the cell means (as the solid's,
/// mpm/stages.hpp): Σ V_p and Σ V_p x_p, in particle order.
template <class Value>
void cell_sums(const Simulation& s, std::vector<double>& volume, std::vector<double>& sum, Value&& x) {
  const Particles& P = s.particles;
  const TwoPhase& t = *s.two_phase;
  const std::vector<double> limit = cell_mean_density_limits(s);
  volume.assign(s.grid.cells() * s.bodies.size(), 0.0);
  sum.assign(s.grid.cells() * s.bodies.size(), 0.0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!t.saturated(P, p) || !takes_part_in_cell_means(P, p, limit)) continue;
    const std::size_t k = cell_slot(s, p);
    volume[k] += P.volume[p];
    sum[k] += P.volume[p] * x(p);
  }
}

/// x_p, or its cell's mean when the cell means are on and the particle takes part.
double cell_mean_or_own(const Simulation& s, std::size_t p, const std::vector<double>& volume,
                        const std::vector<double>& sum, const std::vector<double>& limit, double own) {
  if (!smoothed(s) || !takes_part_in_cell_means(s.particles, p, limit)) return own;
  const std::size_t k = cell_slot(s, p);
  return sum[k] / volume[k];
}

double gravity_z(const Simulation& s) { return -s.gravity_m_s2.value_or(0.0); }

}  // namespace

// M_w,i = Σ_p S_ip ρ_w V_p ;  M̄_w,i = Σ_p S_ip n_p ρ_w V_p ;  p_w,i = Σ_p S_ip ρ_w V_p v_w,p ;
// Q_i = Σ_p S_ip n_p ρ_w g V_p / k_p   (the lumped drag; g the conductivity's, mpm/pore_fluid.hpp)
void map_liquid_to_grid(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  NodalField& f = t.liquid;
  f.reset();
  std::fill(t.porous_mass.begin(), t.porous_mass.end(), 0.0);
  std::fill(t.drag.begin(), t.drag.end(), 0.0);
  const Particles& P = s.particles;
  const double rho_w = t.fluid.density_kg_m3;
  s.bins.scatter([&](std::size_t p) {
    if (!t.saturated(P, p)) return;
    const double n = t.porosity[p], m_w = rho_w * P.volume[p];
    const double q = n * m_w * kConductivityGravity_m_s2 / t.permeability(P.body[p], n);
    visit_support(s, p, [&](std::size_t i, double N, double, double) {
      f.mass[i] += N * m_w;
      t.porous_mass[i] += N * n * m_w;
      f.momentum_r[i] += N * m_w * t.liquid_vr[p];
      f.momentum_z[i] += N * m_w * t.liquid_vz[p];
      t.drag[i] += N * q;
    });
  });
}

// The excess over hydrostatic p_e = p − p_h(z_p) drives both phases (mpm/two_phase.hpp); with
// strain smoothing its cell mean p̄_e,c = Σ_{p∈c} V_p p_e,p / Σ_{p∈c} V_p per cell and body stands
// in for each particle's (the pore pressure's smooth_mean_stress; its transpose is the storage
// equation's cell-mean strain, update_pore_pressure). Then
//   f_e,i = Σ_p V_p p̄_e (G_ip + S_ip/r_p e_r)     (the internal force of −p_e I, hoop term beside)
// goes to the liquid and to the solid's field (σ = σ' − p I).
void add_pore_pressure_forces(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  NodalField& solid = solid_field(s);
  const Particles& P = s.particles;
  const std::vector<double> limit = cell_mean_density_limits(s);
  const auto excess = [&](std::size_t p) { return t.excess_pressure(P, p); };
  if (smoothed(s)) cell_sums(s, t.cell_volume, t.cell_pressure, excess);
  s.bins.scatter([&](std::size_t p) {
    if (!t.saturated(P, p)) return;
    const double pressure = cell_mean_or_own(s, p, t.cell_volume, t.cell_pressure, limit, excess(p));
    const double Vp = P.volume[p] * pressure, inverse_r = s.weights[p].inverse_r;
    visit_support(s, p, [&](std::size_t i, double N, double Gr, double Gz) {
      const double fr = Vp * (Gr + N * inverse_r), fz = Vp * Gz;
      t.liquid.internal_force_r[i] += fr;
      t.liquid.internal_force_z[i] += fz;
      solid.internal_force_r[i] += fr;
      solid.internal_force_z[i] += fz;
    });
  });
}

// v_w,i^n = p_w,i/M_w,i,  v_s,i^n = p_s,i/M_s,i;
// a_w = (f_e − Q (v_w^n − v_s^n)) / M_w       (the liquid; Jassim et al. 2013, its weight balanced by p_h)
// v_w^{n+1} = v_w^n + Δt a_w;
// f_s^ext += (M̄_w − M_w) g − M̄_w a_w, so that integrate_grid's a_s = (f^int + f^ext)/M_s is the
//   mixture's a_s = (F_mix − M̄_w a_w)/M_s, F_mix = f^int(σ') + f_e + (M_s + M̄_w − M_w) g + f^ext
//   (apply_gravity gave M_s g; −M_w g is the buoyancy, the hydrostatic gradient's force).
void integrate_liquid(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  NodalField& f = t.liquid;
  NodalField& solid = solid_field(s);
  const double dt = s.dt_s, floor = s.mass_floor_kg, g_z = gravity_z(s);
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!(f.mass[i] > floor)) {
      f.velocity_r[i] = f.velocity_z[i] = f.velocity_new_r[i] = f.velocity_new_z[i] = 0.0;
      continue;
    }
    const double inverse_m = 1.0 / f.mass[i];
    const double vs_r = solid.momentum_r[i] / solid.mass[i], vs_z = solid.momentum_z[i] / solid.mass[i];
    f.velocity_r[i] = f.momentum_r[i] * inverse_m;
    f.velocity_z[i] = f.momentum_z[i] * inverse_m;
    const double a_r = (f.internal_force_r[i] - t.drag[i] * (f.velocity_r[i] - vs_r)) * inverse_m;
    const double a_z = (f.internal_force_z[i] - t.drag[i] * (f.velocity_z[i] - vs_z)) * inverse_m;
    f.velocity_new_r[i] = f.velocity_r[i] + dt * a_r;
    f.velocity_new_z[i] = f.velocity_z[i] + dt * a_z;
    solid.external_force_r[i] -= t.porous_mass[i] * a_r;
    solid.external_force_z[i] += (t.porous_mass[i] - f.mass[i]) * g_z - t.porous_mass[i] * a_z;
  }
}

// The liquid's fixities: v_w,n = 0 on impermeable sides and on the axis (mpm/two_phase.hpp).
void apply_liquid_boundary_conditions(Simulation& s) {
  NodalField& f = s.two_phase->liquid;
  for (const NodeConstraint& c : s.two_phase->liquid_constraints) {
    if (c.bits & constrain_r) f.velocity_r[c.node] = f.velocity_new_r[c.node] = 0.0;
    if (c.bits & constrain_z) f.velocity_z[c.node] = f.velocity_new_z[c.node] = 0.0;
  }
}

// v_w,p ← α (v_w,p + Σ_i S_ip (v_w,i^{n+1} − v_w,i^n)) + (1 − α) Σ_i S_ip v_w,i^{n+1}   (as the solid's)
// MUSL: p_w,i = Σ_p S_ip ρ_w V_p v_w,p^{n+1},  v_w,i = p_w,i/M_w,i, then the liquid's fixities.
void update_liquid_particles(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  NodalField& f = t.liquid;
  const Particles& P = s.particles;
  const double alpha = s.settings.flip_fraction;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!t.saturated(P, p)) continue;
    double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0;
    visit_support(s, p, [&](std::size_t i, double N, double, double) {
      vr += N * f.velocity_new_r[i];
      vz += N * f.velocity_new_z[i];
      dvr += N * (f.velocity_new_r[i] - f.velocity_r[i]);
      dvz += N * (f.velocity_new_z[i] - f.velocity_z[i]);
    });
    t.liquid_vr[p] = alpha * (t.liquid_vr[p] + dvr) + (1.0 - alpha) * vr;
    t.liquid_vz[p] = alpha * (t.liquid_vz[p] + dvz) + (1.0 - alpha) * vz;
  }
  if (s.settings.transfer == Transfer::usl) return;
  std::fill(f.momentum_r.begin(), f.momentum_r.end(), 0.0);
  std::fill(f.momentum_z.begin(), f.momentum_z.end(), 0.0);
  const double rho_w = t.fluid.density_kg_m3;
  s.bins.scatter([&](std::size_t p) {
    if (!t.saturated(P, p)) return;
    const double m_w = rho_w * P.volume[p];
    visit_support(s, p, [&](std::size_t i, double N, double, double) {
      f.momentum_r[i] += N * m_w * t.liquid_vr[p];
      f.momentum_z[i] += N * m_w * t.liquid_vz[p];
    });
  });
  for (std::size_t i = 0; i < f.size(); ++i) {
    const bool filled = f.mass[i] > s.mass_floor_kg;
    f.velocity_r[i] = filled ? f.momentum_r[i] / f.mass[i] : 0.0;
    f.velocity_z[i] = filled ? f.momentum_z[i] / f.mass[i] : 0.0;
  }
  apply_liquid_boundary_conditions(s);
}

// Δε_v,w = Δt Σ_i (v_w,r,i G_ip,r + v_w,z,i G_ip,z + v_w,r,i S_ip/r_p)   (∇·v_w with the hoop v_r/r),
// from the remapped liquid velocities (MUSL) or v_w^{n+1} (USL), as the solid's strain.
void compute_liquid_strain(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  const NodalField& f = t.liquid;
  const bool remapped = s.settings.transfer != Transfer::usl;
  const std::vector<double>& vr = remapped ? f.velocity_r : f.velocity_new_r;
  const std::vector<double>& vz = remapped ? f.velocity_z : f.velocity_new_z;
  const Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!t.saturated(P, p)) continue;
    const double inverse_r = s.weights[p].inverse_r;
    double divergence = 0.0;
    visit_support(s, p, [&](std::size_t i, double N, double Gr, double Gz) {
      divergence += vr[i] * (Gr + N * inverse_r) + vz[i] * Gz;
    });
    t.liquid_strain[p] = s.dt_s * divergence;
  }
}

// Storage (Verruijt; Anura3D's StressSolid): with strain smoothing the liquid's Δε_v,w takes its
// cell mean Σ V Δε_v,w / Σ V as the solid's Δε_v,s already has (smooth_volumetric_strain), then
//   p* ← p* − (K_w/n) [(1 − n) Δε_v,s + n Δε_v,w]   (tension-positive strains, compression-positive p)
//   p = max(p*, −(p_atm − p_vap))                   (the fluid cavitates at its vapour pressure; below
//                                                     the floor p* keeps the vapour's volume, so that
//                                                     a recompression condenses it first)
//   n ← max(1 − m_s/(ρ_s V), 0.5 n_0)                (the solid's mass is kept; grains incompressible;
//                                                     the floor: closed pores, kClosedPorosityRatio)
// With strain smoothing each particle's excess p* − p_h(z_p) then takes its cell's mean, as the
// forces already do (add_pore_pressure_forces): the particles of a cell would otherwise keep, for
// ever, whatever differences they brought into it (a pattern the grid cannot see, so no flow
// evens it out), and the pore pressure read at a particle (u1, u2, the fields) would be that
// pattern rather than what drives the water.
void update_pore_pressure(Simulation& s) {
  TwoPhase& t = *s.two_phase;
  const Particles& P = s.particles;
  const std::vector<double> limit = cell_mean_density_limits(s);
  if (smoothed(s))
    cell_sums(s, t.cell_strain_volume, t.cell_liquid_strain, [&](std::size_t p) { return t.liquid_strain[p]; });
  const double K = t.fluid.bulk_modulus_Pa, floor = t.fluid.cavitation_floor_Pa();
  std::size_t closed = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!t.saturated(P, p)) continue;
    const double n = t.porosity[p];
    const double solid = trace(s.strain_increment[p]);
    const double liquid = cell_mean_or_own(s, p, t.cell_strain_volume, t.cell_liquid_strain, limit, t.liquid_strain[p]);
    t.liquid_pressure[p] -= K / n * ((1.0 - n) * solid + n * liquid);
    const PoreSpace& pores = t.bodies[P.body[p]];
    const double open = 1.0 - P.mass[p] / (pores.grain_density_kg_m3 * P.volume[p]);
    const double least = kClosedPorosityRatio * pores.initial_porosity;
    closed += open < least;
    t.porosity[p] = std::max(open, least);
  }
  if (smoothed(s)) {
    const auto excess = [&](std::size_t p) { return t.liquid_pressure[p] - t.hydrostatic_pressure(P.z[p]); };
    cell_sums(s, t.cell_volume, t.cell_pressure, excess);
    for (std::size_t p = 0; p < P.size(); ++p)
      if (t.saturated(P, p) && takes_part_in_cell_means(P, p, limit)) {
        const std::size_t k = cell_slot(s, p);
        t.liquid_pressure[p] = t.hydrostatic_pressure(P.z[p]) + t.cell_pressure[k] / t.cell_volume[k];
      }
  }
  for (std::size_t p = 0; p < P.size(); ++p)
    if (t.saturated(P, p)) t.pore_pressure[p] = std::max(t.liquid_pressure[p], floor);
  t.closed_pores = closed;
  t.closed_pores_max = std::max(t.closed_pores_max, closed);
}

double two_phase_time_step_limit(const Simulation& s) {
  if (!s.two_phase) return std::numeric_limits<double>::infinity();
  const TwoPhase& t = *s.two_phase;
  const Particles& P = s.particles;
  const double L = s.grid.min_spacing();
  double limit = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!t.saturated(P, p)) continue;
    const std::size_t b = P.body[p];
    const TwoPhaseWave wave{t.porosity[p],
                            t.permeability(b, t.porosity[p]),
                            t.bodies[b].grain_density_kg_m3,
                            t.fluid.density_kg_m3,
                            s.groups[s.bodies[b].group].constrained_modulus(),
                            t.fluid.bulk_modulus_Pa};
    limit = std::min(limit, mieremet_time_step(wave, L));
  }
  if (!(limit > 0.0))
    throw StepFailure("the two-phase time step is not positive at t = " + std::to_string(s.time_s) +
                      " s (a porosity left (0, 1)?)");
  return limit;
}

// Δt_limit = min(CFL, Mieremet's two-phase step); Δt_{n+1} = C · Δt_limit, or the fixed Δt checked against it.
void limit_two_phase_time_step(Simulation& s) {
  const double limit = two_phase_time_step_limit(s);
  if (!(limit < s.dt_limit_s)) return;
  s.dt_limit_s = limit;
  if (s.settings.fixed_dt_s) {
    if (*s.settings.fixed_dt_s > limit)
      throw StepFailure("the fixed time step " + std::to_string(*s.settings.fixed_dt_s) +
                        " s exceeds the two-phase limit " + std::to_string(limit) +
                        " s at t = " + std::to_string(s.time_s) + " s");
    return;
  }
  s.dt_next_s = s.settings.courant * limit;
}

}  // namespace ffp::mpm
