#pragma once
/// The paper's sand (Table 1) and FFP on a 2 cm mesh: the in-process tests' coarse reference.
#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/ffp_model.hpp"

namespace ffp::test {

inline mpm::FfpDescription coarse_ffp() {
  mpm::FfpDescription d;
  d.soil.law = MohrCoulomb(MohrCoulombParameters{ElasticConstants{2.5e6, 0.33}, 39.0 * kDegree, 0.0, 0.0});
  d.mesh.min_cell_m = 0.02;
  d.mesh.max_cell_m = 0.06;
  d.mesh.below_cell_m = 0.04;
  d.contact.friction = std::tan(20.0 * kDegree);
  return d;
}

}  // namespace ffp::test
