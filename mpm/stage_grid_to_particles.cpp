/// Grid → particle transfers (convective phase). One particle per iteration:
/// no shared writes, parallel and deterministic as is.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>

#include "mpm/particle_update.hpp"
#include "mpm/prefetch.hpp"
#include "mpm/stages.hpp"
#include "mpm/support_row.hpp"
#include "mpm/velocity_gradient.hpp"

namespace ffp::mpm {

namespace {

/// A GIMP stacked pair (stacked_pair): each particle's row weights N_b = s_r s_z,b,
/// and where their four node rows start (the lower's row b is node row b, the
/// upper's row b is node row b + 1).
struct StackedPairRows {
  Row lower[3], upper[3];
  std::size_t first, stride;
  StackedPairRows(const Grid& grid, const ShapeWeights& w, const ShapeWeights& v)
      : first(grid.node(w.node_r, w.node_z)), stride(static_cast<std::size_t>(grid.r.nodes())) {
    const Row wr_lower = load_support_row<3>(w.wr), wr_upper = load_support_row<3>(v.wr);
    for (int b = 0; b < 3; ++b) {
      lower[b] = wr_lower * w.wz[b];
      upper[b] = wr_upper * v.wz[b];
    }
  }
  std::size_t row(int r) const { return first + stride * static_cast<std::size_t>(r); }
};

/// Remap: v_i^{n+1} − v_i^n once per node, in place of v_i^n, which map_velocities_to_grid
/// overwrites next with the remapped field: each particle's Δv then reads one nodal array
/// instead of two (the same differences, so the same bits). And the momenta zeroed for the
/// remap's sums.
void store_velocity_changes(Simulation& s) {
  for (NodalField& f : s.grid.fields) {
    const std::size_t nodes = f.size();
    FFP_OMP(omp parallel for schedule(static) if (nodes >= kParallelMinimum))
    for (std::size_t i = 0; i < nodes; ++i) {
      f.velocity_r[i] = f.velocity_new_r[i] - f.velocity_r[i];
      f.velocity_z[i] = f.velocity_new_z[i] - f.velocity_z[i];
    }
    std::fill(f.momentum_r.begin(), f.momentum_r.end(), 0.0);
    std::fill(f.momentum_z.begin(), f.momentum_z.end(), 0.0);
  }
}

/// Remap, linear hats: each strip's particles gathered, blended and moved (blend_and_move),
/// and their momenta summed onto the nodes.
template <class BlendAndMove>
void remap_linear_strips(Simulation& s, BlendAndMove& blend_and_move) {
  Particles& P = s.particles;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  using Vec = SupportRow<2>;
  s.bins.scatter_strips([&](int, std::span<const std::uint32_t> particles) {
    // Linear hats: the remap's momentum sums of a run of particles in one cell in
    // registers, as in scatter_linear_strip (stage_particles_to_grid.cpp): loaded
    // at the run's first particle, stored after its last, the same terms in the
    // same order (the same bits). The run's nodal velocities are read once too.
    constexpr int kNone = -1;
    int run_field = kNone;
    std::size_t run_node = 0;
    double *momentum_r = nullptr, *momentum_z = nullptr;
    Vec sum_r[2] = {}, sum_z[2] = {};
    Vec new_r[2] = {}, new_z[2] = {}, change_r[2] = {}, change_z[2] = {};  // the run's gathered rows
    const auto nodes_r = static_cast<std::size_t>(s.grid.r.nodes());
    auto store_run = [&] {
      for (int b = 0; b < 2; ++b) {
        store_support_row<2>(momentum_r + run_node + nodes_r * b, sum_r[b]);
        store_support_row<2>(momentum_z + run_node + nodes_r * b, sum_z[b]);
      }
    };
    const Prefetch prefetch(P.size());
    for (std::size_t k = 0; k < particles.size(); ++k) {
      prefetch.ahead(s.weights.data(), particles, k);
      const std::uint32_t p = particles[k];
      const int field = s.bodies[P.body[p]].field;
      NodalField& f = s.grid.fields[static_cast<std::size_t>(field)];
      const ShapeWeights& w = s.weights[p];
      const Vec wr = load_support_row<2>(w.wr);
      const Vec N[2] = {wr * w.wz[0], wr * w.wz[1]};
      const std::size_t node[2] = {s.grid.node(w.node_r, w.node_z), s.grid.node(w.node_r, w.node_z + 1)};
      if (field != run_field || node[0] != run_node) {
        if (run_field != kNone) store_run();
        run_field = field;
        run_node = node[0];
        momentum_r = f.momentum_r.data();
        momentum_z = f.momentum_z.data();
        for (int b = 0; b < 2; ++b) {
          sum_r[b] = load_support_row<2>(momentum_r + node[b]);
          sum_z[b] = load_support_row<2>(momentum_z + node[b]);
          new_r[b] = load_support_row<2>(&f.velocity_new_r[node[b]]);
          new_z[b] = load_support_row<2>(&f.velocity_new_z[node[b]]);
          change_r[b] = load_support_row<2>(&f.velocity_r[node[b]]);  // v_i^{n+1} − v_i^n (below)
          change_z[b] = load_support_row<2>(&f.velocity_z[node[b]]);
        }
      }
      if (p < n) {  // gather_by_rows, from the run's rows
        Vec vr{}, vz{}, dvr{}, dvz{};
        for (int b = 0; b < 2; ++b) {
          vr += N[b] * new_r[b];
          vz += N[b] * new_z[b];
          dvr += N[b] * change_r[b];
          dvz += N[b] * change_z[b];
        }
        blend_and_move(p, row_sum(vr), row_sum(vz), row_sum(dvr), row_sum(dvz));
      }
      const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
      for (int b = 0; b < 2; ++b) {
        sum_r[b] = sum_r[b] + N[b] * pr;
        sum_z[b] = sum_z[b] + N[b] * pz;
      }
    }
    if (run_field != kNone) store_run();
  });
}

/// Remap, GIMP: each strip's particles by stacked pairs where they are, else one by one (update).
template <int S, class BlendAndMove, class Update>
void remap_gimp_strips(Simulation& s, BlendAndMove& blend_and_move, Update& update) {
  Particles& P = s.particles;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  using Vec = SupportRow<S>;
  // GIMP: a cell's lower and upper particle (consecutive, as seeded: the same
  // support columns, the upper one node row up) as a pair. Their four node rows
  // are read once per nodal array, and the remap adds to each once, the lower's
  // term before the upper's, as one by one (the same bits). Array by array, so
  // that only that array's sums are live.
  auto update_pair = [&](std::size_t p, std::size_t q, NodalField& f, const ShapeWeights& w, const ShapeWeights& v) {
    const StackedPairRows N(s.grid, w, v);
    auto gather = [&](const double* x, Vec& sum_p, Vec& sum_q) {
      for (int row = 0; row < S + 1; ++row) {
        const Vec at = load_support_row<S>(x + N.row(row));
        if (row < S) sum_p += N.lower[row] * at;
        if (row > 0) sum_q += N.upper[row - 1] * at;
      }
    };
    Vec vr_p{}, vz_p{}, dvr_p{}, dvz_p{}, vr_q{}, vz_q{}, dvr_q{}, dvz_q{};
    gather(f.velocity_new_r.data(), vr_p, vr_q);
    gather(f.velocity_new_z.data(), vz_p, vz_q);
    gather(f.velocity_r.data(), dvr_p, dvr_q);  // v_i^{n+1} − v_i^n (below)
    gather(f.velocity_z.data(), dvz_p, dvz_q);
    blend_and_move(p, row_sum(vr_p), row_sum(vz_p), row_sum(dvr_p), row_sum(dvz_p));
    blend_and_move(q, row_sum(vr_q), row_sum(vz_q), row_sum(dvr_q), row_sum(dvz_q));
    auto remap = [&](double* x, double momentum_p, double momentum_q) {
      for (int row = 0; row < S + 1; ++row) {
        double* at = x + N.row(row);
        Vec sum = load_support_row<S>(at);
        if (row < S) sum = sum + N.lower[row] * momentum_p;
        if (row > 0) sum = sum + N.upper[row - 1] * momentum_q;
        store_support_row<S>(at, sum);
      }
    };
    remap(f.momentum_r.data(), P.mass[p] * P.vr[p], P.mass[q] * P.vr[q]);
    remap(f.momentum_z.data(), P.mass[p] * P.vz[p], P.mass[q] * P.vz[q]);
  };
  s.bins.scatter_strips([&](int, std::span<const std::uint32_t> particles) {
    const Prefetch prefetch(P.size());
    for (std::size_t k = 0; k < particles.size();) {
      prefetch.ahead(s.weights.data(), particles, k);  // and the next: a pair takes two
      prefetch.ahead(s.weights.data(), particles, k + 1);
      const std::size_t p = particles[k];
      const ShapeWeights& w = s.weights[p];
      if (k + 1 < particles.size() && p < n && rows_fit<S>(s.grid, w)) {
        const std::size_t q = particles[k + 1];
        const ShapeWeights& v = s.weights[q];
        const std::uint8_t field = s.bodies[P.body[p]].field;
        if (q < n && stacked_pair(w, v) && s.bodies[P.body[q]].field == field) {
          update_pair(p, q, s.grid.fields[field], w, v);
          k += 2;
          continue;
        }
      }
      update(p);
      ++k;
    }
  });
}

/// No remap: each thread its own part's particles (mpm/particle_bins.hpp), GIMP's stacked
/// pairs together, the others one by one (update).
template <int S, class BlendAndMove, class Update>
void gather_particles(Simulation& s, BlendAndMove& blend_and_move, Update& update) {
  Particles& P = s.particles;
  const std::size_t n = s.main_step_end;  // a subcycled body moves and strains in its own substeps
  // GIMP: a cell's lower and upper particle (consecutive, as seeded) as a pair whose
  // four node rows are read once for both, as in the remap above (the same bits).
  auto gather_pair = [&](std::size_t p, std::size_t q, const NodalField& f, const ShapeWeights& w,
                         const ShapeWeights& v) {
    const StackedPairRows N(s.grid, w, v);
    // Σ S v^{n+1} and Σ S (v^{n+1} − v^n) of one component for both particles.
    auto gather = [&](const double* updated, const double* previous, Row& v_p, Row& dv_p, Row& v_q, Row& dv_q) {
      for (int row = 0; row < 4; ++row) {
        const std::size_t i = N.row(row);
        const Row now = load_support_row<3>(updated + i), change = now - load_support_row<3>(previous + i);
        if (row < 3) {
          v_p += N.lower[row] * now;
          dv_p += N.lower[row] * change;
        }
        if (row > 0) {
          v_q += N.upper[row - 1] * now;
          dv_q += N.upper[row - 1] * change;
        }
      }
    };
    Row vr_p{}, vz_p{}, dvr_p{}, dvz_p{}, vr_q{}, vz_q{}, dvr_q{}, dvz_q{};
    gather(f.velocity_new_r.data(), f.velocity_r.data(), vr_p, dvr_p, vr_q, dvr_q);
    gather(f.velocity_new_z.data(), f.velocity_z.data(), vz_p, dvz_p, vz_q, dvz_q);
    blend_and_move(p, row_sum(vr_p), row_sum(vz_p), row_sum(dvr_p), row_sum(dvz_p));
    blend_and_move(q, row_sum(vr_q), row_sum(vz_q), row_sum(dvr_q), row_sum(dvz_q));
  };
  s.bins.for_each_particle_range(0, n, P.size(), n >= kParallelMinimum, [&](std::size_t first, std::size_t last) {
    for (std::size_t p = first; p < last; ++p) {
      if constexpr (S == 3) {
        const ShapeWeights& w = s.weights[p];
        if (p + 1 < last && rows_fit<S>(s.grid, w)) {
          const ShapeWeights& v = s.weights[p + 1];
          const std::uint8_t field = s.bodies[P.body[p]].field;
          if (stacked_pair(w, v) && s.bodies[P.body[p + 1]].field == field) {
            gather_pair(p, p + 1, s.grid.fields[field], w, v);
            ++p;
            continue;
          }
        }
      }
      update(p);
    }
  });
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
  // v_p ← α (v_p + Σ S Δv_i) + (1 − α) Σ S v_i^{n+1}, and x_p ← x_p + Δt Σ S v_i^{n+1} (Move),
  // from the particle's gathered sums v = Σ S v_i^{n+1} and dv = Σ S (v_i^{n+1} − v_i^n).
  auto blend_and_move = [&](std::size_t p, double v_r, double v_z, double dv_r, double dv_z) {
    blend_flip_pic(P, p, alpha, v_r, v_z, dv_r, dv_z);
    if constexpr (Move) {
      long clamped = 0;
      move_within_walls(P, p, P.r[p] + dt * v_r, P.z[p] + dt * v_z, walls, clamped);
      if (clamped) clamps += clamped;
    }
  };
  // A particle whose support rows go as vectors (mpm/support_row.hpp): a row of nodes per vector.
  using Vec = SupportRow<S>;
  // The gather and the move of a particle whose rows fit, from its rows' weights N.
  auto gather_by_rows = [&](std::size_t p, const NodalField& f, const Vec N[S], const std::size_t node[S]) {
    if (p < n) {  // not a subcycled body's particle
      Vec vr{}, vz{}, dvr{}, dvz{};
      for (int b = 0; b < S; ++b) {
        const std::size_t i = node[b];
        const Vec new_r = load_support_row<S>(&f.velocity_new_r[i]), new_z = load_support_row<S>(&f.velocity_new_z[i]);
        vr += N[b] * new_r;
        vz += N[b] * new_z;
        if constexpr (Remap) {  // velocity_r, _z hold v_i^{n+1} − v_i^n (see below)
          dvr += N[b] * load_support_row<S>(&f.velocity_r[i]);
          dvz += N[b] * load_support_row<S>(&f.velocity_z[i]);
        } else {
          dvr += N[b] * (new_r - load_support_row<S>(&f.velocity_r[i]));
          dvz += N[b] * (new_z - load_support_row<S>(&f.velocity_z[i]));
        }
      }
      blend_and_move(p, row_sum(vr), row_sum(vz), row_sum(dvr), row_sum(dvz));
    }
  };
  auto update_by_rows = [&](std::size_t p, NodalField& f, const ShapeWeights& w) {
    const Vec wr = load_support_row<S>(w.wr);
    Vec N[S];
    std::size_t node[S];
    for (int b = 0; b < S; ++b) {
      node[b] = s.grid.node(w.node_r, w.node_z + b);
      N[b] = wr * w.wz[b];
    }
    gather_by_rows(p, f, N, node);
    if constexpr (Remap) {
      const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
      for (int b = 0; b < S; ++b) {
        const std::size_t i = node[b];
        store_support_row<S>(&f.momentum_r[i], load_support_row<S>(&f.momentum_r[i]) + N[b] * pr);
        store_support_row<S>(&f.momentum_z[i], load_support_row<S>(&f.momentum_z[i]) + N[b] * pz);
      }
    }
  };
  auto update = [&](std::size_t p) {
    NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const ShapeWeights& w = s.weights[p];
    if (rows_fit<S>(s.grid, w)) return update_by_rows(p, f, w);
    // A GIMP edge particle: node by node.
    if (p < n) {  // not a subcycled body's particle
      double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0;
      for_support<S>(s.grid, w, [&](std::size_t i, double N, double, double) {
        vr += N * f.velocity_new_r[i];
        vz += N * f.velocity_new_z[i];
        if constexpr (Remap) {
          dvr += N * f.velocity_r[i];
          dvz += N * f.velocity_z[i];
        } else {
          dvr += N * (f.velocity_new_r[i] - f.velocity_r[i]);
          dvz += N * (f.velocity_new_z[i] - f.velocity_z[i]);
        }
      });
      blend_and_move(p, vr, vz, dvr, dvz);
    }
    if constexpr (Remap) {
      const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
      for_support<S>(s.grid, w, [&](std::size_t i, double N, double, double) {
        f.momentum_r[i] += N * pr;
        f.momentum_z[i] += N * pz;
      });
    }
  };
  if constexpr (Remap) {
    store_velocity_changes(s);
    if constexpr (S == 2) {
      remap_linear_strips(s, blend_and_move);
    } else {
      remap_gimp_strips<S>(s, blend_and_move, update);
    }
    s.momentum_remapped = true;
  } else {
    gather_particles<S>(s, blend_and_move, update);
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
      for_support<S>(s.grid, w, [&](std::size_t i, double N, double, double) {
        vr += N * f.velocity_r[i];
        vz += N * f.velocity_z[i];
      });
      move_within_walls(P, p, P.r[p] + dt * vr, P.z[p] + dt * vz, walls, clamped);
    }
    clamps += clamped;
  });
  s.wall_clamps += clamps;
}

using NodalArray = std::vector<double> NodalField::*;

/// The velocity gradient's five sums by support rows (mpm/support_row.hpp): row b adds
/// its nodal velocity rows times N = s_r s_z,b and G = (s_r' s_z,b, s_r s_z,b').
template <class Vec>
struct GradientRows {
  Vec rr{}, rz{}, zr{}, zz{}, tt{};

  void add(Vec wr, Vec gr, double wz, double gz, Vec vr_row, Vec vz_row) {
    const Vec N = wr * wz, Gr = gr * wz, Gz = wr * gz;
    rr += vr_row * Gr;
    rz += vr_row * Gz;
    zr += vz_row * Gr;
    zz += vz_row * Gz;
    tt += vr_row * N;
  }
  /// The rows summed; L_θθ = Σ S v_r / r.
  VelocityGradient gradient(double inverse_r) const {
    VelocityGradient L;
    L.rr = row_sum(rr);
    L.rz = row_sum(rz);
    L.zr = row_sum(zr);
    L.zz = row_sum(zz);
    L.tt = row_sum(tt) * inverse_r;
    return L;
  }
};

/// Δε_p, spin and V_p of one particle from the nodal velocities (vr, vz) of its field.
template <int S>
inline void strain_increment_of(const Grid& grid, const ShapeWeights& w, const double* __restrict vr,
                                const double* __restrict vz, double dt, Voigt& de, double& spin_dt, double& volume) {
  if (rows_fit<S>(grid, w)) {  // a row of nodes per vector (mpm/support_row.hpp)
    using Vec = SupportRow<S>;
    const Vec wr = load_support_row<S>(w.wr), gr = load_support_row<S>(w.gr);
    GradientRows<Vec> sums;
    for (int b = 0; b < S; ++b) {
      const std::size_t i = grid.node(w.node_r, w.node_z + b);
      sums.add(wr, gr, w.wz[b], w.gz[b], load_support_row<S>(vr + i), load_support_row<S>(vz + i));
    }
    apply_velocity_gradient(sums.gradient(w.inverse_r), dt, de, spin_dt, volume);
    return;
  }
  // A GIMP edge particle: node by node.
  const auto node = [&](int a, int b) { return grid.node(w.node_r, w.node_z + b) + static_cast<std::size_t>(a); };
  apply_velocity_gradient(velocity_gradient<S>(w, node, vr, vz), dt, de, spin_dt, volume);
}

/// strain_increment_of for a GIMP cell's lower and upper particle (consecutive, the
/// same support columns, the upper one node row up), their four node rows read once
/// for both; each particle's sums take the same terms in the same order (the same bits).
inline void strain_increments_of_pair(const Grid& grid, const ShapeWeights& lower, const ShapeWeights& upper,
                                      const double* __restrict vr, const double* __restrict vz, double dt,
                                      Voigt& de_lower, double& spin_lower, double& volume_lower, Voigt& de_upper,
                                      double& spin_upper, double& volume_upper) {
  const Row wr_l = load_support_row<3>(lower.wr), gr_l = load_support_row<3>(lower.gr);
  const Row wr_u = load_support_row<3>(upper.wr), gr_u = load_support_row<3>(upper.gr);
  GradientRows<Row> sums_l, sums_u;
  const std::size_t first = grid.node(lower.node_r, lower.node_z);
  const auto row_stride = static_cast<std::size_t>(grid.r.nodes());
  for (int row = 0; row < 4; ++row) {
    const std::size_t i = first + row_stride * static_cast<std::size_t>(row);
    const Row vr_row = load_support_row<3>(vr + i), vz_row = load_support_row<3>(vz + i);
    if (row < 3) sums_l.add(wr_l, gr_l, lower.wz[row], lower.gz[row], vr_row, vz_row);
    if (row > 0) sums_u.add(wr_u, gr_u, upper.wz[row - 1], upper.gz[row - 1], vr_row, vz_row);
  }
  apply_velocity_gradient(sums_l.gradient(lower.inverse_r), dt, de_lower, spin_lower, volume_lower);
  apply_velocity_gradient(sums_u.gradient(upper.inverse_r), dt, de_upper, spin_upper, volume_upper);
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
  const Prefetch prefetch(P.size());
  for (std::size_t k = first; k < last; ++k) {
    if (prefetch.on() && k + kPrefetchAhead < last) prefetch.lines(weights + index(k + kPrefetchAhead));
    const std::size_t p = index(k);
    if (p >= n) continue;
    const std::uint8_t field = s.bodies[P.body[p]].field;
    const NodalField& f = grid.fields[field];
    if constexpr (S == 3) {  // a GIMP cell's lower and upper particle as a pair
      if (k + 1 < last && rows_fit<S>(grid, weights[p])) {
        const std::size_t q = index(k + 1);
        const ShapeWeights &w = weights[p], &v = weights[q];
        if (q < n && stacked_pair(w, v) && s.bodies[P.body[q]].field == field) {
          strain_increments_of_pair(grid, w, v, (f.*velocity_r).data(), (f.*velocity_z).data(), dt, strain_increment[p],
                                    spin[p], volume[p], strain_increment[q], spin[q], volume[q]);
          ++k;
          continue;
        }
      }
    }
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
