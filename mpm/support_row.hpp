#pragma once
/// One row of a GIMP particle's 3×3 support as a vector of four doubles (GCC/Clang
/// vector extension): the row's three nodes a = 0, 1, 2 and the next node, whose
/// weight is zero (ShapeWeights::wr[3] = gr[3] = 0). With AVX (the build's
/// FFP_X86_64_V3) a row is one 256-bit register, so a transfer handles a row in
/// one load, one multiply-add and one store per nodal array instead of three.
///
/// The fourth node only ever takes a zero term or is read with a zero weight, and
/// it lies inside the particle's strip neighbourhood (ParticleBins: strips two apart
/// are at least two node columns apart), so no other thread writes it meanwhile.
/// Where the row ends at the grid's last node column the fourth node would be
/// the next row's first: such particles take the node-by-node path (row_fits).
#include <cstring>

#include "mpm/grid.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp::mpm {

using Row = double __attribute__((vector_size(32)));
inline Row load_row(const double* x) {
  Row v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
inline void store_row(double* x, Row v) { std::memcpy(x, &v, sizeof v); }
/// x[0] + x[1] + x[2] (the fourth lane holds a zero-weight term).
inline double row_sum(Row x) { return (x[0] + x[1]) + x[2]; }
/// The fourth node of every support row is a node of the same grid row.
inline bool row_fits(const Grid& grid, const ShapeWeights& w) { return w.node_r + 3 < grid.r.nodes(); }

}  // namespace ffp::mpm
