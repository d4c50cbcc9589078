/// Grid → particle transfers (convective phase). One particle per iteration:
/// no shared writes, parallel and deterministic as is.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>

#include "mpm/pair.hpp"
#include "mpm/stages.hpp"
#include "mpm/support_row.hpp"
#include "mpm/velocity_gradient.hpp"

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
  // A GIMP particle whose support rows fit (mpm/support_row.hpp): a row of nodes per vector.
  auto update_by_rows = [&](std::size_t p, NodalField& f, const ShapeWeights& w) {
    const Row wr = load_row(w.wr);
    Row N[3];
    std::size_t node[3];
    for (int b = 0; b < 3; ++b) {
      node[b] = s.grid.node(w.node_r, w.node_z + b);
      N[b] = wr * w.wz[b];
    }
    if (p < n) {  // not a subcycled body's particle
      Row vr{}, vz{}, dvr{}, dvz{};
      for (int b = 0; b < 3; ++b) {
        const std::size_t i = node[b];
        const Row new_r = load_row(&f.velocity_new_r[i]), new_z = load_row(&f.velocity_new_z[i]);
        vr += N[b] * new_r;
        vz += N[b] * new_z;
        dvr += N[b] * (new_r - load_row(&f.velocity_r[i]));
        dvz += N[b] * (new_z - load_row(&f.velocity_z[i]));
      }
      const double v_r = row_sum(vr), v_z = row_sum(vz);
      P.vr[p] = alpha * (P.vr[p] + row_sum(dvr)) + (1.0 - alpha) * v_r;
      P.vz[p] = alpha * (P.vz[p] + row_sum(dvz)) + (1.0 - alpha) * v_z;
      if constexpr (Move) {
        long clamped = 0;
        move_within_walls(P, p, P.r[p] + dt * v_r, P.z[p] + dt * v_z, walls, clamped);
        if (clamped) clamps += clamped;
      }
    }
    if constexpr (Remap) {
      const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
      for (int b = 0; b < 3; ++b) {
        const std::size_t i = node[b];
        store_row(&f.momentum_r[i], load_row(&f.momentum_r[i]) + N[b] * pr);
        store_row(&f.momentum_z[i], load_row(&f.momentum_z[i]) + N[b] * pz);
      }
    }
  };
  auto update = [&](std::size_t p) {
    NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const ShapeWeights& w = s.weights[p];
    if constexpr (S == 3) {
      if (row_fits(s.grid, w)) return update_by_rows(p, f, w);
    }
    // S_ip and the nodes, formed once for the gather and the remap.
    // S_ip of nodes a = 0, 1 of each row as a pair (mpm/pair.hpp), node 2 alone: the
    // same products, and each sum takes its terms in the same order, as node by node.
    const Pair wr01 = pair(w.wr[0], w.wr[1]);
    Pair N01[S];
    double N2[S];
    std::size_t node[S];
    for (int b = 0; b < S; ++b) {
      node[b] = s.grid.node(w.node_r, w.node_z + b);
      N01[b] = wr01 * w.wz[b];
      if constexpr (S == 3) N2[b] = w.wr[2] * w.wz[b];
    }
    if (p < n) {  // not a subcycled body's particle
      const double* __restrict v_r = f.velocity_r.data();
      const double* __restrict v_z = f.velocity_z.data();
      const double* __restrict v_new_r = f.velocity_new_r.data();
      const double* __restrict v_new_z = f.velocity_new_z.data();
      double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0;
      for (int b = 0; b < S; ++b) {
        const std::size_t i = node[b];
        const Pair new_r = load(v_new_r + i), new_z = load(v_new_z + i);
        const Pair tr = N01[b] * new_r, tz = N01[b] * new_z;
        const Pair dr = N01[b] * (new_r - load(v_r + i)), dz = N01[b] * (new_z - load(v_z + i));
        add_lanes(vr, tr);
        add_lanes(vz, tz);
        add_lanes(dvr, dr);
        add_lanes(dvz, dz);
        if constexpr (S == 3) {
          const std::size_t k = i + 2;
          vr += N2[b] * v_new_r[k];
          vz += N2[b] * v_new_z[k];
          dvr += N2[b] * (v_new_r[k] - v_r[k]);
          dvz += N2[b] * (v_new_z[k] - v_z[k]);
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
      double* __restrict momentum_r = f.momentum_r.data();
      double* __restrict momentum_z = f.momentum_z.data();
      for (int b = 0; b < S; ++b) {
        const std::size_t i = node[b];
        store(momentum_r + i, load(momentum_r + i) + N01[b] * pr);
        store(momentum_z + i, load(momentum_z + i) + N01[b] * pz);
        if constexpr (S == 3) {
          momentum_r[i + 2] += N2[b] * pr;
          momentum_z[i + 2] += N2[b] * pz;
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
  } else {  // each thread its own part's particles (mpm/particle_bins.hpp)
    s.bins.for_each_particle_range(0, n, P.size(), n >= kParallelMinimum, [&](std::size_t first, std::size_t last) {
      for (std::size_t p = first; p < last; ++p) update(p);
    });
  }
  s.wall_clamps += clamps;
}

template <int S>
void move_particles_impl(Simulation& s) {
  Particles& P = s.particles;
  const double dt = s.dt_s;
  const Walls& walls = s.walls;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  std::atomic<long> clamps{0};            // rare (should stay 0)
  s.bins.for_each_particle_range(0, n, P.size(), n >= kParallelMinimum, [&](std::size_t first, std::size_t last) {
    long clamped = 0;
    for (std::size_t p = first; p < last; ++p) {
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
      move_within_walls(P, p, P.r[p] + dt * vr, P.z[p] + dt * vz, walls, clamped);
    }
    clamps += clamped;
  });
  s.wall_clamps += clamps;
}

using NodalArray = std::vector<double> NodalField::*;

/// Δε_p, spin and V_p of one particle from the nodal velocities (vr, vz) of its field.
template <int S>
inline void strain_increment_of(const Grid& grid, const ShapeWeights& w, const double* __restrict vr,
                                const double* __restrict vz, double dt, Voigt& de, double& spin_dt, double& volume) {
  // Nodes a = 0, 1 of a row as a pair (mpm/pair.hpp): the same products, the
  // sums in the same order as node by node.
  VelocityGradient L;
  if constexpr (S == 3) {
    if (row_fits(grid, w)) {  // a row of nodes per vector (mpm/support_row.hpp)
      const Row wr = load_row(w.wr), gr = load_row(w.gr);
      Row rr{}, rz{}, zr{}, zz{}, tt{};
      for (int b = 0; b < 3; ++b) {
        const std::size_t i = grid.node(w.node_r, w.node_z + b);
        const double wz = w.wz[b], gz = w.gz[b];
        const Row N = wr * wz, Gr = gr * wz, Gz = wr * gz;
        const Row vr_row = load_row(vr + i), vz_row = load_row(vz + i);
        rr += vr_row * Gr;
        rz += vr_row * Gz;
        zr += vz_row * Gr;
        zz += vz_row * Gz;
        tt += vr_row * N;
      }
      L.rr = row_sum(rr);
      L.rz = row_sum(rz);
      L.zr = row_sum(zr);
      L.zz = row_sum(zz);
      L.tt = row_sum(tt) * w.inverse_r;
      apply_velocity_gradient(L, dt, de, spin_dt, volume);
      return;
    }
  }
  const Pair wr01 = pair(w.wr[0], w.wr[1]), gr01 = pair(w.gr[0], w.gr[1]);
  for (int b = 0; b < S; ++b) {
    const std::size_t i = grid.node(w.node_r, w.node_z + b);
    const double wz = w.wz[b], gz = w.gz[b];
    const Pair N = wr01 * wz, Gr = gr01 * wz, Gz = wr01 * gz;
    const Pair vr01 = load(vr + i), vz01 = load(vz + i);
    add_lanes(L.rr, vr01 * Gr);
    add_lanes(L.rz, vr01 * Gz);
    add_lanes(L.zr, vz01 * Gr);
    add_lanes(L.zz, vz01 * Gz);
    add_lanes(L.tt, vr01 * N);
    if constexpr (S == 3) {
      const std::size_t k = i + 2;
      const double N2 = w.wr[2] * wz, Gr2 = w.gr[2] * wz, Gz2 = w.wr[2] * gz;
      L.rr += vr[k] * Gr2;
      L.rz += vr[k] * Gz2;
      L.zr += vz[k] * Gr2;
      L.zz += vz[k] * Gz2;
      L.tt += vr[k] * N2;
    }
  }
  L.tt *= w.inverse_r;
  apply_velocity_gradient(L, dt, de, spin_dt, volume);
}

/// The same for particles first..last of `index` (p = index(k)).
template <int S, class Index>
void strain_increments_of(Simulation& s, std::size_t first, std::size_t last, Index&& index, NodalArray velocity_r,
                          NodalArray velocity_z) {
  Particles& P = s.particles;
  const double dt = s.dt_s;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  const Grid& grid = s.grid;
  const ShapeWeights* weights = s.weights.data();
  Voigt* strain_increment = s.strain_increment.data();
  double* spin = s.spin_dt.data();
  double* volume = P.volume.data();
  for (std::size_t k = first; k < last; ++k) {
    const std::size_t p = index(k);
    if (p >= n) continue;
    const NodalField& f = grid.fields[s.bodies[P.body[p]].field];
    strain_increment_of<S>(grid, weights[p], (f.*velocity_r).data(), (f.*velocity_z).data(), dt, strain_increment[p],
                           spin[p], volume[p]);
  }
}

template <int S>
void strain_increments_impl(Simulation& s, NodalArray velocity_r, NodalArray velocity_z) {
  const std::size_t n = s.main_step_end;
  const auto identity = [](std::size_t k) { return k; };
  // Each thread its own part's particles (mpm/particle_bins.hpp).
  s.bins.for_each_particle_range(0, n, s.particles.size(), n >= kParallelMinimum,
                                 [&](std::size_t first, std::size_t last) {
                                   strain_increments_of<S>(s, first, last, identity, velocity_r, velocity_z);
                                 });
}

NodalArray strain_velocity_r(StrainVelocity source) {
  return source == StrainVelocity::remapped ? &NodalField::velocity_r : &NodalField::velocity_new_r;
}
NodalArray strain_velocity_z(StrainVelocity source) {
  return source == StrainVelocity::remapped ? &NodalField::velocity_z : &NodalField::velocity_new_z;
}

/// smooth_volumetric_strain comes right after compute_strain_increments: it may
/// make the increments itself, strip by strip (strains_fused_with_smoothing).
bool strain_fuses_with_smoothing(const Simulation& s) {
  const std::vector<Stage>& stages = s.stages.items();
  const auto it = std::ranges::find(stages, "compute_strain_increments", &Stage::name);
  return it != stages.end() && it + 1 != stages.end() && (it + 1)->name == "smooth_volumetric_strain";
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
// (When smooth_volumetric_strain follows, it makes them, strip by strip, in the
// pass that sums the strip's cells: strain_increments_of_strip.)
void compute_strain_increments(Simulation& s, StrainVelocity source) {
  if (strain_fuses_with_smoothing(s)) {
    s.strain_deferred = true;
    s.strain_source = source;
    return;
  }
  const NodalArray vr = strain_velocity_r(source);
  const NodalArray vz = strain_velocity_z(source);
  if (s.settings.shape_function == ShapeFunction::linear) {
    strain_increments_impl<2>(s, vr, vz);
  } else {
    strain_increments_impl<3>(s, vr, vz);
  }
}

void strain_increments_of_strip(Simulation& s, std::span<const std::uint32_t> strip) {
  const NodalArray vr = strain_velocity_r(s.strain_source);
  const NodalArray vz = strain_velocity_z(s.strain_source);
  const auto index = [&](std::size_t k) { return static_cast<std::size_t>(strip[k]); };
  if (s.settings.shape_function == ShapeFunction::linear) {
    strain_increments_of<2>(s, 0, strip.size(), index, vr, vz);
  } else {
    strain_increments_of<3>(s, 0, strip.size(), index, vr, vz);
  }
}

}  // namespace ffp::mpm
