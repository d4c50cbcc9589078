#pragma once
/// Particle–node weights S_ip and gradients G_ip = ∇S_ip on a tensor-product
/// grid, built from 1D factors: S_ip = s_r(r_p)·s_z(z_p),
/// G_ip = (s_r'·s_z, s_r·s_z'). Any (non-uniform, moving) node spacing.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "mpm/grid_axis.hpp"

namespace ffp::mpm {

enum class ShapeFunction : std::uint8_t { linear, gimp };
using ShapeFunctionName = std::pair<ShapeFunction, std::string_view>;
/// The scene's names of ShapeFunction, in the order messages list them.
inline constexpr auto kShapeFunctionNames =
    std::to_array<ShapeFunctionName>({{ShapeFunction::linear, "linear"}, {ShapeFunction::gimp, "gimp"}});
inline std::string to_string(ShapeFunction f) {
  return std::string(std::ranges::find(kShapeFunctionNames, f, &ShapeFunctionName::first)->second);
}

/// Nodes of one particle's support in one direction: base, base+1 (, base+2).
struct Weights1D {
  int base = 0;
  double w[3] = {0.0, 0.0, 0.0};  ///< s_k
  double g[3] = {0.0, 0.0, 0.0};  ///< ds_k/dx
};

/// Linear hats, point evaluation in `cell`: s = ((x1 − x)/h, (x − x0)/h).
inline Weights1D linear_weights(const GridAxis& axis, double x, int cell) {
  Weights1D out;
  out.base = cell;
  const double x0 = axis.coordinate(cell), x1 = axis.coordinate(cell + 1);
  const double inverse_h = axis.inverse_spacing(cell);
  out.w[0] = (x1 - x) * inverse_h;
  out.w[1] = (x - x0) * inverse_h;
  out.g[0] = -inverse_h;
  out.g[1] = inverse_h;
  return out;
}

/// uGIMP (Bardenhagen & Kober 2004, weighting functions averaged over the
/// particle domain): s_k = (1/2l)∫_{x−l}^{x+l} N_k dξ and
/// ds_k/dx = (N_k(x+l) − N_k(x−l))/(2l), exact for any node spacing.
/// The domain is kept inside the two cells around the particle and inside the
/// grid, so it is truncated at the axis r = 0 (no mirror nodes needed) and on
/// cells narrower than 2l (the compressing zone of a moving mesh).
inline Weights1D gimp_weights(const GridAxis& axis, double x, double half_length, int cell) {
  Weights1D out;
  const double xc = axis.coordinate(cell), xc1 = axis.coordinate(cell + 1);
  const int base = std::clamp(x < 0.5 * (xc + xc1) ? cell - 1 : cell, 0, axis.nodes() - 3);
  out.base = base;
  const double x0 = axis.coordinate(base), x1 = axis.coordinate(base + 1), x2 = axis.coordinate(base + 2);
  const double inverse_h0 = axis.inverse_spacing(base), inverse_h1 = axis.inverse_spacing(base + 1);
  const double l = std::min(half_length, std::min(x - x0, x2 - x));
  if (!(l > 1e-9 * (x2 - x0))) {  // point particle (or on the grid edge): linear hats
    // (each entry by a fixed index, so that the weights can stay in registers)
    const bool left = x < x1;
    out.w[0] = left ? (x1 - x) * inverse_h0 : 0.0;
    out.w[1] = left ? (x - x0) * inverse_h0 : (x2 - x) * inverse_h1;
    out.w[2] = left ? 0.0 : (x - x1) * inverse_h1;
    out.g[0] = left ? -inverse_h0 : 0.0;
    out.g[1] = left ? inverse_h0 : -inverse_h1;
    out.g[2] = left ? 0.0 : inverse_h1;
    return out;
  }
  const double a = x - l, b = x + l, inverse_length = 0.5 / l;
  // Part of the domain in [x0, x1] and in [x1, x2]; a linear function integrates
  // to length × midpoint value.
  const double length0 = std::max(0.0, std::min(b, x1) - a), mid0 = a + 0.5 * length0;
  const double length1 = std::max(0.0, b - std::max(a, x1)), mid1 = b - 0.5 * length1;
  out.w[0] = length0 * (x1 - mid0) * inverse_h0 * inverse_length;
  out.w[2] = length1 * (mid1 - x1) * inverse_h1 * inverse_length;
  out.w[1] = 1.0 - out.w[0] - out.w[2];
  // Hat values at the domain ends.
  auto hats = [&](double y, double n[3]) {
    if (y < x1) {
      n[0] = (x1 - y) * inverse_h0;
      n[1] = (y - x0) * inverse_h0;
      n[2] = 0.0;
    } else {
      n[0] = 0.0;
      n[1] = (x2 - y) * inverse_h1;
      n[2] = (y - x1) * inverse_h1;
    }
  };
  double na[3], nb[3];
  hats(a, na);
  hats(b, nb);
  for (int k = 0; k < 3; ++k) out.g[k] = (nb[k] - na[k]) * inverse_length;
  return out;
}

/// One particle's weights for the current step (cached once per step: every
/// transfer of the step uses the start-of-step positions).
/// wr and gr carry a fourth, zero entry, so that a support row (its three nodes
/// and the next) goes as one 256-bit vector (mpm/support_row.hpp). 128 bytes on a
/// 64-byte boundary: each particle's weights are two whole cache lines.
struct alignas(64) ShapeWeights {
  double wr[4], gr[4];                  ///< s_r, s_r' at nodes node_r + a (wr[3] = gr[3] = 0)
  double wz[3], gz[3];                  ///< s_z, s_z' at nodes node_z + b
  double inverse_r;                     ///< 1/r_p, for the hoop terms
  std::int32_t node_r = 0, node_z = 0;  ///< first node of the support patch
};

/// fn(i, S_ip, G_ip,r, G_ip,z) over a particle's S×S support node by node, row b outside:
/// S_ip = s_r,a s_z,b and G_ip = (s_r,a' s_z,b, s_r,a s_z,b'), where node(a, b) = i is where the
/// support's node (a, b) sits in the arrays fn works on (the grid's index, or a subcycled body's own).
template <int S, class Node, class Fn>
inline void for_support_at(const ShapeWeights& w, Node&& node, Fn&& fn) {
  for (int b = 0; b < S; ++b)
    for (int a = 0; a < S; ++a) fn(node(a, b), w.wr[a] * w.wz[b], w.gr[a] * w.wz[b], w.wr[a] * w.gz[b]);
}

}  // namespace ffp::mpm
