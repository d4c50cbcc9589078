#pragma once
/// Four points in vector lanes (GCC/Clang vector extension: one 256-bit register with
/// AVX, two 128-bit halves without): four consecutive Voigt tensors loaded as six
/// vectors and transposed into their six components, a vector each, and back. For the
/// loops that run the same scalar operations on four points at once (the Mohr–Coulomb
/// elastic screen, the time step's maxima): lane by lane the same bits as the scalar code.
///
/// Internal linkage: each file that includes this compiles the helpers for its own
/// target (the files that use them are built for AVX2 where FFP_X86_64_V3 is on), so
/// no two files may share one out-of-line copy. Vectors cross only these helpers
/// (-Wno-psabi where they are used).
#include <cstring>

#include "models/voigt.hpp"

namespace ffp {
namespace {  // NOLINT(google-build-namespaces): see above

static_assert(sizeof(Voigt) == 6 * sizeof(double), "an array of Voigt is a plain array of doubles");

using Lanes = double __attribute__((vector_size(32)));
using LaneMask = long long __attribute__((vector_size(32)));  ///< a comparison's lanes: all ones or all zeros

inline Lanes load_lanes(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store_lanes(double* p, Lanes v) { std::memcpy(p, &v, sizeof v); }
/// mask ? a : b lane by lane.
inline Lanes select(LaneMask mask, Lanes a, Lanes b) { return (Lanes)((mask & (LaneMask)a) | (~mask & (LaneMask)b)); }
/// mask ? a : b lane by lane, for masks.
inline LaneMask select_mask(LaneMask mask, LaneMask a, LaneMask b) { return (mask & a) | (~mask & b); }
/// std::max(a, b) lane by lane, with its semantics: b only where a < b (a NaN b is not taken).
inline Lanes max_lanes(Lanes a, Lanes b) { return select(a < b, b, a); }
/// |x| lane by lane (the sign bit cleared, as std::abs).
inline Lanes abs_lanes(Lanes x) { return (Lanes)((LaneMask)x & ~(LaneMask)(Lanes{-0.0, -0.0, -0.0, -0.0})); }

/// Four consecutive Voigt (24 doubles at p) → their six components, a vector each.
inline void to_lanes(const double* p, Lanes c[6]) {
  const Lanes v0 = load_lanes(p), v1 = load_lanes(p + 4), v2 = load_lanes(p + 8), v3 = load_lanes(p + 12),
              v4 = load_lanes(p + 16), v5 = load_lanes(p + 20);
  // Pairs of points first: (σ_0, σ_1) of points 0 and 1, of points 2 and 3, and so on.
  const Lanes a01 = __builtin_shufflevector(v0, v1, 0, 1, 6, 7), a23 = __builtin_shufflevector(v3, v4, 0, 1, 6, 7);
  const Lanes b01 = __builtin_shufflevector(v0, v2, 2, 3, 4, 5), b23 = __builtin_shufflevector(v3, v5, 2, 3, 4, 5);
  const Lanes d01 = __builtin_shufflevector(v1, v2, 0, 1, 6, 7), d23 = __builtin_shufflevector(v4, v5, 0, 1, 6, 7);
  c[0] = __builtin_shufflevector(a01, a23, 0, 2, 4, 6);
  c[1] = __builtin_shufflevector(a01, a23, 1, 3, 5, 7);
  c[2] = __builtin_shufflevector(b01, b23, 0, 2, 4, 6);
  c[3] = __builtin_shufflevector(b01, b23, 1, 3, 5, 7);
  c[4] = __builtin_shufflevector(d01, d23, 0, 2, 4, 6);
  c[5] = __builtin_shufflevector(d01, d23, 1, 3, 5, 7);
}

/// The way back: six component vectors → four consecutive Voigt (24 doubles at p).
inline void from_lanes(const Lanes c[6], double* p) {
  const Lanes a01 = __builtin_shufflevector(c[0], c[1], 0, 4, 1, 5),
              a23 = __builtin_shufflevector(c[0], c[1], 2, 6, 3, 7);
  const Lanes b01 = __builtin_shufflevector(c[2], c[3], 0, 4, 1, 5),
              b23 = __builtin_shufflevector(c[2], c[3], 2, 6, 3, 7);
  const Lanes d01 = __builtin_shufflevector(c[4], c[5], 0, 4, 1, 5),
              d23 = __builtin_shufflevector(c[4], c[5], 2, 6, 3, 7);
  store_lanes(p, __builtin_shufflevector(a01, b01, 0, 1, 4, 5));
  store_lanes(p + 4, __builtin_shufflevector(d01, a01, 0, 1, 6, 7));
  store_lanes(p + 8, __builtin_shufflevector(b01, d01, 2, 3, 6, 7));
  store_lanes(p + 12, __builtin_shufflevector(a23, b23, 0, 1, 4, 5));
  store_lanes(p + 16, __builtin_shufflevector(d23, a23, 0, 1, 6, 7));
  store_lanes(p + 20, __builtin_shufflevector(b23, d23, 2, 3, 6, 7));
}

}  // namespace
}  // namespace ffp
