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
/// the next row's first: such particles take the node-by-node path (rows_fit).
/// Linear hats have two nodes per row: a row is a Pair (128 bits).
#include <cstring>
#include <type_traits>

#include "mpm/grid.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp::mpm {

using Row = double __attribute__((vector_size(32)));
using Pair = double __attribute__((vector_size(16)));
/// x[0] + x[1] + x[2] (the fourth lane holds a zero-weight term).
inline double row_sum(Row x) { return (x[0] + x[1]) + x[2]; }
/// x[0] + x[1]: a linear support row is a Pair.
inline double row_sum(Pair x) { return x[0] + x[1]; }

/// fn(node, S_ip, G_ip,r, G_ip,z) over the S×S support of a particle on the grid, node by
/// node: for linear hats and for the GIMP particles whose rows do not go as vectors.
template <int S, class Fn>
inline void for_support(const Grid& grid, const ShapeWeights& w, Fn&& fn) {
  for (int b = 0; b < S; ++b) {
    const std::size_t row = grid.node(w.node_r, w.node_z + b);
    for (int a = 0; a < S; ++a)
      fn(row + static_cast<std::size_t>(a), w.wr[a] * w.wz[b], w.gr[a] * w.wz[b], w.wr[a] * w.gz[b]);
  }
}

/// The vector of one support row: S = 3 (GIMP) a Row, S = 2 (linear hats) a Pair.
template <int S>
using SupportRow = std::conditional_t<S == 3, Row, Pair>;
template <int S>
inline SupportRow<S> load_support_row(const double* x) {
  SupportRow<S> v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
template <int S>
inline void store_support_row(double* x, SupportRow<S> v) {
  std::memcpy(x, &v, sizeof v);
}
/// Whether a GIMP row goes as one vector at all: only where the target has 256-bit
/// vectors (AVX, e.g. FFP_X86_64_V3). Without them GCC splits a Row into two 128-bit
/// halves, which ran the GIMP step at half the node-by-node speed (Zen 5 EPYC:
/// 4.7 against 9.2 M particle-steps/s); a Pair is one SSE2 register everywhere.
#if defined(__AVX__)
inline constexpr bool kGimpRowVectors = true;
#else
inline constexpr bool kGimpRowVectors = false;
#endif

/// The support's rows go as vectors: always for linear hats; for GIMP where the
/// target has 256-bit vectors, unless the fourth node of a row would be the next
/// grid row's first (see above).
template <int S>
inline bool rows_fit(const Grid& grid, const ShapeWeights& w) {
  return S == 2 || (kGimpRowVectors && w.node_r + 3 < grid.r.nodes());
}

/// Two GIMP particles whose supports are the same node columns, the second one node
/// row up: a cell's lower and upper particle, seeded one after the other. Together
/// they touch four node rows instead of six, so the transfers take them as a pair
/// (each nodal sum still takes the lower's term before the upper's).
inline bool stacked_pair(const ShapeWeights& lower, const ShapeWeights& upper) {
  return upper.node_r == lower.node_r && upper.node_z == lower.node_z + 1;
}

}  // namespace ffp::mpm
