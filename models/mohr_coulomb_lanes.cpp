#include "models/mohr_coulomb_lanes.hpp"

#include <cmath>

#include "models/voigt_lanes.hpp"

namespace ffp {

// ElasticTrial (decompose, values, store_with_values) and return_to_mohr_coulomb,
// lane by lane, in the same order. Compiled with the elastic screen's options
// (models/CMakeLists.txt): -ffp-contract=off, since the scalar return forms no
// fused multiply-add either.
void return_planar_trials(Voigt* stress, const std::size_t point[4], const MohrCoulombStrength& strength,
                          const ReturnDirections& directions) {
  Lanes rr, zz, tt, rz;
  for (int k = 0; k < 4; ++k) {
    const Voigt& s = stress[point[k]];
    rr[k] = s[0];
    zz[k] = s[1];
    tt[k] = s[2];
    rz[k] = s[3];
  }
  // The trial's in-plane Mohr circle and its principal values σ1 ≥ σ2 ≥ σ3, θθ above,
  // between or below the in-plane pair.
  const Lanes centre = 0.5 * (rr + zz), half_difference = 0.5 * (rr - zz);
  const Lanes squared = half_difference * half_difference + rz * rz;
  Lanes radius;
  for (int k = 0; k < 4; ++k) radius[k] = std::sqrt(squared[k]);
  const Lanes in_major = centre + radius, in_minor = centre - radius;
  const LaneMask tt_top = tt >= in_major, tt_middle = ~tt_top & (tt >= in_minor), tt_bottom = ~(tt_top | tt_middle);
  const Lanes v0 = select(tt_top, tt, in_major);
  const Lanes v1 = select(tt_top, in_major, select(tt_middle, tt, in_minor));
  const Lanes v2 = select(tt_bottom, tt, in_minor);

  // The return (models/mohr_coulomb_return.hpp).
  const double sf = strength.sin_phi;
  auto yield = [&](Lanes major, Lanes minor) {
    return (major - minor) + (major + minor) * strength.sin_phi - 2.0 * strength.cohesion_Pa * strength.cos_phi;
  };
  const Lanes f_trial = yield(v0, v2);
  const LaneMask yields = f_trial > 0.0;
  const Lanes cohesion = Lanes{} + strength.cohesion_Pa;
  const Lanes scale = max_lanes(max_lanes(abs_lanes(v0), abs_lanes(v2)), cohesion);
  const Lanes tolerance = 1e-13 * scale;
  const double major_term = directions.major_term, middle_term = directions.middle_term,
               minor_term = directions.minor_term, plane_stiffness = directions.plane_stiffness;

  const Lanes multiplier = f_trial / plane_stiffness;
  const Lanes plane0 = v0 - multiplier * major_term, plane1 = v1 - multiplier * middle_term,
              plane2 = v2 - multiplier * minor_term;
  const LaneMask upper_order = plane0 - plane1 >= -tolerance;
  const LaneMask lower_order = plane1 - plane2 >= -tolerance;

  // Both edges, g_b's terms as in the scalar return's edge().
  struct Edge {
    Lanes out[3];
    LaneMask admissible;
  };
  const Lanes lambda_tolerance = tolerance / plane_stiffness;
  auto edge = [&](bool compression) {
    const double b0 = compression ? middle_term : major_term, b1 = compression ? major_term : minor_term,
                 b2 = compression ? minor_term : middle_term;
    const Lanes f_b = compression ? yield(v1, v2) : yield(v0, v1);
    const double coupling = (1.0 + sf) * b0 - (1.0 - sf) * b2;  // n_a · D g_b
    const Lanes sum = (f_trial + f_b) / (plane_stiffness + coupling);
    const Lanes difference = (f_trial - f_b) / (plane_stiffness - coupling);
    const Lanes lambda_a = 0.5 * (sum + difference);
    const Lanes lambda_b = 0.5 * (sum - difference);
    Edge e;
    e.out[0] = v0 - lambda_a * major_term - lambda_b * b0;
    e.out[1] = v1 - lambda_a * middle_term - lambda_b * b1;
    e.out[2] = v2 - lambda_a * minor_term - lambda_b * b2;
    if (compression) {
      e.out[0] = e.out[1] = 0.5 * (e.out[0] + e.out[1]);
    } else {
      e.out[1] = e.out[2] = 0.5 * (e.out[1] + e.out[2]);
    }
    e.admissible =
        (lambda_a >= -lambda_tolerance) & (lambda_b >= -lambda_tolerance) & (e.out[0] - e.out[2] >= -tolerance);
    return e;
  };
  const Edge compression = edge(true), extension = edge(false);

  // The plane if it keeps the order; else the edge the plane return overshot first,
  // then the other; else the apex c cot φ.
  const LaneMask on_plane = upper_order & lower_order, compression_first = ~upper_order;
  const LaneMask first_admissible = select_mask(compression_first, compression.admissible, extension.admissible);
  const LaneMask second_admissible = select_mask(compression_first, extension.admissible, compression.admissible);
  const Lanes apex = Lanes{} + strength.cohesion_Pa * strength.cos_phi / sf;
  const Lanes plane[3] = {plane0, plane1, plane2};
  Lanes returned[3];
  for (int i = 0; i < 3; ++i) {
    const Lanes first = select(compression_first, compression.out[i], extension.out[i]);
    const Lanes second = select(compression_first, extension.out[i], compression.out[i]);
    returned[i] = select(on_plane, plane[i], select(first_admissible, first, select(second_admissible, second, apex)));
  }

  // Back onto the trial's directions (planar_with_values, principal_stress.hpp).
  const Lanes value_tt = select(tt_top, returned[0], select(tt_middle, returned[1], returned[2]));
  const Lanes value_major = select(tt_top, returned[1], returned[0]);
  const Lanes value_minor = select(tt_bottom, returned[1], returned[2]);
  const LaneMask circle = radius > 0.0;
  const Lanes cos_2theta = select(circle, half_difference / radius, Lanes{} + 1.0);
  const Lanes sin_2theta = select(circle, rz / radius, Lanes{});
  const Lanes new_centre = 0.5 * (value_major + value_minor);
  const Lanes new_radius = 0.5 * (value_major - value_minor);
  const Lanes out_rr = new_centre + new_radius * cos_2theta, out_zz = new_centre - new_radius * cos_2theta;
  const Lanes out_rz = new_radius * sin_2theta;
  for (int k = 0; k < 4; ++k) {
    if (!yields[k]) continue;  // inside the surface: the trial stays
    Voigt& s = stress[point[k]];
    s[0] = out_rr[k];
    s[1] = out_zz[k];
    s[2] = value_tt[k];
    s[3] = out_rz[k];
    s[4] = 0.0;
    s[5] = 0.0;
  }
}

}  // namespace ffp
