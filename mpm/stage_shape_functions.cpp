#include <algorithm>
#include <cmath>
#include <string>

#include "mpm/stages.hpp"

namespace ffp::mpm {

namespace {

template <bool Gimp>
inline Weights1D axis_weights(const GridAxis& axis, double x, double half_length, int cell) {
  if constexpr (Gimp) {
    return gimp_weights(axis, x, half_length, cell);
  } else {
    return linear_weights(axis, x, cell);
  }
}

/// The weights of particles [first, last), counting their strips in strip_count;
/// returns how many are outside the grid. `hinted`: s.cell holds the previous
/// step's cells of these particles (GridAxis::cell_near). In blocks: a block's
/// radial weights, then its vertical ones — two short loops whose particles
/// overlap in the processor, where one long loop over both directions spills.
template <bool Gimp>
long shape_functions_of(Simulation& s, std::size_t first, std::size_t last, bool hinted, std::uint32_t* strip_count) {
  const Particles& P = s.particles;
  const GridAxis& axis_r = s.grid.r;
  const GridAxis& axis_z = s.grid.z;
  const auto cells_r = static_cast<std::uint32_t>(axis_r.cells());
  constexpr std::size_t kBlock = 64;
  int cell_r[kBlock], hint_z[kBlock];
  long outside = 0;
  for (std::size_t begin = first; begin < last; begin += kBlock) {
    const std::size_t end = std::min(begin + kBlock, last);
    for (std::size_t i = begin; i < end; ++i) {
      const double r = P.r[i];
      // The previous step's cell (i, j) from its index: one division for both directions.
      const std::uint32_t previous_z = hinted ? s.cell[i] / cells_r : 0;
      hint_z[i - begin] = hinted ? static_cast<int>(previous_z) : -1;
      const int cr = axis_r.cell_near(r, hinted ? static_cast<int>(s.cell[i] - previous_z * cells_r) : -1);
      cell_r[i - begin] = cr;
      if (cr < 0) continue;
      const Weights1D wr = axis_weights<Gimp>(axis_r, r, P.half_r[i], cr);
      ShapeWeights& w = s.weights[i];
      w.node_r = wr.base;
      for (int k = 0; k < 3; ++k) {
        w.wr[k] = wr.w[k];
        w.gr[k] = wr.g[k];
      }
      w.wr[3] = 0.0;
      w.gr[3] = 0.0;
      w.inverse_r = 1.0 / r;
    }
    for (std::size_t i = begin; i < end; ++i) {
      const double z = P.z[i];
      const int cr = cell_r[i - begin];
      const int cz = axis_z.cell_near(z, hint_z[i - begin]);
      if (cr < 0 || cz < 0) {
        ++outside;
        continue;
      }
      const Weights1D wz = axis_weights<Gimp>(axis_z, z, P.half_z[i], cz);
      ShapeWeights& w = s.weights[i];
      w.node_z = wz.base;
      for (int k = 0; k < 3; ++k) {
        w.wz[k] = wz.w[k];
        w.gz[k] = wz.g[k];
      }
      s.cell[i] = static_cast<std::uint32_t>(s.grid.cell(cr, cz));
      s.strip[i] = s.bins.strip_of(cr, cz);
      ++strip_count[s.strip[i]];
    }
  }
  return outside;
}

}  // namespace

void compute_shape_functions(Simulation& s) {
  const Particles& p = s.particles;
  const std::size_t n = p.size();
  const bool hinted = s.cell.size() == n;  // the previous step's cells, as hints
  s.weights.resize(n);
  s.strip.resize(n);
  s.cell.resize(n);
  const bool gimp = s.settings.shape_function == ShapeFunction::gimp;
  long outside = 0;
  // Contiguous chunks, each counting its particles' strips for the bins as it goes.
  s.bins.begin_build(n);
  const int chunks = s.bins.chunks();
  FFP_OMP(omp parallel for schedule(static, 1) reduction(+ : outside) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks; ++t) {
    const auto [first, last] = s.bins.chunk_range(t);
    std::uint32_t* strip_count = s.bins.counts(t);
    outside += gimp ? shape_functions_of<true>(s, first, last, hinted, strip_count)
                    : shape_functions_of<false>(s, first, last, hinted, strip_count);
  }
  if (outside > 0) {
    for (std::size_t i = 0; i < n; ++i) {
      if (s.grid.r.cell_of(p.r[i]) < 0 || s.grid.z.cell_of(p.z[i]) < 0)
        throw StepFailure("particle " + std::to_string(i) + " left the grid at r = " + std::to_string(p.r[i]) +
                          " m, z = " + std::to_string(p.z[i]) + " m (t = " + std::to_string(s.time_s) + " s)");
    }
  }
  s.bins.finish_build(s.strip);
}

}  // namespace ffp::mpm
