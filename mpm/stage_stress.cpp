/// Stress-side stages: anti-locking smoothing and the constitutive update.
#include <algorithm>
#include <optional>
#include <span>
#include <vector>

#include "mpm/parallel.hpp"
#include "mpm/prefetch.hpp"
#include "mpm/stages.hpp"
#include "mpm/velocity_gradient.hpp"

namespace ffp::mpm {

// f(p, slot) for each particle of a strip that takes part in the strain means, in
// strip order (slot = cell·bodies + body); a subcycled body smooths its own.
template <class F>
void for_strain_mean_particles(const Simulation& s, std::span<const std::uint32_t> strip,
                               const std::vector<double>& limit, F&& f) {
  const std::size_t bodies = s.bodies.size();
  for (const std::uint32_t p : strip) {
    if (p >= s.main_step_end || !takes_part_in_cell_means(s.particles, p, limit)) continue;
    f(p, s.cell[p] * bodies + s.particles.body[p]);
  }
}

// Two sums per slot, x_k += a and y_k += b·c, over a strip's particles in order. A
// run of particles in one slot (they are seeded cell by cell) sums in registers:
// loaded at the run's first particle and stored after its last, the same terms in
// the same order as a read-modify-write per particle (the same bits), without the
// store-to-load chain through memory from one particle to the next.
class SlotSums {
 public:
  SlotSums(std::vector<double>& x, std::vector<double>& y) : x_(x.data()), y_(y.data()) {}
  /// x_k += a, y_k += b.
  void add(std::size_t k, double a, double b) {
    select(k);
    x_sum_ += a;
    y_sum_ += b;
  }
  /// x_k += a, y_k += b·c, formed as the expression y_k += b * c (a product passed
  /// in, rounded, would not fuse with the sum as there).
  void add_product(std::size_t k, double a, double b, double c) {
    select(k);
    x_sum_ += a;
    y_sum_ += b * c;
  }
  void store() {
    if (slot_ == kNone) return;
    x_[slot_] = x_sum_;
    y_[slot_] = y_sum_;
  }

 private:
  void select(std::size_t k) {
    if (k == slot_) return;
    store();
    slot_ = k;
    x_sum_ = x_[k];
    y_sum_ = y_[k];
  }
  static constexpr std::size_t kNone = ~std::size_t{0};
  double* x_;
  double* y_;
  std::size_t slot_ = kNone;
  double x_sum_ = 0.0, y_sum_ = 0.0;
};

// Strain smoothing (Al-Kafaji 2013; Yerro 2015): per cell c and body,
//   Δε̄_v,c = Σ_{p∈c} V_p Δε_v,p / Σ_{p∈c} V_p   (V_p = r_p A_p: axisymmetric volume weights)
//   Δε_p ← Δε_p + (Δε̄_v,c − Δε_v,p)/3 · I
// over the particles that take part in the means (takes_part_in_cell_means: not a
// disconnected granular particle). Volume weights, the integration weights of the
// internal force, keep the operator the transpose of smooth_mean_stress (mass weights
// made an E = 1 kPa block collapsing at Courant 1 go unstable); the inflated particles
// are kept out by the exclusion and by holding their volume (update_stresses).
void smooth_volumetric_strain(Simulation& s) {
  const Particles& P = s.particles;
  const std::size_t bodies = s.bodies.size();
  const std::size_t slots = s.grid.cells() * bodies;
  const std::vector<double> limit = cell_mean_density_limits(s);
  s.cell_volume.assign(slots, 0.0);
  s.cell_volumetric_strain.assign(slots, 0.0);
  // Per strip (whose cells no other strip touches): the cell sums, then the
  // shift of the same particles, in one pass over the strip's data.
  const bool make_strain = s.strain_deferred;
  s.strain_deferred = false;
  s.bins.for_each_strip([&](int, std::span<const std::uint32_t> strip) {
    // Each particle's increment is its own (no sums across particles): the same
    // bits made here in strip order as in compute_strain_increments' index order.
    if (make_strain) strain_increments_of_strip(s, strip);
    SlotSums sums(s.cell_volume, s.cell_volumetric_strain);
    for_strain_mean_particles(s, strip, limit, [&](std::size_t p, std::size_t k) {
      sums.add_product(k, P.volume[p], P.volume[p], trace(s.strain_increment[p]));
    });
    sums.store();
    for_strain_mean_particles(s, strip, limit, [&](std::size_t p, std::size_t k) {
      Voigt& de = s.strain_increment[p];
      const double shift = (s.cell_volumetric_strain[k] / s.cell_volume[k] - trace(de)) / 3.0;
      de[0] += shift;
      de[1] += shift;
      de[2] += shift;
    });
  });
}

// Full smoothing (strain_smoothing full): per cell c and body the whole tensor,
//   Δε̄_c = Σ_{p∈c} V_p Δε_p / Σ_{p∈c} V_p,   Δε_p ← Δε̄_c,
// over the same particles and weights as the volumetric smoothing. Every particle of
// a cell then strains as the cell's one point: the mixed integration of Anura3D
// (MPMStrainSmoothing.FOR, one Gauss point per element, its strain and stress given
// to every material point of a filled element), the cell-mean of the particle B
// matrices B̄_c = Σ V_p B_p / V_c in place of each B_p. It removes the isochoric
// constraints the 3×3 particle quadrature adds per cell in plastic flow; the spin
// (Jaumann) and the volume update J stay the particle's own.
void smooth_strain_increment(Simulation& s) {
  const Particles& P = s.particles;
  const std::size_t bodies = s.bodies.size();
  const std::size_t slots = s.grid.cells() * bodies;
  const std::vector<double> limit = cell_mean_density_limits(s);
  s.cell_volume.assign(slots, 0.0);
  s.cell_strain_increment.assign(slots, Voigt::Zero());
  s.bins.for_each_strip([&](int, std::span<const std::uint32_t> strip) {
    for_strain_mean_particles(s, strip, limit, [&](std::size_t p, std::size_t k) {
      s.cell_volume[k] += P.volume[p];
      s.cell_strain_increment[k] += P.volume[p] * s.strain_increment[p];
    });
    for_strain_mean_particles(s, strip, limit, [&](std::size_t p, std::size_t k) {
      s.strain_increment[p] = s.cell_strain_increment[k] / s.cell_volume[k];
    });
  });
}

// The transpose of strain smoothing, for the internal force (B-bar, Hughes 1980):
//   σ̄_m,c = Σ_{p∈c} V_p tr(σ_p)/3 / Σ_{p∈c} V_p,  used in place of each particle's tr(σ_p)/3
// (same particles and weights as the strain). Smoothing only the strain makes the
// discrete stiffness unsymmetric; measured here, a ν = 0.49 block then gains energy
// even at Courant 0.5, and with both halves it is stable at Courant 1 (linear and GIMP).
// Full smoothing: the whole σ̄_c = Σ V_p σ_p / V_c in place of σ_p, since
// Σ_p V_p B_p^T σ̄_c = V_c B̄_c^T σ̄_c = Σ_p V_p B̄_c^T σ_p (the transpose of Δε_p ← Δε̄_c).
void smooth_mean_stress(Simulation& s) {
  if (s.internal_forces_mapped) return;  // map_particles_to_grid made the means with the forces
  const std::vector<double> limit = cell_mean_density_limits(s);
  clear_cell_mean_stress(s);
  s.bins.for_each_strip(
      [&](int strip, std::span<const std::uint32_t> particles) { strip_cell_mean_stress(s, strip, particles, limit); });
}

void clear_cell_mean_stress(Simulation& s) {
  const std::size_t slots = s.grid.cells() * s.bodies.size();
  s.cell_volume.assign(slots, 0.0);
  if (s.settings.strain_smoothing == StrainSmoothing::full) {
    s.cell_stress.assign(slots, Voigt::Zero());
  } else {
    s.cell_mean_stress.assign(slots, 0.0);
  }
}

void strip_cell_mean_stress(Simulation& s, int strip, std::span<const std::uint32_t> particles,
                            const std::vector<double>& limit) {
  const Particles& P = s.particles;
  const std::size_t bodies = s.bodies.size();
  if (s.settings.strain_smoothing == StrainSmoothing::full) {
    for (const std::uint32_t p : particles) {
      if (!takes_part_in_cell_means(P, p, limit)) continue;
      const std::size_t k = s.cell[p] * bodies + P.body[p];
      s.cell_volume[k] += P.volume[p];
      s.cell_stress[k] += P.volume[p] * P.stress[p];
    }
    s.bins.for_each_cell_of_strip(strip, [&](std::size_t cell) {
      for (std::size_t k = cell * bodies; k < (cell + 1) * bodies; ++k)
        if (s.cell_volume[k] > 0.0) s.cell_stress[k] /= s.cell_volume[k];
    });
    return;
  }
  SlotSums sums(s.cell_volume, s.cell_mean_stress);
  const Prefetch prefetch(P.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    prefetch.ahead(P.stress.data(), particles, k);
    const std::uint32_t p = particles[k];
    if (!takes_part_in_cell_means(P, p, limit)) continue;
    sums.add(s.cell[p] * bodies + P.body[p], P.volume[p], P.volume[p] * trace(P.stress[p]) / 3.0);
  }
  sums.store();
  s.bins.for_each_cell_of_strip(strip, [&](std::size_t cell) {
    for (std::size_t k = cell * bodies; k < (cell + 1) * bodies; ++k)
      if (s.cell_volume[k] > 0.0) s.cell_mean_stress[k] /= s.cell_volume[k];
  });
}

std::vector<double> cell_mean_density_limits(const Simulation& s) {
  std::vector<double> limit(s.bodies.size());
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const MaterialGroup& g = s.groups[s.bodies[b].group];
    limit[b] = g.disconnected_below_kg_m3;  // 0 for a body that is not granular: every particle takes part
  }
  return limit;
}

namespace {

/// update_time_step runs right after update_stresses: the stress pass forms the CFL
/// maxima of the particles it has in cache, and the time step makes no pass of its own.
bool time_step_follows(const Simulation& s) {
  const std::vector<Stage>& stages = s.stages.items();
  const auto stress = std::ranges::find(stages, "update_stresses", &Stage::name);
  return stress != stages.end() && stress + 1 != stages.end() &&
         ((stress + 1)->name == "update_time_step" || (stress + 1)->name == "check_time_step");
}

/// One thread's maxima, on a cache line of its own.
struct alignas(64) ThreadSignal {
  SignalMaxima maxima;
};

}  // namespace

// Jaumann rate (objective for large rotations) before the law (rotate_by_spin,
// mpm/velocity_gradient.hpp). Then σ ← law(σ, Δε) for each material group, one batch call per chunk, and
// σ ← 0 where a granular particle has lost grain contact (ρ_p below the group's limit);
// then, if the time step follows, the batch's CFL maxima (Simulation::stressed_signal).
void update_stresses(Simulation& s) {
  constexpr std::size_t chunk = 512;
  std::vector<Voigt>& stress = s.particles.stress;
  std::vector<Voigt>& strain = s.particles.strain;
  const bool signal = time_step_follows(s);
  s.stressed_signal.assign(signal ? s.groups.size() : 0, std::nullopt);
  // One per thread of the batches' team, which has at most thread_count() members.
  std::vector<ThreadSignal> thread_signal(signal ? static_cast<std::size_t>(std::max(1, thread_count())) : 0);
  for (std::size_t group = 0; group < s.groups.size(); ++group) {
    MaterialGroup& g = s.groups[group];
    if (g.begin >= s.main_step_end) continue;  // a subcycled body: stressed in its own substeps
    std::fill(thread_signal.begin(), thread_signal.end(), ThreadSignal{});
    // Balanced batches (ParticleBins::for_each_particle_batch): a plastic return costs
    // several elastic updates, and the returns gather about the cone, in one part.
    s.bins.for_each_particle_batch(
        g.begin, g.end, s.particles.size(), chunk, g.size() >= kParallelMinimum,
        [&](std::size_t first, std::size_t last) {
          for (std::size_t p = first; p < last; ++p) {
            rotate_by_spin(stress[p], s.spin_dt[p]);
            strain[p] += s.strain_increment[p];  // after smoothing: the strain the law sees
          }
          g.update(first, last, stress, s.strain_increment, s.dt_s);
          if (g.disconnected_below_kg_m3 > 0.0) {
            // ρ_p = m_p/V_p < ρ_disconnected: the grains no longer touch, σ = 0, and
            // V_p is held at m_p/ρ_disconnected: grains apart take up no more room
            // than their loosest packing when they meet again. Without it, particles
            // pushed off the axis to the shaft grew to J = V/V0 = 10, 20 and 36 at
            // h = 1, 0.5 and 0.25 cm (their hoop stretch r/r0 ∝ 1/h), and a
            // re-compacted one stayed stress-free long after its grains touched.
            const double limit = g.disconnected_below_kg_m3;
            for (std::size_t p = first; p < last; ++p) {
              if (s.particles.mass[p] <= limit * s.particles.volume[p]) {  // at the limit: still apart
                stress[p].setZero();
                s.particles.volume[p] = s.particles.mass[p] / limit;
              }
            }
          }
          if (signal)
            thread_signal[static_cast<std::size_t>(team_member())].maxima.merge(
                signal_maxima(s.particles, first, last));
        });
    if (signal) {
      SignalMaxima maxima;
      for (const ThreadSignal& t : thread_signal) maxima.merge(t.maxima);
      s.stressed_signal[group] = maxima;
    }
  }
}

}  // namespace ffp::mpm
