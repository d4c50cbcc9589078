#include "models/elastic_screen.hpp"

#include <cmath>
#include <cstring>

#include "models/principal_stress.hpp"

namespace ffp {

namespace {

static_assert(sizeof(Voigt) == 6 * sizeof(double), "a block of Voigt is a plain array of doubles");

// Four points in lanes (GCC/Clang vector extension: one 256-bit register with AVX).
using Lanes = double __attribute__((vector_size(32)));
using Mask = long long __attribute__((vector_size(32)));

Lanes load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store(double* p, Lanes v) { std::memcpy(p, &v, sizeof v); }
/// mask ? a : b lane by lane (a comparison's lanes are all ones or all zeros).
Lanes select(Mask mask, Lanes a, Lanes b) { return (Lanes)((mask & (Mask)a) | (~mask & (Mask)b)); }

// Four consecutive Voigt (24 doubles, six loads) → their six components, a vector each.
void to_lanes(const double* p, Lanes c[6]) {
  const Lanes v0 = load(p), v1 = load(p + 4), v2 = load(p + 8), v3 = load(p + 12), v4 = load(p + 16), v5 = load(p + 20);
  const Lanes a01 = __builtin_shufflevector(v0, v1, 0, 1, 6, 7), a23 = __builtin_shufflevector(v3, v4, 0, 1, 6, 7);
  const Lanes b01 = __builtin_shufflevector(v0, v2, 2, 3, 4, 5), b23 = __builtin_shufflevector(v3, v5, 2, 3, 4, 5);
  const Lanes d01 = __builtin_shufflevector(v1, v2, 0, 1, 6, 7), d23 = __builtin_shufflevector(v4, v5, 0, 1, 6, 7);
  c[0] = __builtin_shufflevector(a01, a23, 0, 2, 4, 6);
  c[1] = __builtin_shufflevector(a01, a23, 1, 3, 5, 7);
  c[2] = __builtin_shufflevector(b01, b23, 0, 2, 4, 6);
  c[3] = __builtin_shufflevector(b01, b23, 1, 3, 5, 7);
  c[4] = __builtin_shufflevector(d01, d23, 0, 2, 4, 6);
  c[5] = __builtin_shufflevector(d01, d23, 1, 3, 5, 7);
}

// The way back: six component vectors → four consecutive Voigt.
void from_lanes(const Lanes c[6], double* p) {
  const Lanes a01 = __builtin_shufflevector(c[0], c[1], 0, 4, 1, 5),
              a23 = __builtin_shufflevector(c[0], c[1], 2, 6, 3, 7);
  const Lanes b01 = __builtin_shufflevector(c[2], c[3], 0, 4, 1, 5),
              b23 = __builtin_shufflevector(c[2], c[3], 2, 6, 3, 7);
  const Lanes d01 = __builtin_shufflevector(c[4], c[5], 0, 4, 1, 5),
              d23 = __builtin_shufflevector(c[4], c[5], 2, 6, 3, 7);
  store(p, __builtin_shufflevector(a01, b01, 0, 1, 4, 5));
  store(p + 4, __builtin_shufflevector(d01, a01, 0, 1, 6, 7));
  store(p + 8, __builtin_shufflevector(b01, d01, 2, 3, 6, 7));
  store(p + 12, __builtin_shufflevector(a23, b23, 0, 1, 4, 5));
  store(p + 16, __builtin_shufflevector(d23, a23, 0, 1, 6, 7));
  store(p + 20, __builtin_shufflevector(b23, d23, 2, 3, 6, 7));
}

}  // namespace

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
    const Lanes major = select(upper < tt, tt, upper);  // std::max(upper, tt)
    const Lanes minor = select(tt < lower, tt, lower);  // std::min(lower, tt)
    const Lanes f = (major - minor) + (major + minor) * strength.sin_phi - cohesion_term;
    const Mask settles = (zt == 0.0) & (rt == 0.0) & ~(f > 0.0);
    for (int k = 0; k < 4; ++k) settled[i + static_cast<std::size_t>(k)] = settles[k] != 0;
  }
  for (; i < n; ++i) {  // the last points of a block not a multiple of four
    const ElasticTrial trial(stress[i], strain_increment[i], d);
    trial.store(stress[i]);
    settled[i] = trial.planar && !(strength.yield(trial.major, trial.minor) > 0.0);
  }
}

}  // namespace ffp
