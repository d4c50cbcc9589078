#include "models/mohr_coulomb.hpp"

#include <algorithm>
#include <cassert>

#include "models/elastic_screen.hpp"
#include "models/mohr_coulomb_lanes.hpp"
#include "models/principal_stress.hpp"

namespace ffp {

MohrCoulomb::MohrCoulomb(const MohrCoulombParameters& parameters)
    : parameters_(parameters),
      strength_(MohrCoulombStrength::of(parameters.friction_angle_rad, parameters.dilatancy_angle_rad,
                                        parameters.cohesion_Pa)),
      stiffness_(PrincipalStiffness::of(parameters.elastic)),
      directions_(ReturnDirections::of(strength_, stiffness_)),
      elastic_stiffness_(ElasticStiffness::of(parameters.elastic)) {}

double MohrCoulomb::yield_function(const Voigt& stress) const {
  return strength_.yield(PrincipalStresses(stress).values());
}

ReturnRegion MohrCoulomb::update(Voigt& stress, const Voigt& strain_increment) const {
  const Voigt trial = stress + elastic_stiffness_.stress_increment(strain_increment);
  const PrincipalStresses principal(trial);
  Eigen::Vector3d returned = principal.values();
  const ReturnRegion region = return_to_mohr_coulomb(returned, strength_, directions_);
  stress = region == ReturnRegion::elastic ? trial : principal.with_values(returned);
  return region;
}

// Most points of a batch stay elastic: the elastic screen forms every trial and
// tests it in vector lanes (screen_elastic_trials, the same bits as update() above),
// block by block. The points that yield with θθ principal (the MPM) return four at a
// time in lanes (return_planar_trials, again the same bits), the last few of the batch
// and any other point one by one (return_from_trial).
void MohrCoulomb::update(std::span<Voigt> stress, std::span<const Voigt> strain_increment) const {
  assert(stress.size() == strain_increment.size());
  constexpr std::size_t kBlock = 64;
  bool settled[kBlock];
  const bool in_lanes = strength_.sin_phi > 0.0;  // Tresca's corner case is scalar only
  std::size_t waiting[4];
  int waiting_count = 0;
  for (std::size_t begin = 0; begin < stress.size(); begin += kBlock) {
    const std::size_t n = std::min(kBlock, stress.size() - begin);
    screen_elastic_trials(&stress[begin], &strain_increment[begin], n, elastic_stiffness_, strength_, settled);
    for (std::size_t k = 0; k < n; ++k) {
      if (settled[k]) continue;
      const Voigt& trial = stress[begin + k];
      if (!in_lanes || trial[4] != 0.0 || trial[5] != 0.0) {
        return_from_trial(stress[begin + k]);
        continue;
      }
      waiting[waiting_count++] = begin + k;
      if (waiting_count == 4) {
        return_planar_trials(stress.data(), waiting, strength_, directions_);
        waiting_count = 0;
      }
    }
  }
  for (int k = 0; k < waiting_count; ++k) return_from_trial(stress[waiting[k]]);
}

void MohrCoulomb::return_from_trial(Voigt& stress) const {
  const ElasticTrial trial(stress);
  if (!trial.planar) {
    const PrincipalStresses principal(stress);
    Eigen::Vector3d returned = principal.values();
    if (return_to_mohr_coulomb(returned, strength_, directions_) != ReturnRegion::elastic)
      stress = principal.with_values(returned);
    return;
  }
  Eigen::Vector3d returned = trial.values();
  if (return_to_mohr_coulomb(returned, strength_, directions_) != ReturnRegion::elastic)
    trial.store_with_values(returned, stress);
}

}  // namespace ffp
