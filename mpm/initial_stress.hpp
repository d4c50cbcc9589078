#pragma once
/// K0 initial stress of a horizontally layered body at rest.
#include <algorithm>

#include "models/voigt.hpp"
#include "mpm/model.hpp"

namespace ffp::mpm {

/// σ'_v = γ·depth, σ'_h = K0·σ'_v (Jaky 1944 for K0 = 1 − sin φ' when the scene
/// omits it), depth = max(0, z_surface − z); tension-positive Voigt.
inline Voigt geostatic_stress(const GeostaticStress& g, double unit_weight_N_m3, double z_m) {
  const double vertical = unit_weight_N_m3 * std::max(0.0, g.surface_z_m - z_m);
  Voigt s = Voigt::Zero();
  s[0] = -g.k0 * vertical;  // rr
  s[1] = -vertical;         // zz
  s[2] = -g.k0 * vertical;  // θθ
  return s;
}

}  // namespace ffp::mpm
