#include "models/mohr_coulomb.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

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

// Most points of a batch stay elastic. For those with θθ principal (the
// axisymmetric MPM: zero 23 and 13 shears) the trial and its yield value are
// formed here in scalars, by the same operations in the same order as
// ElasticStiffness::stress_increment, PrincipalStresses and
// MohrCoulombStrength::yield (so the same bits), without the principal-space
// object; a point that yields, or a general 3D one, takes update() above.
void MohrCoulomb::update(std::span<Voigt> stress, std::span<const Voigt> strain_increment) const {
  assert(stress.size() == strain_increment.size());
  const double lambda = elastic_stiffness_.lambda, two_shear = elastic_stiffness_.two_shear;
  for (std::size_t i = 0; i < stress.size(); ++i) {
    Voigt& sig = stress[i];
    const Voigt& de = strain_increment[i];
    const double lambda_tr = lambda * (de[0] + de[1] + de[2]);
    const double t0 = sig[0] + (two_shear * de[0] + lambda_tr);
    const double t1 = sig[1] + (two_shear * de[1] + lambda_tr);
    const double t2 = sig[2] + (two_shear * de[2] + lambda_tr);
    const double t3 = sig[3] + two_shear * de[3];
    const double t4 = sig[4] + two_shear * de[4];
    const double t5 = sig[5] + two_shear * de[5];
    if (t4 == 0.0 && t5 == 0.0) {
      const double centre = 0.5 * (t0 + t1), half_difference = 0.5 * (t0 - t1);
      const double radius = std::sqrt(half_difference * half_difference + t3 * t3);
      const double major = std::max(centre + radius, t2), minor = std::min(centre - radius, t2);
      if (!(strength_.yield(major, minor) > 0.0)) {
        sig << t0, t1, t2, t3, t4, t5;
        continue;
      }
    }
    update(sig, de);
  }
}

}  // namespace ffp
