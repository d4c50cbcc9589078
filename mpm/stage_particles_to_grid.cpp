/// Particle → grid transfers. Each scatter runs through ParticleBins, so every
/// nodal sum has one fixed order (deterministic under OpenMP).
#include <algorithm>
#include <span>

#include "mpm/internal_force.hpp"
#include "mpm/prefetch.hpp"
#include "mpm/stages.hpp"
#include "mpm/support_row.hpp"

namespace ffp::mpm {

namespace {

/// m_i += S_ip m_p and p_i += S_ip m_p v_p for one particle.
template <int S>
inline void add_mass_momentum(const Simulation& s, std::size_t p, NodalField& f) {
  const Particles& P = s.particles;
  const double m = P.mass[p], pr = m * P.vr[p], pz = m * P.vz[p];
  for_support<S>(s.grid, s.weights[p], [&](std::size_t i, double N, double, double) {
    f.mass[i] += N * m;
    f.momentum_r[i] += N * pr;
    f.momentum_z[i] += N * pz;
  });
}

template <int S>
void scatter_mass_momentum(Simulation& s) {
  const Particles& P = s.particles;
  s.bins.scatter([&](std::size_t p) { add_mass_momentum<S>(s, p, s.grid.fields[s.bodies[P.body[p]].field]); });
}

/// The components of σ_p the internal force takes: with strain smoothing, its cell's mean stress.
inline ForceStress particle_force_stress(const Simulation& s, std::size_t p, StrainSmoothing smoothing,
                                         const std::vector<double>& limit) {
  const Particles& P = s.particles;
  const Voigt& own = P.stress[p];
  if (smoothing != StrainSmoothing::off && takes_part_in_cell_means(P, p, limit)) {
    const std::size_t k = s.cell[p] * s.bodies.size() + P.body[p];
    if (smoothing == StrainSmoothing::full) {
      const Voigt& cell = s.cell_stress[k];  // the cell's whole mean stress (the transpose of Δε_p ← Δε̄_c)
      return {cell[0], cell[1], cell[2], cell[3]};
    }
    return b_bar_force_stress(own, s.cell_mean_stress[k]);
  }
  return own_force_stress(own);
}

/// f_i^int −= V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r] for one particle.
template <int S>
inline void add_particle_internal_force(Simulation& s, std::size_t p, NodalField& f, StrainSmoothing smoothing,
                                        const std::vector<double>& limit) {
  const ShapeWeights& w = s.weights[p];
  const auto node = [&](int a, int b) { return s.grid.node(w.node_r, w.node_z + b) + static_cast<std::size_t>(a); };
  add_internal_force<S>(w, particle_force_stress(s, p, smoothing, limit), s.particles.volume[p], node,
                        f.internal_force_r.data(), f.internal_force_z.data());
}

template <int S>
void scatter_internal_forces(Simulation& s) {
  const StrainSmoothing smoothing = s.settings.strain_smoothing;
  const bool smoothed = smoothing != StrainSmoothing::off;
  const std::vector<double> limit = smoothed ? cell_mean_density_limits(s) : std::vector<double>{};
  s.bins.scatter([&](std::size_t p) {
    add_particle_internal_force<S>(s, p, s.grid.fields[s.bodies[s.particles.body[p]].field], smoothing, limit);
  });
}

/// add_mass_momentum and add_internal_force in one visit of the support, a
/// support row per vector where the rows fit (mpm/support_row.hpp): each node's
/// five sums take the same terms as the two apart, formed with the weights
/// factored by rows (equal up to rounding).
template <int S>
inline void add_mass_momentum_force(const Simulation& s, std::size_t p, NodalField& f, StrainSmoothing smoothing,
                                    const std::vector<double>& limit) {
  const Particles& P = s.particles;
  const ShapeWeights& w = s.weights[p];
  const double m = P.mass[p], pr = m * P.vr[p], pz = m * P.vz[p];
  const ForceStress sig = particle_force_stress(s, p, smoothing, limit);
  const double V = P.volume[p], s_rr = sig.rr, s_zz = sig.zz, s_rz = sig.rz, hoop = sig.tt * w.inverse_r;
  if (rows_fit<S>(s.grid, w)) {
    // Row by row (mpm/support_row.hpp), with S_ip = s_r,a s_z,b and G_ip = (s_r,a' s_z,b,
    // s_r,a s_z,b') factored: f_r,i = −V (σ_rr G_r + σ_rz G_z + σ_θθ S/r)
    //   = s_z,b · [−V (σ_rr s_r' + σ_θθ s_r/r)] + s_z,b' · [−V σ_rz s_r], and so on.
    using Vec = SupportRow<S>;
    const Vec wr = load_support_row<S>(w.wr), gr = load_support_row<S>(w.gr);
    const Vec mass_r = m * wr, momentum_rr = pr * wr, momentum_zr = pz * wr;
    const Vec force_r_w = -V * (s_rr * gr + hoop * wr), force_r_g = -V * s_rz * wr;
    const Vec force_z_w = -V * s_rz * gr, force_z_g = -V * s_zz * wr;
    auto add = [](std::vector<double>& x, std::size_t i, Vec term) {
      store_support_row<S>(&x[i], load_support_row<S>(&x[i]) + term);
    };
    for (int b = 0; b < S; ++b) {
      const std::size_t i = s.grid.node(w.node_r, w.node_z + b);
      const double wz = w.wz[b], gz = w.gz[b];
      add(f.mass, i, mass_r * wz);
      add(f.momentum_r, i, momentum_rr * wz);
      add(f.momentum_z, i, momentum_zr * wz);
      add(f.internal_force_r, i, force_r_w * wz + force_r_g * gz);
      add(f.internal_force_z, i, force_z_w * wz + force_z_g * gz);
    }
    return;
  }
  for_support<S>(s.grid, w, [&](std::size_t i, double N, double Gr, double Gz) {  // a GIMP edge particle
    f.mass[i] += N * m;
    f.momentum_r[i] += N * pr;
    f.momentum_z[i] += N * pz;
    f.internal_force_r[i] -= V * (s_rr * Gr + s_rz * Gz + hoop * N);
    f.internal_force_z[i] -= V * (s_rz * Gr + s_zz * Gz);
  });
}

/// The fused scatter of one strip's particles for linear hats. A particle's four nodes
/// are its cell's, and consecutive particles of a strip mostly share a cell (they are
/// seeded cell by cell), so a run of them adds to its nodes' five sums in registers:
/// the node rows are loaded at the run's first particle and stored after its last, and
/// each sum takes the same terms in the same order as with one read-modify-write per
/// particle (the same bits). The scatter's cost is its loads and stores (llvm-mca,
/// Zen 3 model: the load-store unit is the busiest resource); a run of four makes a
/// quarter of the nodal ones. Each sum holds both node rows (lanes 0–1 the lower, 2–3
/// the upper), so that the five stay in registers.
void scatter_linear_strip(Simulation& s, std::span<const std::uint32_t> particles, StrainSmoothing smoothing,
                          const std::vector<double>& limit) {
  const Particles& P = s.particles;
  const std::size_t nodes_r = static_cast<std::size_t>(s.grid.r.nodes());
  constexpr int kNone = -1;
  int run_field = kNone;
  std::size_t run_node = 0;  // the run's first node (its cell's lower left)
  double* arrays[5] = {};    // the run field's mass, momentum r, z, internal force r, z
  Row sums[5] = {};          // their sums at the run's two node rows
  auto both_rows = [](Pair x) { return __builtin_shufflevector(x, x, 0, 1, 0, 1); };
  auto store_run = [&] {
    for (int a = 0; a < 5; ++a) {
      store_support_row<2>(arrays[a] + run_node, __builtin_shufflevector(sums[a], sums[a], 0, 1));
      store_support_row<2>(arrays[a] + run_node + nodes_r, __builtin_shufflevector(sums[a], sums[a], 2, 3));
    }
  };
  const Prefetch prefetch(P.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    prefetch.ahead(s.weights.data(), particles, k);
    const std::uint32_t p = particles[k];
    const ShapeWeights& w = s.weights[p];
    const int field = s.bodies[P.body[p]].field;
    const std::size_t node = s.grid.node(w.node_r, w.node_z);
    if (field != run_field || node != run_node) {
      if (run_field != kNone) store_run();
      NodalField& f = s.grid.fields[static_cast<std::size_t>(field)];
      arrays[0] = f.mass.data();
      arrays[1] = f.momentum_r.data();
      arrays[2] = f.momentum_z.data();
      arrays[3] = f.internal_force_r.data();
      arrays[4] = f.internal_force_z.data();
      run_field = field;
      run_node = node;
      for (int a = 0; a < 5; ++a)
        sums[a] = __builtin_shufflevector(load_support_row<2>(arrays[a] + node),
                                          load_support_row<2>(arrays[a] + node + nodes_r), 0, 1, 2, 3);
    }
    // The terms of add_mass_momentum_force's rows (S = 2), both rows at once.
    const double m = P.mass[p], pr = m * P.vr[p], pz = m * P.vz[p];
    const ForceStress sig = particle_force_stress(s, p, smoothing, limit);
    const double V = P.volume[p], s_rr = sig.rr, s_zz = sig.zz, s_rz = sig.rz, hoop = sig.tt * w.inverse_r;
    const Pair wr = load_support_row<2>(w.wr), gr = load_support_row<2>(w.gr);
    const Row wz{w.wz[0], w.wz[0], w.wz[1], w.wz[1]}, gz{w.gz[0], w.gz[0], w.gz[1], w.gz[1]};
    const Row mass_r = both_rows(m * wr), momentum_rr = both_rows(pr * wr), momentum_zr = both_rows(pz * wr);
    const Row force_r_w = both_rows(-V * (s_rr * gr + hoop * wr)), force_r_g = both_rows(-V * s_rz * wr);
    const Row force_z_w = both_rows(-V * s_rz * gr), force_z_g = both_rows(-V * s_zz * wr);
    sums[0] = sums[0] + mass_r * wz;
    sums[1] = sums[1] + momentum_rr * wz;
    sums[2] = sums[2] + momentum_zr * wz;
    sums[3] = sums[3] + (force_r_w * wz + force_r_g * gz);
    sums[4] = sums[4] + (force_z_w * wz + force_z_g * gz);
  }
  if (run_field != kNone) store_run();
}

/// What add_mass_momentum_force's row terms are formed from, for one GIMP particle.
struct GimpParticleTerms {
  const ShapeWeights* w;
  double m, pr, pz, V, s_rr, s_zz, s_rz, hoop;
};
inline GimpParticleTerms gimp_particle_terms(const Simulation& s, std::size_t p, StrainSmoothing smoothing,
                                             const std::vector<double>& limit) {
  const Particles& P = s.particles;
  const ShapeWeights& w = s.weights[p];
  const double m = P.mass[p];
  const ForceStress sig = particle_force_stress(s, p, smoothing, limit);
  return {&w, m, m * P.vr[p], m * P.vz[p], P.volume[p], sig.rr, sig.zz, sig.rz, sig.tt * w.inverse_r};
}

/// Two consecutive GIMP particles of a strip on the same support columns, the second
/// one node row up (a cell's lower and upper particle, as seeded): their four node
/// rows take one read-modify-write per nodal array instead of three and three, the
/// lower particle's term added before the upper's, as one by one (the same bits).
/// Array by array, so that only the two particles' factors of that array are live.
inline void add_gimp_pair(Grid& grid, NodalField& f, const GimpParticleTerms& lower, const GimpParticleTerms& upper) {
  const std::size_t first = grid.node(lower.w->node_r, lower.w->node_z);
  const auto row_stride = static_cast<std::size_t>(grid.r.nodes());
  // x_row += t_lower(row) + t_upper(row − 1), the terms from row factors (u, v):
  // row b's term is u s_z,b (+ v s_z,b' for the forces).
  auto add_rows = [&](double* x, Row u_lower, Row v_lower, Row u_upper, Row v_upper, bool with_gradient) {
    for (int row = 0; row < 4; ++row) {
      double* at = x + first + row_stride * static_cast<std::size_t>(row);
      Row sum = load_support_row<3>(at);
      if (row < 3) {
        const double wz = lower.w->wz[row], gz = lower.w->gz[row];
        sum = with_gradient ? sum + (u_lower * wz + v_lower * gz) : sum + u_lower * wz;
      }
      if (row > 0) {
        const double wz = upper.w->wz[row - 1], gz = upper.w->gz[row - 1];
        sum = with_gradient ? sum + (u_upper * wz + v_upper * gz) : sum + u_upper * wz;
      }
      store_support_row<3>(at, sum);
    }
  };
  const Row wr_l = load_support_row<3>(lower.w->wr), gr_l = load_support_row<3>(lower.w->gr);
  const Row wr_u = load_support_row<3>(upper.w->wr), gr_u = load_support_row<3>(upper.w->gr);
  const Row none{};
  add_rows(f.mass.data(), lower.m * wr_l, none, upper.m * wr_u, none, false);
  add_rows(f.momentum_r.data(), lower.pr * wr_l, none, upper.pr * wr_u, none, false);
  add_rows(f.momentum_z.data(), lower.pz * wr_l, none, upper.pz * wr_u, none, false);
  add_rows(f.internal_force_r.data(), -lower.V * (lower.s_rr * gr_l + lower.hoop * wr_l), -lower.V * lower.s_rz * wr_l,
           -upper.V * (upper.s_rr * gr_u + upper.hoop * wr_u), -upper.V * upper.s_rz * wr_u, true);
  add_rows(f.internal_force_z.data(), -lower.V * lower.s_rz * gr_l, -lower.V * lower.s_zz * wr_l,
           -upper.V * upper.s_rz * gr_u, -upper.V * upper.s_zz * wr_u, true);
}

/// The fused scatter of one strip's particles for GIMP: a cell's lower and upper
/// particle as a pair (add_gimp_pair), any other one by one.
void scatter_gimp_strip(Simulation& s, std::span<const std::uint32_t> particles, StrainSmoothing smoothing,
                        const std::vector<double>& limit) {
  const Particles& P = s.particles;
  auto field_of = [&](std::size_t p) { return s.bodies[P.body[p]].field; };
  const Prefetch prefetch(P.size());
  for (std::size_t k = 0; k < particles.size();) {
    prefetch.ahead(s.weights.data(), particles, k);  // and the next: a pair takes two
    prefetch.ahead(s.weights.data(), particles, k + 1);
    const std::size_t p = particles[k];
    const ShapeWeights& w = s.weights[p];
    NodalField& f = s.grid.fields[field_of(p)];
    if (k + 1 < particles.size() && rows_fit<3>(s.grid, w)) {
      const std::size_t q = particles[k + 1];
      const ShapeWeights& v = s.weights[q];
      if (stacked_pair(w, v) && field_of(q) == field_of(p)) {
        add_gimp_pair(s.grid, f, gimp_particle_terms(s, p, smoothing, limit),
                      gimp_particle_terms(s, q, smoothing, limit));
        k += 2;
        continue;
      }
    }
    add_mass_momentum_force<3>(s, p, f, smoothing, limit);
    ++k;
  }
}

/// map_particles_to_grid, smooth_mean_stress and compute_internal_forces in one
/// pass over the particles, strip by strip: the strip's cell means (its cells are
/// its own), then per particle its mass, momentum and internal-force terms. Every
/// nodal sum and cell sum takes its terms in the same order as the three stages
/// apart (ParticleBins order); the nodal terms are formed row by row (above).
template <int S>
void scatter_mass_momentum_forces(Simulation& s) {
  const StrainSmoothing smoothing = s.settings.strain_smoothing;
  const bool smoothed = smoothing != StrainSmoothing::off;
  const std::vector<double> limit = smoothed ? cell_mean_density_limits(s) : std::vector<double>{};
  if (smoothed) clear_cell_mean_stress(s);
  s.bins.scatter_strips([&](int strip, std::span<const std::uint32_t> particles) {
    if (smoothed) strip_cell_mean_stress(s, strip, particles, limit);
    if constexpr (S == 2) {
      scatter_linear_strip(s, particles, smoothing, limit);
    } else {
      scatter_gimp_strip(s, particles, smoothing, limit);
    }
  });
}

/// The three stages may run as one pass only if nothing else runs between them.
bool forces_fuse_with_mapping(const Simulation& s) {
  const std::vector<Stage>& stages = s.stages.items();
  const auto first = std::ranges::find(stages, "map_particles_to_grid", &Stage::name);
  const auto last = std::ranges::find(stages, "compute_internal_forces", &Stage::name);
  if (first == stages.end() || last == stages.end() || last < first) return false;
  return std::all_of(first + 1, last, [&](const Stage& stage) {
    return stage.name == "smooth_mean_stress" && s.settings.strain_smoothing != StrainSmoothing::off;
  });
}

template <int S>
void scatter_momentum(Simulation& s) {
  const Particles& P = s.particles;
  s.bins.scatter([&](std::size_t p) {
    NodalField& f = s.grid.fields[s.bodies[P.body[p]].field];
    const double pr = P.mass[p] * P.vr[p], pz = P.mass[p] * P.vz[p];
    for_support<S>(s.grid, s.weights[p], [&](std::size_t i, double N, double, double) {
      f.momentum_r[i] += N * pr;
      f.momentum_z[i] += N * pz;
    });
  });
}

}  // namespace

void reset_grid(Simulation& s) {
  for (NodalField& f : s.grid.fields) f.reset();
}

// m_i = Σ_p S_ip m_p ;  p_i = Σ_p S_ip m_p v_p
// (and, when the stage list runs smooth_mean_stress and compute_internal_forces
// right after, those two as well, in the same pass: scatter_mass_momentum_forces)
void map_particles_to_grid(Simulation& s) {
  s.internal_forces_mapped = forces_fuse_with_mapping(s);
  if (s.internal_forces_mapped) {
    if (uses_linear_hats(s)) {
      scatter_mass_momentum_forces<2>(s);
    } else {
      scatter_mass_momentum_forces<3>(s);
    }
  } else if (uses_linear_hats(s)) {
    scatter_mass_momentum<2>(s);
  } else {
    scatter_mass_momentum<3>(s);
  }
}

// f_i^int = −Σ_p V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r]   (axisymmetric, per radian;
// the hoop term is the σ_θθ/r part of div σ in cylindrical coordinates).
// With strain smoothing σ_p carries its cell's mean stress (smooth_mean_stress).
void compute_internal_forces(Simulation& s) {
  if (s.internal_forces_mapped) {  // made by map_particles_to_grid
    s.internal_forces_mapped = false;
    return;
  }
  if (uses_linear_hats(s)) {
    scatter_internal_forces<2>(s);
  } else {
    scatter_internal_forces<3>(s);
  }
}

// MUSL (Sulsky et al. 1995): p_i = Σ_p S_ip m_p v_p^{n+1};  v_i = p_i/m_i
// (p_i is summed by update_particles as it updates each particle, unless a stage
// list without it got here: then the sum is made here, in the same order).
void map_velocities_to_grid(Simulation& s) {
  if (!s.momentum_remapped) {
    for (NodalField& f : s.grid.fields) {
      std::fill(f.momentum_r.begin(), f.momentum_r.end(), 0.0);
      std::fill(f.momentum_z.begin(), f.momentum_z.end(), 0.0);
    }
    if (uses_linear_hats(s)) {
      scatter_momentum<2>(s);
    } else {
      scatter_momentum<3>(s);
    }
  }
  s.momentum_remapped = false;
  const double floor = s.mass_floor_kg;
  for (NodalField& f : s.grid.fields) {
    const std::size_t n = f.size();
    FFP_OMP(omp parallel for schedule(static) if (n >= kParallelMinimum))
    for (std::size_t i = 0; i < n; ++i) {
      const bool filled = f.mass[i] > floor;
      f.velocity_r[i] = filled ? f.momentum_r[i] / f.mass[i] : 0.0;
      f.velocity_z[i] = filled ? f.momentum_z[i] / f.mass[i] : 0.0;
    }
  }
}

}  // namespace ffp::mpm
