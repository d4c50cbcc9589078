#include <cmath>
#include <string>

#include "mpm/stages.hpp"

namespace ffp::mpm {

void compute_shape_functions(Simulation& s) {
  const Particles& p = s.particles;
  const std::size_t n = p.size();
  // The previous step's cells, where they are this step's particles', as hints.
  const bool hinted = s.cell.size() == n;
  const auto cells_r = static_cast<std::uint32_t>(s.grid.r.cells());
  s.weights.resize(n);
  s.strip.resize(n);
  s.cell.resize(n);
  const bool gimp = s.settings.shape_function == ShapeFunction::gimp;
  const GridAxis& axis_r = s.grid.r;
  const GridAxis& axis_z = s.grid.z;
  long outside = 0;
  // Contiguous chunks, each counting its particles' strips for the bins as it goes.
  s.bins.begin_build(n);
  const int chunks = s.bins.chunks();
  FFP_OMP(omp parallel for schedule(static, 1) reduction(+ : outside) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks; ++t) {
    const auto [first, last] = s.bins.chunk_range(t, n);
    std::uint32_t* strip_count = s.bins.counts(t);
    for (std::size_t i = first; i < last; ++i) {
      const double r = p.r[i], z = p.z[i];
      const std::uint32_t previous = hinted ? s.cell[i] : 0;
      const int cr = axis_r.cell_near(r, static_cast<int>(previous % cells_r));
      const int cz = axis_z.cell_near(z, static_cast<int>(previous / cells_r));
      if (cr < 0 || cz < 0) {
        ++outside;
        continue;
      }
      const Weights1D wr = gimp ? gimp_weights(axis_r, r, p.half_r[i], cr) : linear_weights(axis_r, r, cr);
      const Weights1D wz = gimp ? gimp_weights(axis_z, z, p.half_z[i], cz) : linear_weights(axis_z, z, cz);
      ShapeWeights& w = s.weights[i];
      w.node_r = wr.base;
      w.node_z = wz.base;
      for (int k = 0; k < 3; ++k) {
        w.wr[k] = wr.w[k];
        w.gr[k] = wr.g[k];
        w.wz[k] = wz.w[k];
        w.gz[k] = wz.g[k];
      }
      w.wr[3] = 0.0;
      w.gr[3] = 0.0;
      w.inverse_r = 1.0 / r;
      s.cell[i] = static_cast<std::uint32_t>(s.grid.cell(cr, cz));
      s.strip[i] = s.bins.strip_of(cr, cz);
      ++strip_count[s.strip[i]];
    }
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
