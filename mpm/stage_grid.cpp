/// Grid (Lagrangian phase) stages: loads, integration, fixities.
#include <algorithm>
#include <cmath>

#include "mpm/stages.hpp"

namespace ffp::mpm {

namespace {

/// integrate_grid comes right after apply_gravity: it may add m_i g in its own
/// loop over the nodes (one parallel region fewer; the same operation per node).
bool gravity_fuses_with_integration(const Simulation& s) {
  const std::vector<Stage>& stages = s.stages.items();
  const auto it = std::ranges::find(stages, "apply_gravity", &Stage::name);
  return it != stages.end() && it + 1 != stages.end() && (it + 1)->name == "integrate_grid";
}

}  // namespace

// f_i^ext,z −= m_i g : Σ_p S_ip m_p g = m_i g by the partition of unity.
void apply_gravity(Simulation& s) {
  if (gravity_fuses_with_integration(s)) {
    s.gravity_deferred = true;
    return;
  }
  const double g = *s.gravity_m_s2;
  for (NodalField& f : s.grid.fields) {
    const std::size_t n = f.size();
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t i = 0; i < n; ++i) f.external_force_z[i] -= f.mass[i] * g;
  }
}

// f_i,r = ± p(t) · r_side · ∫_{z_min}^{z_max} N_j(z) dz  (per radian: the face element is r dθ dz);
// on the top side f_i,z = −p(t) · ∫_{r_min}^{r_max} N_i(r) r dr (the face element is r dθ dr).
void apply_surface_pressure(Simulation& s) {
  NodalField& f = s.grid.fields[0];
  for (const SurfacePressure& load : s.pressures) {
    const double p = load.pressure_Pa(s.time_s);
    if (load.side == Side::top) {
      const int j = s.grid.z.nodes() - 1;
      for (int i = 0; i < s.grid.r.nodes(); ++i)
        f.external_force_z[s.grid.node(i, j)] -= p * s.grid.r.hat_moment(i, load.r_min_m, load.r_max_m);
      continue;
    }
    const bool inner = load.side == Side::inner;
    const int i = inner ? 0 : s.grid.r.nodes() - 1;
    const double r = s.grid.r.coordinate(i);
    const double sign = inner ? 1.0 : -1.0;  // pressure pushes into the body
    for (int j = 0; j < s.grid.z.nodes(); ++j)
      f.external_force_r[s.grid.node(i, j)] += sign * p * r * s.grid.z.hat_integral(j, load.z_min_m, load.z_max_m);
  }
}

// Cundall's local (non-viscous) damping: f_i ← f_i − α |f_i| sign(v_i), per component.
void apply_local_damping(Simulation& s) {
  const double alpha = s.settings.local_damping;
  const double floor = s.mass_floor_kg;
  for (NodalField& f : s.grid.fields) {
    const std::size_t n = f.size();
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t i = 0; i < n; ++i) {
      if (!(f.mass[i] > floor)) continue;
      const double fr = f.internal_force_r[i] + f.external_force_r[i];
      const double fz = f.internal_force_z[i] + f.external_force_z[i];
      const double vr = f.momentum_r[i], vz = f.momentum_z[i];  // same sign as v_i
      f.external_force_r[i] -= alpha * std::abs(fr) * ((vr > 0.0) - (vr < 0.0));
      f.external_force_z[i] -= alpha * std::abs(fz) * ((vz > 0.0) - (vz < 0.0));
    }
  }
}

// v_i^n = p_i/m_i ;  v_i^{n+1} = v_i^n + Δt (f_i^int + f_i^ext)/m_i   (empty nodes: 0)
// (f_i^ext,z −= m_i g first, when apply_gravity left it here.)
void integrate_grid(Simulation& s) {
  const double dt = s.dt_s;
  const double floor = s.mass_floor_kg;
  const bool gravity = s.gravity_deferred;
  const double g = gravity ? *s.gravity_m_s2 : 0.0;
  s.gravity_deferred = false;
  for (NodalField& f : s.grid.fields) {
    const std::size_t n = f.size();
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t i = 0; i < n; ++i) {
      if (gravity) f.external_force_z[i] -= f.mass[i] * g;
      if (f.mass[i] > floor) {
        const double inverse_m = 1.0 / f.mass[i];
        f.velocity_r[i] = f.momentum_r[i] * inverse_m;
        f.velocity_z[i] = f.momentum_z[i] * inverse_m;
        f.velocity_new_r[i] = f.velocity_r[i] + dt * (f.internal_force_r[i] + f.external_force_r[i]) * inverse_m;
        f.velocity_new_z[i] = f.velocity_z[i] + dt * (f.internal_force_z[i] + f.external_force_z[i]) * inverse_m;
      } else {
        f.velocity_r[i] = f.velocity_z[i] = f.velocity_new_r[i] = f.velocity_new_z[i] = 0.0;
      }
    }
  }
}

// Lysmer & Kuhlemeyer (1969), with the springs of Liu et al. (2006) when the waves' source is
// known: on an absorbing side f_i = R_i − c_i v_i^{n+1} − k_i u_i^{n+1}, c_i = ρ c A_i, k_i = α G A_i/R
// (mpm/boundary_conditions.hpp), taken at the step's end so that no step is too long for them:
// m_i (v^{n+1} − v^n) = Δt (f_i + R_i − c_i v^{n+1} − k_i (u^n + Δt v^{n+1})), i.e.
// v ← (m v* + Δt (R − k u^n))/(m + Δt c + Δt² k) with v* integrate_grid's velocity, then u += Δt v.
// R_i = −(f_i^int + f_i^ext) of the first step: the reaction the side carried in the initial
// (geostatic) state, held so that the sand at rest stays at rest.
void apply_absorbing_boundaries(Simulation& s) {
  const std::size_t n = s.absorbing.size(), fields = s.grid.fields.size();
  if (s.absorbing_reaction_r.size() != n * fields) {
    s.absorbing_reaction_r.assign(n * fields, 0.0);
    s.absorbing_reaction_z.assign(n * fields, 0.0);
    s.absorbing_displacement_r.assign(n * fields, 0.0);
    s.absorbing_displacement_z.assign(n * fields, 0.0);
    for (std::size_t k = 0; k < fields; ++k) {
      const NodalField& f = s.grid.fields[k];
      for (std::size_t a = 0; a < n; ++a) {
        const std::size_t i = s.absorbing[a].node;
        s.absorbing_reaction_r[k * n + a] = -(f.internal_force_r[i] + f.external_force_r[i]);
        s.absorbing_reaction_z[k * n + a] = -(f.internal_force_z[i] + f.external_force_z[i]);
      }
    }
  }
  const double dt = s.dt_s, floor = s.mass_floor_kg;
  for (std::size_t a = 0; a < n; ++a) {
    const Dashpot d = dashpot(s.absorbing[a], s.grid.r, s.grid.z, s.beyond);
    const std::size_t i = s.absorbing[a].node;
    for (std::size_t k = 0; k < fields; ++k) {
      NodalField& f = s.grid.fields[k];
      const double m = f.mass[i];
      if (!(m > floor)) continue;
      double& ur = s.absorbing_displacement_r[k * n + a];
      double& uz = s.absorbing_displacement_z[k * n + a];
      f.velocity_new_r[i] = (m * f.velocity_new_r[i] + dt * (s.absorbing_reaction_r[k * n + a] - d.stiffness_r * ur)) /
                            (m + dt * d.damping_r + dt * dt * d.stiffness_r);
      f.velocity_new_z[i] = (m * f.velocity_new_z[i] + dt * (s.absorbing_reaction_z[k * n + a] - d.stiffness_z * uz)) /
                            (m + dt * d.damping_z + dt * dt * d.stiffness_z);
      ur += dt * f.velocity_new_r[i];
      uz += dt * f.velocity_new_z[i];
    }
  }
}

// Constrained components: v_i^n = v_i^{n+1} = 0, so the FLIP increment there is 0
// as well (equivalent to zeroing p_i and f_i, Sulsky et al. 1995).
void apply_boundary_conditions(Simulation& s) {
  for (NodalField& f : s.grid.fields) {
    for (const NodeConstraint& c : s.grid.constraints) {
      if (c.bits & constrain_r) f.velocity_r[c.node] = f.velocity_new_r[c.node] = 0.0;
      if (c.bits & constrain_z) f.velocity_z[c.node] = f.velocity_new_z[c.node] = 0.0;
    }
  }
}

}  // namespace ffp::mpm
