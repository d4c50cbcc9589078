/// Grid → particle transfers (convective phase). One particle per iteration:
/// no shared writes, parallel and deterministic as is.
#include <algorithm>
#include <atomic>
#include <cmath>

#include "mpm/stages.hpp"

namespace ffp::mpm {

namespace {

/// Moves a particle to x + Δt·v, kept inside the walls (counted in `clamps`).
inline void move_within_walls(Particles& P, std::size_t p, double r, double z, const Walls& walls, long& clamps) {
  // Interpolation makes v_n → 0 at a wall, so particles approach it but never
  // cross — unless Δt·|v_i| exceeds a cell at some node, which the CFL estimate
  // does not bound. Keep them in, and count it.
  if (r < walls.r_min || r > walls.r_max || z < walls.z_min || z > walls.z_max) {
    r = std::clamp(r, walls.r_min, walls.r_max);
    z = std::clamp(z, walls.z_min, walls.z_max);
    ++clamps;
  }
  P.r[p] = r;
  P.z[p] = z;
}

/// Remap: also p_i += S_ip m_p v_p^{n+1} while the particle's weights are at hand
/// (MUSL), in ParticleBins order, so every nodal sum keeps its one fixed order.
template <int S, bool Move, bool Remap>
void update_particles_impl(Simulation& s) {
  Particles& P = s.particles;
  const double dt = s.dt_s, alpha = s.settings.flip_fraction;
  const Walls& walls = s.walls;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  std::atomic<long> clamps{0};            // rare (should stay 0): an atomic costs nothing here
  auto update = [&](std::size_t p) {
    NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const ShapeWeights& w = s.weights[p];
    if (p < n) {  // not a subcycled body's particle
      double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0;
      for (int b = 0; b < S; ++b) {
        const std::size_t row = s.grid.node(w.node_r, w.node_z + b);
        for (int a = 0; a < S; ++a) {
          const std::size_t i = row + static_cast<std::size_t>(a);
          const double N = w.wr[a] * w.wz[b];
          vr += N * f.velocity_new_r[i];
          vz += N * f.velocity_new_z[i];
          dvr += N * (f.velocity_new_r[i] - f.velocity_r[i]);
          dvz += N * (f.velocity_new_z[i] - f.velocity_z[i]);
        }
      }
      P.vr[p] = alpha * (P.vr[p] + dvr) + (1.0 - alpha) * vr;
      P.vz[p] = alpha * (P.vz[p] + dvz) + (1.0 - alpha) * vz;
      if constexpr (Move) {
        long clamped = 0;
        move_within_walls(P, p, P.r[p] + dt * vr, P.z[p] + dt * vz, walls, clamped);
        if (clamped) clamps += clamped;
      }
    }
    if constexpr (Remap) {
      const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
      for (int b = 0; b < S; ++b) {
        const std::size_t row = s.grid.node(w.node_r, w.node_z + b);
        for (int a = 0; a < S; ++a) {
          const std::size_t i = row + static_cast<std::size_t>(a);
          const double N = w.wr[a] * w.wz[b];
          f.momentum_r[i] += N * pr;
          f.momentum_z[i] += N * pz;
        }
      }
    }
  };
  if constexpr (Remap) {
    for (NodalField& f : s.grid.fields) {
      std::fill(f.momentum_r.begin(), f.momentum_r.end(), 0.0);
      std::fill(f.momentum_z.begin(), f.momentum_z.end(), 0.0);
    }
    s.bins.scatter(update);
    s.momentum_remapped = true;
  } else {
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t p = 0; p < n; ++p) update(p);
  }
  s.wall_clamps += clamps;
}

template <int S>
void move_particles_impl(Simulation& s) {
  Particles& P = s.particles;
  const double dt = s.dt_s;
  const Walls& walls = s.walls;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  long clamps = 0;
  FFP_OMP(omp parallel for schedule(static) reduction(+ : clamps) if (n >= kParallelMinimum))
  for (std::size_t p = 0; p < n; ++p) {
    const NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const ShapeWeights& w = s.weights[p];
    double vr = 0.0, vz = 0.0;
    for (int b = 0; b < S; ++b) {
      const std::size_t row = s.grid.node(w.node_r, w.node_z + b);
      for (int a = 0; a < S; ++a) {
        const std::size_t i = row + static_cast<std::size_t>(a);
        const double N = w.wr[a] * w.wz[b];
        vr += N * f.velocity_r[i];
        vz += N * f.velocity_z[i];
      }
    }
    move_within_walls(P, p, P.r[p] + dt * vr, P.z[p] + dt * vz, walls, clamps);
  }
  s.wall_clamps += clamps;
}

using NodalArray = std::vector<double> NodalField::*;

template <int S>
void strain_increments_impl(Simulation& s, NodalArray velocity_r, NodalArray velocity_z) {
  Particles& P = s.particles;
  const double dt = s.dt_s;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
  for (std::size_t p = 0; p < n; ++p) {
    const NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const double* vr = (f.*velocity_r).data();
    const double* vz = (f.*velocity_z).data();
    const ShapeWeights& w = s.weights[p];
    double Lrr = 0.0, Lrz = 0.0, Lzr = 0.0, Lzz = 0.0, Ltt = 0.0;
    for (int b = 0; b < S; ++b) {
      const std::size_t row = s.grid.node(w.node_r, w.node_z + b);
      for (int a = 0; a < S; ++a) {
        const std::size_t i = row + static_cast<std::size_t>(a);
        const double N = w.wr[a] * w.wz[b], Gr = w.gr[a] * w.wz[b], Gz = w.wr[a] * w.gz[b];
        Lrr += vr[i] * Gr;
        Lrz += vr[i] * Gz;
        Lzr += vz[i] * Gr;
        Lzz += vz[i] * Gz;
        Ltt += vr[i] * N;
      }
    }
    Ltt *= w.inverse_r;
    Voigt& de = s.strain_increment[p];
    de << dt * Lrr, dt * Lzz, dt * Ltt, 0.5 * dt * (Lrz + Lzr), 0.0, 0.0;
    s.spin_dt[p] = 0.5 * dt * (Lrz - Lzr);
    const double J = ((1.0 + dt * Lrr) * (1.0 + dt * Lzz) - dt * dt * Lrz * Lzr) * (1.0 + dt * Ltt);
    P.volume[p] *= J;
  }
}

}  // namespace

// v_p^{n+1} = α (v_p^n + Σ_i S_ip (v_i^{n+1} − v_i^n)) + (1 − α) Σ_i S_ip v_i^{n+1}
// x_p^{n+1} = x_p^n + Δt Σ_i S_ip v_i^{n+1} (USL, classic MUSL); musl_remapped: in move_particles.
// MUSL and musl_remapped: p_i = Σ_p S_ip m_p v_p^{n+1} summed here as well, for
// map_velocities_to_grid (one pass over the particles instead of two).
void update_particles(Simulation& s) {
  const bool linear = s.settings.shape_function == ShapeFunction::linear;
  switch (s.settings.transfer) {
    case Transfer::usl:
      linear ? update_particles_impl<2, true, false>(s) : update_particles_impl<3, true, false>(s);
      break;
    case Transfer::musl:
      linear ? update_particles_impl<2, true, true>(s) : update_particles_impl<3, true, true>(s);
      break;
    case Transfer::musl_remapped:
      linear ? update_particles_impl<2, false, true>(s) : update_particles_impl<3, false, true>(s);
      break;
  }
}

// musl_remapped (as the paper's code, Anura3D, moves particles): x_p^{n+1} =
// x_p^n + Δt Σ_i S_ip ṽ_i^{n+1}, ṽ the velocities remapped from the updated
// particles — the same field that gives the strain increments, so that a
// particle moves as it strains.
void move_particles(Simulation& s) {
  if (s.settings.shape_function == ShapeFunction::linear) {
    move_particles_impl<2>(s);
  } else {
    move_particles_impl<3>(s);
  }
}

// L_p = Σ_i v_i ⊗ G_ip,  L_θθ = Σ_i S_ip v_r,i / r_p  (hoop strain rate v_r/r);
// Δε = Δt sym(L),  spin W_rz Δt = ½ Δt (L_rz − L_zr);  V_p ← V_p det(I + Δt L)
void compute_strain_increments(Simulation& s, StrainVelocity source) {
  const bool remapped = source == StrainVelocity::remapped;
  const NodalArray vr = remapped ? &NodalField::velocity_r : &NodalField::velocity_new_r;
  const NodalArray vz = remapped ? &NodalField::velocity_z : &NodalField::velocity_new_z;
  if (s.settings.shape_function == ShapeFunction::linear) {
    strain_increments_impl<2>(s, vr, vz);
  } else {
    strain_increments_impl<3>(s, vr, vz);
  }
}

}  // namespace ffp::mpm
