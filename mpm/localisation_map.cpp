#include "mpm/localisation_map.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "models/localisation.hpp"
#include "models/math_constants.hpp"
#include "models/mohr_coulomb_return.hpp"

namespace ffp::mpm {

namespace {

/// One particle on the surface: counts and fields. A face takes its plane's tangent, an edge
/// the corner tangent of its two planes; the apex has none.
void evaluate(const ElasticConstants& elastic, const MohrCoulombParameters& p, const StrengthSlopes& slopes,
              const Voigt& stress, std::size_t i, LocalisationMap& map) {
  const MohrCoulombStrength strength =
      MohrCoulombStrength::of(p.friction_angle_rad, p.dilatancy_angle_rad, p.cohesion_Pa);
  const MohrCoulombFlow at = mohr_coulomb_flow(stress, strength, slopes);
  if (at.region == ReturnRegion::elastic) return;
  if (at.region == ReturnRegion::apex) {
    ++map.at_apex;
    map.place[i] = YieldPlace::apex;
    return;
  }
  const bool face = at.region == ReturnRegion::plane;
  ++(face ? map.on_face : map.on_edge);
  map.place[i] = face ? YieldPlace::face : YieldPlace::edge;
  const Localisation found = face ? find_localisation(elastic, at.flow) : find_localisation(elastic, at.corner);
  if (!found.localised) return;
  ++(face ? map.localised_on_face : map.localised_on_edge);
  map.place[i] = YieldPlace::localised;
  map.localised[i] = 1.0;
  map.band_angle_deg[i] = found.band_normal_rad / kDegree;
}

}  // namespace

std::size_t minimum_yielding_for_share(std::size_t soil_particles) {
  return std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil(kMinimumYieldingShare * static_cast<double>(soil_particles))));
}

LocalisationMap map_localisation(const MaterialGroup& group, std::span<const Voigt> stress) {
  LocalisationMap map;
  map.place.assign(stress.size(), YieldPlace::inside);
  map.localised.assign(stress.size(), 0.0);
  map.band_angle_deg.assign(stress.size(), 0.0);
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        using State = typename Law::State;
        if constexpr (requires(const State& s) {
                        law.current_strength(s, 0.0);
                        law.strength_slopes(s, 0.0);
                      }) {
          const auto& states = std::get<std::vector<State>>(group.states);
          for (std::size_t k = 0; k < group.size(); ++k) {
            const std::size_t i = group.begin + k;
            const double p = mean_pressure(stress[i]);
            evaluate(law.elastic(), law.current_strength(states[k], p), law.strength_slopes(states[k], p), stress[i], i,
                     map);
          }
        }
      },
      group.law);
  return map;
}

}  // namespace ffp::mpm
