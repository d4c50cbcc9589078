#include "mpm/boundary_conditions.hpp"

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
  }
  return 0;
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

}  // namespace ffp::mpm
