#pragma once
/// Particle indices binned into strips of grid cells, for race-free and
/// deterministic particle→grid sums under OpenMP.
///
/// Strips are `width` cells wide across the longer grid direction. A particle's
/// support (≤ 3 nodes per direction) reaches at most one node column beyond its
/// strip on either side, so strips two apart never touch a common node. The
/// scatter runs the even strips in parallel, then the odd ones; within a strip
/// particles go in index order. Every node therefore receives its terms in one
/// fixed order — the same for any thread count or schedule — and sums are
/// bit-identical from run to run.
///
/// Each thread keeps its own particles from stage to stage (cache affinity): the
/// strips are cut into parts(), one per thread, of consecutive strips holding
/// about equal numbers of particles, and part t also names the particle indices
/// [particle_range(t)) — as many, and nearly the same particles, since particles
/// are numbered strip by strip (generate_particles) and move less than a strip
/// per step. Every particle stage of a step runs part t on thread t (scatter,
/// for_each_strip, for_each_part), so a particle's data stays in one core's
/// cache; measured with dynamically scheduled strips and index halves, the
/// reference FFP run (6,086 particles, 2.4 MB) gained nothing from a second
/// thread in the shape-function, transfer and smoothing stages.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "mpm/parallel.hpp"

namespace ffp::mpm {

struct ParticleBins {
  static constexpr int width = 4;      ///< cells per strip: > 3 keeps same-colour strips apart with GIMP
  int axis = 0;                        ///< 0: strips of cell columns (along r), 1: of cell rows (along z)
  std::vector<std::uint32_t> offsets;  ///< strip s holds order[offsets[s] .. offsets[s+1])
  std::vector<std::uint32_t> order;    ///< particle indices, strip by strip

  void configure(int cells_r, int cells_z);
  int strips() const { return static_cast<int>(offsets.size()) - 1; }
  /// The strip of a particle in grid cell (i, j).
  std::uint32_t strip_of(int i, int j) const { return static_cast<std::uint32_t>((axis == 0 ? i : j) / width); }
  /// Counting sort of the particles by strip (stable: ascending within a strip).
  void build(std::span<const std::uint32_t> strip_of_particle);

  /// The same sort in two halves, for a caller that counts the strips while it
  /// computes them (one parallel pass fewer): begin_build(n), then for each chunk
  /// t < chunks(), ++counts(t)[strip] over the particles of chunk_range(t)
  /// (chunks may run in parallel), then finish_build(strips).
  void begin_build(std::size_t n);
  int chunks() const { return chunks_; }
  /// The particles of chunk t: the part t of the last build (particle_range), so
  /// that the thread that counts them has them in cache; begin_build(n) made the
  /// parts cover [0, n).
  std::pair<std::size_t, std::size_t> chunk_range(int t) const { return particle_range(t); }
  std::uint32_t* counts(int t) { return counts_.data() + static_cast<std::size_t>(t) * offsets.size(); }
  void finish_build(std::span<const std::uint32_t> strip_of_particle);

  /// fn(p) for every particle, scatter-safe (see above).
  template <class Fn>
  void scatter(Fn&& fn) const {
    scatter_strips([&](int, std::span<const std::uint32_t> particles) {
      for (const std::uint32_t p : particles) fn(static_cast<std::size_t>(p));
    });
  }

  /// fn(strip, particles) strip by strip, `particles` the strip's slice of
  /// `order`, scatter-safe as scatter() (even strips in parallel, then odd):
  /// for a pass that first sums the strip's own cells, then scatters its particles.
  /// One parallel region; each thread takes the strips of its own part.
  template <class Fn>
  void scatter_strips(Fn&& fn) const {
    FFP_OMP(omp parallel if (order.size() >= kParallelMinimum)) {
      for (int colour = 0; colour < 2; ++colour) {
        for (int part = team_member(); part + 1 < static_cast<int>(part_strip_.size()); part += team_size()) {
          const int first = part_strip_[static_cast<std::size_t>(part)];
          const int last = part_strip_[static_cast<std::size_t>(part) + 1];
          for (int s = first + ((first & 1) != colour); s < last; s += 2) fn(s, particles_of(s));
        }
        FFP_OMP(omp barrier)
      }
    }
  }

  /// fn(strip, particles) for every strip at once, `particles` the strip's
  /// slice of `order`: for sums into cells (which no two strips share) and for
  /// a second pass over the same particles that reads those sums, both in one
  /// parallel region while the strip's data is still in cache.
  template <class Fn>
  void for_each_strip(Fn&& fn) const {
    for_each_part([&](int part) {
      const int last = part_strip_[static_cast<std::size_t>(part) + 1];
      for (int s = part_strip_[static_cast<std::size_t>(part)]; s < last; ++s) fn(s, particles_of(s));
    });
  }

  /// fn(part) for every part, part t on thread t of the team (see above): for
  /// particle loops over particle_range(part), in one parallel region.
  template <class Fn>
  void for_each_part(Fn&& fn) const {
    const int count = static_cast<int>(part_strip_.size()) - 1;
    FFP_OMP(omp parallel if (order.size() >= kParallelMinimum))
    for (int part = team_member(); part < count; part += team_size()) fn(part);
  }

  int parts() const { return static_cast<int>(part_particle_.size()) - 1; }
  /// The particle indices of a part (see above); the parts cover [0, n) in order.
  std::pair<std::size_t, std::size_t> particle_range(int part) const {
    return {part_particle_[static_cast<std::size_t>(part)], part_particle_[static_cast<std::size_t>(part) + 1]};
  }

  /// The parts are those of a build of these n particles.
  bool covers(std::size_t n) const { return part_particle_.back() == n && !order.empty(); }

  /// fn(first, last) for the particles of [begin, end) in each part, part t on
  /// thread t, in one parallel region (`parallel`: big enough to share). Before the
  /// first build (the parts do not cover the n particles yet), one part.
  template <class Fn>
  void for_each_particle_range(std::size_t begin, std::size_t end, std::size_t n, [[maybe_unused]] bool parallel,
                               Fn&& fn) const {
    const bool ready = covers(n);
    const int count = ready ? parts() : 1;
    FFP_OMP(omp parallel if (parallel && ready))
    for (int part = team_member(); part < count; part += team_size()) {
      const auto [first, last] = ready ? particle_range(part) : std::pair<std::size_t, std::size_t>{0, n};
      if (std::max(first, begin) < std::min(last, end)) fn(std::max(first, begin), std::min(last, end));
    }
  }

  /// fn(first, last) over batches of at most `batch` particles of [begin, end), for a
  /// stage whose cost per particle varies in space (the plastic returns gather where
  /// the sand yields, in one part): each thread takes its own part's batches in
  /// order, then helps with the others' from where they stand. Any schedule is
  /// fine for a stage whose particles are independent.
  template <class Fn>
  void for_each_particle_batch(std::size_t begin, std::size_t end, std::size_t n, std::size_t batch,
                               [[maybe_unused]] bool parallel, Fn&& fn) const {
    const bool ready = covers(n);
    const int count = ready ? parts() : 1;
    std::vector<std::atomic<std::size_t>> next(static_cast<std::size_t>(count));
    std::vector<std::size_t> stop(static_cast<std::size_t>(count));
    for (int part = 0; part < count; ++part) {
      const auto [first, last] = ready ? particle_range(part) : std::pair<std::size_t, std::size_t>{0, n};
      next[static_cast<std::size_t>(part)] = std::clamp(first, begin, end);
      stop[static_cast<std::size_t>(part)] = std::clamp(last, begin, end);
    }
    FFP_OMP(omp parallel if (parallel && ready))
    for (int k = 0; k < count; ++k) {
      const auto part = static_cast<std::size_t>((team_member() + k) % count);
      for (std::size_t first; (first = next[part].fetch_add(batch)) < stop[part];)
        fn(first, std::min(stop[part], first + batch));
    }
  }

  /// fn(cell) for the grid cells of strip s (cell (i, j) = i + cells_r·j).
  template <class Fn>
  void for_each_cell_of_strip(int s, Fn&& fn) const {
    const int first = s * width;
    const int last_r = axis == 0 ? std::min(first + width, cells_r_) : cells_r_;
    const int last_z = axis == 1 ? std::min(first + width, cells_z_) : cells_z_;
    for (int j = axis == 1 ? first : 0; j < last_z; ++j)
      for (int i = axis == 0 ? first : 0; i < last_r; ++i)
        fn(static_cast<std::size_t>(i) + static_cast<std::size_t>(cells_r_) * static_cast<std::size_t>(j));
  }

 private:
  std::span<const std::uint32_t> particles_of(int s) const {
    const std::size_t first = offsets[static_cast<std::size_t>(s)];
    return {order.data() + first, offsets[static_cast<std::size_t>(s) + 1] - first};
  }
  /// Cut the strips into `parts` runs of about equal particle counts (after a build).
  void partition(int parts);

  std::vector<std::uint32_t> counts_;  ///< per (chunk, strip) during build
  int cells_r_ = 0, cells_z_ = 0;
  int chunks_ = 1;
  std::vector<int> part_strip_{0, 0};             ///< part t holds strips [part_strip_[t], part_strip_[t + 1])
  std::vector<std::size_t> part_particle_{0, 0};  ///< and particles [part_particle_[t], part_particle_[t + 1])
};

}  // namespace ffp::mpm
