#include "models/material_law.hpp"

#include <cmath>
#include <type_traits>

namespace ffp {

MaterialLaw make_law(const MaterialParameters& parameters) {
  return std::visit(
      [](const auto& p) -> MaterialLaw {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, ElasticConstants>) {
          return LinearElastic(p);
        } else if constexpr (std::is_same_v<P, MohrCoulombParameters>) {
          return MohrCoulomb(p);
        } else {
          return StrainSofteningMohrCoulomb(p);
        }
      },
      parameters);
}

double at_rest_k0(const MaterialParameters& parameters) {
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&parameters)) return 1.0 - std::sin(mc->friction_angle_rad);
  if (const auto* ss = std::get_if<StrainSofteningParameters>(&parameters)) return 1.0 - std::sin(ss->friction_peak_rad);
  const double nu = std::get<ElasticConstants>(parameters).poisson_ratio;
  return nu / (1.0 - nu);
}

}  // namespace ffp
