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
#include <algorithm>
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
  /// t < chunks(), ++counts(t)[strip] over the particles of chunk_range(t, n)
  /// (chunks may run in parallel), then finish_build(strips).
  void begin_build(std::size_t n);
  int chunks() const { return chunks_; }
  std::pair<std::size_t, std::size_t> chunk_range(int t, std::size_t n) const {
    const auto T = static_cast<std::size_t>(chunks_), k = static_cast<std::size_t>(t);
    return {n * k / T, n * (k + 1) / T};
  }
  std::uint32_t* counts(int t) { return counts_.data() + static_cast<std::size_t>(t) * offsets.size(); }
  void finish_build(std::span<const std::uint32_t> strip_of_particle);

  /// fn(p) for every particle, scatter-safe (see above).
  template <class Fn>
  void scatter(Fn&& fn) const {
    const int n = strips();
    for (int colour = 0; colour < 2; ++colour) {
      FFP_OMP(omp parallel for schedule(dynamic, 1) if (order.size() >= kParallelMinimum))
      for (int s = colour; s < n; s += 2)
        for (std::uint32_t k = offsets[static_cast<std::size_t>(s)]; k < offsets[static_cast<std::size_t>(s) + 1]; ++k)
          fn(static_cast<std::size_t>(order[k]));
    }
  }

  /// fn(strip, particles) strip by strip, `particles` the strip's slice of
  /// `order`, scatter-safe as scatter() (even strips in parallel, then odd):
  /// for a pass that first sums the strip's own cells, then scatters its particles.
  template <class Fn>
  void scatter_strips(Fn&& fn) const {
    const int n = strips();
    for (int colour = 0; colour < 2; ++colour) {
      FFP_OMP(omp parallel for schedule(dynamic, 1) if (order.size() >= kParallelMinimum))
      for (int s = colour; s < n; s += 2) {
        const std::size_t first = offsets[static_cast<std::size_t>(s)];
        const std::size_t last = offsets[static_cast<std::size_t>(s) + 1];
        fn(s, std::span<const std::uint32_t>(order.data() + first, last - first));
      }
    }
  }

  /// fn(strip, particles) for every strip at once, `particles` the strip's
  /// slice of `order`: for sums into cells (which no two strips share) and for
  /// a second pass over the same particles that reads those sums, both in one
  /// parallel region while the strip's data is still in cache.
  template <class Fn>
  void for_each_strip(Fn&& fn) const {
    const int n = strips();
    FFP_OMP(omp parallel for schedule(dynamic, 1) if (order.size() >= kParallelMinimum))
    for (int s = 0; s < n; ++s) {
      const std::size_t first = offsets[static_cast<std::size_t>(s)];
      const std::size_t last = offsets[static_cast<std::size_t>(s) + 1];
      fn(s, std::span<const std::uint32_t>(order.data() + first, last - first));
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
  std::vector<std::uint32_t> counts_;  ///< per (chunk, strip) during build
  int cells_r_ = 0, cells_z_ = 0;
  int chunks_ = 1;
};

}  // namespace ffp::mpm
