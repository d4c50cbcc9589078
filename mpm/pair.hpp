#pragma once
/// Two doubles in one SSE2 register (GCC/Clang vector extension), for the two
/// adjacent nodes a = 0, 1 of a support row: lane-wise IEEE operations give the
/// same bits as the scalar code, so sums keep their order and their values.
#include <cstring>

namespace ffp::mpm {

using Pair = double __attribute__((vector_size(16)));
inline Pair pair(double a, double b) { return Pair{a, b}; }
inline Pair load(const double* x) {
  Pair v;
  std::memcpy(&v, x, sizeof v);
  return v;
}
inline void store(double* x, Pair v) { std::memcpy(x, &v, sizeof v); }
/// sum + x[0] + x[1], in that order: node a = 0's term, then a = 1's, as node by node.
inline void add_lanes(double& sum, Pair x) { sum = sum + x[0] + x[1]; }

}  // namespace ffp::mpm
