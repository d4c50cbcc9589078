#include "models/mohr_coulomb.hpp"

#include <cassert>

#include "models/principal_stress.hpp"

namespace ffp {

MohrCoulomb::MohrCoulomb(const MohrCoulombParameters& parameters)
    : parameters_(parameters),
      strength_(MohrCoulombStrength::of(parameters.friction_angle_rad, parameters.dilatancy_angle_rad,
                                        parameters.cohesion_Pa)),
      stiffness_(PrincipalStiffness::of(parameters.elastic)),
      elastic_stiffness_(ElasticStiffness::of(parameters.elastic)) {}

double MohrCoulomb::yield_function(const Voigt& stress) const {
  return strength_.yield(PrincipalStresses(stress).values());
}

ReturnRegion MohrCoulomb::update(Voigt& stress, const Voigt& strain_increment) const {
  const Voigt trial = stress + elastic_stiffness_.stress_increment(strain_increment);
  const PrincipalStresses principal(trial);
  Eigen::Vector3d returned = principal.values();
  const ReturnRegion region = return_to_mohr_coulomb(returned, strength_, stiffness_);
  stress = region == ReturnRegion::elastic ? trial : principal.with_values(returned);
  return region;
}

// Most points of a batch stay elastic: their trial and yield value come from
// ElasticTrial (the same bits as update() above) and the yield test decides; a point
// that yields returns on ElasticTrial's principal values, without the principal-space
// object (again the same bits); a general 3D point takes update().
void MohrCoulomb::update(std::span<Voigt> stress, std::span<const Voigt> strain_increment) const {
  assert(stress.size() == strain_increment.size());
  const ElasticStiffness stiffness = elastic_stiffness_;  // copies: the stores below cannot change them
  const MohrCoulombStrength strength = strength_;
  for (std::size_t i = 0; i < stress.size(); ++i) {
    const ElasticTrial trial(stress[i], strain_increment[i], stiffness);
    if (!trial.planar) {
      update(stress[i], strain_increment[i]);
    } else if (!(strength.yield(trial.major, trial.minor) > 0.0)) {
      trial.store(stress[i]);
    } else {  // the return of update(), on the trial's scalar principal values
      Eigen::Vector3d returned = trial.values();
      if (return_to_mohr_coulomb(returned, strength, stiffness_) == ReturnRegion::elastic) {
        trial.store(stress[i]);
      } else {
        trial.store_with_values(returned, stress[i]);
      }
    }
  }
}

}  // namespace ffp
