#include "mpm/boundary_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ffp::mpm {

namespace {

std::uint8_t bits_of(Fixity f, std::uint8_t normal) {
  switch (f) {
    case Fixity::free:
      return 0;
    case Fixity::roller:
      return normal;
    case Fixity::fixed:
      return constrain_r | constrain_z;
    case Fixity::absorbing:
      return 0;
  }
  return 0;
}

/// ∫ N_i(r) r dr over the radial hat of node i: on each neighbouring segment [r_i, r_n],
/// L (2 r_i + r_n)/6. (Unweighted, GridAxis::hat_integral.)
double radial_hat_integral(const GridAxis& r, int i) {
  double sum = 0.0;
  for (const int n : {i - 1, i + 1}) {
    if (n < 0 || n >= r.nodes()) continue;
    sum += std::abs(r.coordinate(n) - r.coordinate(i)) * (2.0 * r.coordinate(i) + r.coordinate(n)) / 6.0;
  }
  return sum;
}

}  // namespace

std::vector<NodeConstraint> constrained_nodes(const BoundaryConditions& bc, int nr, int nz, bool inner_is_axis) {
  const Fixity inner = (inner_is_axis && bc.inner == Fixity::free) ? Fixity::roller : bc.inner;
  std::vector<NodeConstraint> out;
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nr; ++i) {
      std::uint8_t bits = 0;
      if (i == 0) bits |= bits_of(inner, constrain_r);
      if (i == nr - 1) bits |= bits_of(bc.outer, constrain_r);
      if (j == 0) bits |= bits_of(bc.bottom, constrain_z);
      if (j == nz - 1) bits |= bits_of(bc.top, constrain_z);
      if (bits != 0) out.push_back({static_cast<std::uint32_t>(i + nr * j), bits});
    }
  }
  return out;
}

std::vector<AbsorbingNode> absorbing_nodes(const BoundaryConditions& bc, int nr, int nz, int bottom_row) {
  std::vector<AbsorbingNode> out;
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nr; ++i) {
      const AbsorbingNode a{static_cast<std::uint32_t>(i + nr * j),
                            i,
                            j,
                            bc.bottom == Fixity::absorbing && j == bottom_row,
                            bc.top == Fixity::absorbing && j == nz - 1,
                            bc.inner == Fixity::absorbing && i == 0,
                            bc.outer == Fixity::absorbing && i == nr - 1};
      if (a.bottom || a.top || a.inner || a.outer) out.push_back(a);
    }
  }
  return out;
}

Dashpot dashpot(const AbsorbingNode& a, const GridAxis& r, const GridAxis& z, const Impedance& beyond) {
  const double normal = beyond.density_kg_m3 * beyond.p_wave_m_s, tangential = beyond.density_kg_m3 * beyond.s_wave_m_s;
  // G/R of the springs: G = ρ c_s²; R the node's distance from the source.
  double g_over_r = 0.0;
  if (beyond.has_source) {
    const double distance = std::hypot(r.coordinate(a.i) - beyond.source_r_m, z.coordinate(a.j) - beyond.source_z_m);
    g_over_r = beyond.density_kg_m3 * beyond.s_wave_m_s * beyond.s_wave_m_s / std::max(distance, 1e-9);
  }
  Dashpot d{0.0, 0.0, 0.0, 0.0};
  const int sides_z = int{a.bottom} + int{a.top}, sides_r = int{a.inner} + int{a.outer};
  if (sides_z > 0) {
    const double area = sides_z * radial_hat_integral(r, a.i);
    d.damping_z += normal * area;
    d.damping_r += tangential * area;
    d.stiffness_z += kSpringNormal * g_over_r * area;
    d.stiffness_r += kSpringTangential * g_over_r * area;
  }
  if (sides_r > 0) {
    const double area = sides_r * r.coordinate(a.i) * z.hat_integral(a.j, z.front(), z.back());
    d.damping_r += normal * area;
    d.damping_z += tangential * area;
    d.stiffness_r += kSpringNormal * g_over_r * area;
    d.stiffness_z += kSpringTangential * g_over_r * area;
  }
  return d;
}

}  // namespace ffp::mpm
