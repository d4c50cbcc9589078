#include "models/elastic_screen.hpp"

#include <cmath>

#include "models/principal_stress.hpp"
#include "models/voigt_lanes.hpp"

namespace ffp {

// ElasticTrial's operations, in the same order, four points per instruction. The file
// is compiled with -ffp-contract=off (models/CMakeLists.txt): a fused multiply-add
// would round differently from the scalar trials of the other laws and of update().
void screen_elastic_trials(Voigt* stress, const Voigt* strain_increment, std::size_t n, const ElasticStiffness& d,
                           const MohrCoulombStrength& strength, bool* settled) {
  double* s = stress->data();
  const double* e = strain_increment->data();
  const double cohesion_term = 2.0 * strength.cohesion_Pa * strength.cos_phi;
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    Lanes sig[6], de[6];
    to_lanes(s + 6 * i, sig);
    to_lanes(e + 6 * i, de);
    const Lanes lambda_tr = d.lambda * (de[0] + de[1] + de[2]);
    const Lanes rr = sig[0] + (d.two_shear * de[0] + lambda_tr);
    const Lanes zz = sig[1] + (d.two_shear * de[1] + lambda_tr);
    const Lanes tt = sig[2] + (d.two_shear * de[2] + lambda_tr);
    const Lanes rz = sig[3] + d.two_shear * de[3];
    const Lanes zt = sig[4] + d.two_shear * de[4];
    const Lanes rt = sig[5] + d.two_shear * de[5];
    const Lanes trial[6] = {rr, zz, tt, rz, zt, rt};
    from_lanes(trial, s + 6 * i);
    const Lanes centre = 0.5 * (rr + zz), half_difference = 0.5 * (rr - zz);
    const Lanes squared = half_difference * half_difference + rz * rz;
    Lanes radius;
    for (int k = 0; k < 4; ++k) radius[k] = std::sqrt(squared[k]);
    const Lanes upper = centre + radius, lower = centre - radius;
    const Lanes major = max_lanes(upper, tt);           // std::max(upper, tt)
    const Lanes minor = select(tt < lower, tt, lower);  // std::min(lower, tt)
    const Lanes f = (major - minor) + (major + minor) * strength.sin_phi - cohesion_term;
    const LaneMask settles = (zt == 0.0) & (rt == 0.0) & ~(f > 0.0);
    for (int k = 0; k < 4; ++k) settled[i + static_cast<std::size_t>(k)] = settles[k] != 0;
  }
  for (; i < n; ++i) {  // the last points of a block not a multiple of four
    const ElasticTrial trial(stress[i], strain_increment[i], d);
    trial.store(stress[i]);
    settled[i] = trial.planar && !(strength.yield(trial.major, trial.minor) > 0.0);
  }
}

}  // namespace ffp
