/// The micropolar option's stages (docs/theory.md#micropolar): the micro-rotation's nodal
/// field integrated as the velocities are, and the skew and couple stresses of the micropolar
/// particles. Written plainly: the scatters go through ParticleBins one particle at a time
/// (fixed order, bit-identical for any thread count); every other loop writes one node or one
/// particle per iteration.
#include <cmath>

#include "mpm/stages.hpp"
#include "mpm/support_row.hpp"

namespace ffp::mpm {

namespace {

/// fn(p, group) for every particle of a micropolar body, each on one thread.
template <class Fn>
void for_micropolar_particles(const Simulation& s, Fn&& fn) {
  for (const MicropolarGroup& g : s.micropolar.groups) {
    const MaterialGroup& group = s.groups[g.group];
    const auto begin = static_cast<std::ptrdiff_t>(group.begin), end = static_cast<std::ptrdiff_t>(group.end);
    FFP_OMP(omp parallel for schedule(static) if (group.size() >= kParallelMinimum))
    for (std::ptrdiff_t p = begin; p < end; ++p) fn(static_cast<std::size_t>(p), g);
  }
}

/// ω̇_i = h_i/Θ_i (0 on empty nodes), then ω̇_i = 0 where ω is fixed.
void spin_from_momentum(MicropolarFields& f, std::vector<double>& spin) {
  const std::size_t n = spin.size();
  FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
  for (std::size_t i = 0; i < n; ++i)
    spin[i] = f.rotational_mass[i] > f.rotational_mass_floor ? f.angular_momentum[i] / f.rotational_mass[i] : 0.0;
  for (const std::uint32_t i : f.fixed_nodes) spin[i] = 0.0;
}

template <int S>
void scatter_micropolar(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  const Particles& P = s.particles;
  s.bins.scatter([&](std::size_t p) {
    const MicropolarGroup* g = f.group_of(P.body[p]);
    if (g == nullptr) return;
    NodalField& field = s.grid.fields[s.bodies[P.body[p]].field];
    const ShapeWeights& w = s.weights[p];
    const double inertia = P.mass[p] * g->micro_inertia_m2, angular = inertia * f.rotation_rate[p];
    const double V = P.volume[p], skew = f.skew_stress[p], m_r = f.couple_r[p], m_z = f.couple_z[p];
    const double hoop = f.couple_hoop[p] * w.inverse_r;
    for_support<S>(s.grid, w, [&](std::size_t i, double N, double Gr, double Gz) {
      f.rotational_mass[i] += N * inertia;
      f.angular_momentum[i] += N * angular;
      f.couple_force[i] += V * (2.0 * skew * N - m_r * Gr - m_z * Gz + hoop * N);
      field.internal_force_r[i] -= V * skew * Gz;
      field.internal_force_z[i] += V * skew * Gr;
    });
  });
}

template <int S>
void scatter_angular_momentum(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  const Particles& P = s.particles;
  s.bins.scatter([&](std::size_t p) {
    const MicropolarGroup* g = f.group_of(P.body[p]);
    if (g == nullptr) return;
    const double angular = P.mass[p] * g->micro_inertia_m2 * f.rotation_rate[p];
    for_support<S>(s.grid, s.weights[p],
                   [&](std::size_t i, double N, double, double) { f.angular_momentum[i] += N * angular; });
  });
}

template <int S>
void blend_rotation_rates(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  const double alpha = s.settings.flip_fraction;
  for_micropolar_particles(s, [&](std::size_t p, const MicropolarGroup&) {
    double updated = 0.0, change = 0.0;  // Σ S ω̇_i^{n+1}, Σ S (ω̇_i^{n+1} − ω̇_i^n)
    for_support<S>(s.grid, s.weights[p], [&](std::size_t i, double N, double, double) {
      updated += N * f.spin_new[i];
      change += N * (f.spin_new[i] - f.spin[i]);
    });
    f.rotation_rate[p] = alpha * (f.rotation_rate[p] + change) + (1.0 - alpha) * updated;
  });
}

/// The micro terms' slip at the sand's friction (models/micropolar.hpp), at the mean pressure of
/// the step's start.
void slip_at_friction(MicropolarFields& f, std::size_t p, const MicropolarGroup& g, const Voigt& stress) {
  const double pressure = -(stress[0] + stress[1] + stress[2]) / 3.0;
  const MicroStresses held = held_at_friction({f.skew_stress[p], f.couple_r[p], f.couple_z[p], f.couple_hoop[p]},
                                              g.slip_friction, g.length_m, pressure);
  f.skew_stress[p] = held.skew;
  f.couple_r[p] = held.couple_r;
  f.couple_z[p] = held.couple_z;
  f.couple_hoop[p] = held.couple_hoop;
}

template <int S>
void micropolar_stresses(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  const Particles& P = s.particles;
  const std::vector<double>& spin = s.settings.transfer == Transfer::usl ? f.spin_new : f.spin;
  const double dt = s.dt_s;
  for_micropolar_particles(s, [&](std::size_t p, const MicropolarGroup& g) {
    const ShapeWeights& w = s.weights[p];
    double rate = 0.0, rate_r = 0.0, rate_z = 0.0;  // ω̇_p and ∇ω̇_p from the nodes
    for_support<S>(s.grid, w, [&](std::size_t i, double N, double Gr, double Gz) {
      rate += N * spin[i];
      rate_r += Gr * spin[i];
      rate_z += Gz * spin[i];
    });
    const double turn = dt * rate, macro_turn = s.spin_dt[p];  // Δω, Δω_M
    f.rotation[p] += turn;
    f.macro_rotation[p] += macro_turn;
    const double limit = s.groups[g.group].disconnected_below_kg_m3;
    if (limit > 0.0 && P.mass[p] <= limit * P.volume[p]) {  // grains apart carry no moment either
      f.skew_stress[p] = f.couple_r[p] = f.couple_z[p] = f.couple_hoop[p] = 0.0;
      return;
    }
    f.skew_stress[p] += 2.0 * g.cosserat_shear_modulus * (macro_turn - turn);
    const double m_r = f.couple_r[p], m_z = f.couple_z[p];
    f.couple_r[p] = m_r + macro_turn * m_z + g.couple_modulus * dt * rate_r;
    f.couple_z[p] = m_z - macro_turn * m_r + g.couple_modulus * dt * rate_z;
    f.couple_hoop[p] -= g.couple_modulus * turn * w.inverse_r;
    if (g.slip_friction > 0.0) slip_at_friction(f, p, g, P.stress[p]);
  });
}

}  // namespace

// Θ_i = Σ_p S_ip m_p j ;  h_i = Σ_p S_ip m_p j ω̇_p ;
// c_i = Σ_p V_p [2 s_p S_ip − m_r,p G_ip,r − m_z,p G_ip,z + m_θ,p S_ip/r_p]   (the couple on ω_i);
// f_i^int += Σ_p V_p s_p (−G_ip,z, G_ip,r)   (the skew stress's share of the force: σ_rz += s, σ_zr −= s).
// From the virtual power of W_micro = 2 G_c (ω_M − ω)² + G ℓ² κ·κ per radian (docs/theory.md#micropolar).
void map_micropolar_to_grid(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  for (auto* a : {&f.rotational_mass, &f.angular_momentum, &f.couple_force}) std::fill(a->begin(), a->end(), 0.0);
  if (uses_linear_hats(s)) {
    scatter_micropolar<2>(s);
  } else {
    scatter_micropolar<3>(s);
  }
}

// ω̇_i^n = h_i/Θ_i ;  ω̇_i^{n+1} = ω̇_i^n + Δt c_i/Θ_i   (empty nodes: 0; fixed nodes: 0 before and after).
// With Cundall's local damping, c_i −= α |c_i| sign(ω̇_i), as f_i is damped (apply_local_damping).
void integrate_micro_rotation(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  const double dt = s.dt_s, alpha = s.settings.local_damping;
  const std::size_t n = f.couple_force.size();
  if (alpha > 0.0) {
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t i = 0; i < n; ++i) {
      const double h = f.angular_momentum[i];  // same sign as ω̇_i
      f.couple_force[i] -= alpha * std::abs(f.couple_force[i]) * ((h > 0.0) - (h < 0.0));
    }
  }
  spin_from_momentum(f, f.spin);
  FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
  for (std::size_t i = 0; i < n; ++i)
    f.spin_new[i] = f.rotational_mass[i] > f.rotational_mass_floor
                        ? f.spin[i] + dt * f.couple_force[i] / f.rotational_mass[i]
                        : 0.0;
  for (const std::uint32_t i : f.fixed_nodes) f.spin_new[i] = 0.0;
}

// ω̇_p ← α (ω̇_p + Σ_i S_ip (ω̇_i^{n+1} − ω̇_i^n)) + (1 − α) Σ_i S_ip ω̇_i^{n+1}   (as v_p, update_particles).
void update_particle_micro_rotation(Simulation& s) {
  if (uses_linear_hats(s)) {
    blend_rotation_rates<2>(s);
  } else {
    blend_rotation_rates<3>(s);
  }
}

// MUSL: h_i = Σ_p S_ip m_p j ω̇_p^{n+1};  ω̇_i = h_i/Θ_i (fixed nodes 0): the micro spin the
// rotation increments take, as the strain increments take the remapped velocities.
void map_micro_spin_to_grid(Simulation& s) {
  MicropolarFields& f = s.micropolar;
  std::fill(f.angular_momentum.begin(), f.angular_momentum.end(), 0.0);
  if (uses_linear_hats(s)) {
    scatter_angular_momentum<2>(s);
  } else {
    scatter_angular_momentum<3>(s);
  }
  spin_from_momentum(f, f.spin);
}

// Δω_p = Δt Σ_i S_ip ω̇_i ;  Δκ = Δt Σ_i G_ip ω̇_i,  Δκ_θ = −Δω_p/r_p ;  Δω_M = spin·Δt (compute_strain_increments);
// s ← s + 2 G_c (Δω_M − Δω_p) ;  m ← m + ΔW m (Jaumann, the couple vector turned with the spin) + 2 G ℓ² Δκ.
// ω̇_i: USL the grid update's ω̇^{n+1}, MUSL the remapped one. A particle that has lost grain
// contact (below its group's disconnection density) carries no skew or couple stress.
void update_micropolar_stresses(Simulation& s) {
  if (uses_linear_hats(s)) {
    micropolar_stresses<2>(s);
  } else {
    micropolar_stresses<3>(s);
  }
}

}  // namespace ffp::mpm
