#include "models/localisation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/LU>

#include "models/math_constants.hpp"
#include "models/principal_stress.hpp"

namespace ffp {

namespace {

Eigen::Matrix3d to_matrix(const Voigt& t) {
  Eigen::Matrix3d m;
  m << t[0], t[3], t[5], t[3], t[1], t[4], t[5], t[4], t[2];
  return m;
}

/// D:t = λ tr(t) I + 2G t.
Voigt elastic_map(const ElasticStiffness& d, const Voigt& t) { return d.stress_increment(t); }

Eigen::Vector3d in_plane_normal(double theta_rad) { return {std::cos(theta_rad), std::sin(theta_rad), 0.0}; }

}  // namespace

Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticFlow* flow, const Eigen::Vector3d& n) {
  const double g = elastic.shear_modulus(), lambda = elastic.lame_lambda();
  // A^e_jk = (λ + G) n_j n_k + G δ_jk
  Eigen::Matrix3d a_elastic = (lambda + g) * (n * n.transpose()) + g * Eigen::Matrix3d::Identity();
  if (flow == nullptr) return a_elastic;
  const ElasticStiffness d = ElasticStiffness::of(elastic);
  const Voigt dm = elastic_map(d, flow->flow_direction);  // a = D:m
  const Voigt dn = elastic_map(d, flow->yield_normal);    // b = D:n_f (D has major symmetry)
  const double chi = contract(flow->yield_normal, dm) + flow->hardening_modulus_Pa;
  assert(chi > 0.0 && "the plastic multiplier needs n_f:D:m + H > 0");
  // A_jk = A^e_jk − (a·n)_j (b·n)_k / χ (Rudnicki & Rice 1975)
  const Eigen::Vector3d an = to_matrix(dm) * n, bn = to_matrix(dn) * n;
  return a_elastic - (an * bn.transpose()) / chi;
}

double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticFlow* flow, double theta_rad) {
  const double g = elastic.shear_modulus();
  const double det_elastic = g * g * elastic.constrained_modulus();  // det A^e = G²(λ + 2G) for any unit n
  return acoustic_tensor(elastic, flow, in_plane_normal(theta_rad)).determinant() / det_elastic;
}

Localisation find_localisation(const ElasticConstants& elastic, const PlasticFlow& flow) {
  auto ratio = [&](double theta) { return acoustic_determinant_ratio(elastic, &flow, theta); };
  constexpr int kSamples = 180;  // every 1°: see the header for why this finds the global minimum
  const double step = kPi / kSamples;
  int best = 0;
  double best_ratio = ratio(0.0);
  for (int k = 1; k < kSamples; ++k) {
    const double r = ratio(k * step);
    if (r < best_ratio) best = k, best_ratio = r;
  }
  // Golden section on [θ_best − 1°, θ_best + 1°] (r is π-periodic: the bracket may cross 0).
  constexpr double kInverseGolden = 0.6180339887498949;  // (√5 − 1)/2
  double lo = (best - 1) * step, hi = (best + 1) * step;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double r1 = ratio(x1), r2 = ratio(x2);
  // Stop at 1e-12 rad: below √ε of a quadratic minimum's curvature scale, where r no
  // longer changes in double precision (about 50 iterations from 2°).
  while (hi - lo > 1e-12) {
    if (r1 <= r2) {
      hi = x2, x2 = x1, r2 = r1;
      x1 = hi - kInverseGolden * (hi - lo), r1 = ratio(x1);
    } else {
      lo = x1, x1 = x2, r1 = r2;
      x2 = lo + kInverseGolden * (hi - lo), r2 = ratio(x2);
    }
  }
  double theta = r1 <= r2 ? x1 : x2;
  double minimum = std::min({r1, r2, best_ratio});
  if (best_ratio < std::min(r1, r2)) theta = best * step;  // never worse than the best sample
  theta = std::fmod(theta, kPi);
  if (theta < 0.0) theta += kPi;
  return {minimum, theta, minimum <= kSingularAcousticRatio};
}

MohrCoulombFlow mohr_coulomb_flow(const Voigt& stress, const MohrCoulombStrength& strength) {
  const PrincipalStresses principal(stress);
  const Eigen::Vector3d& s = principal.values();
  // Stresses come back from Voigt storage: rounding is ~1e-15 of their size; 1e-9 of it
  // separates "on the surface" and "two principal values equal" from rounding while
  // being far below any physical difference.
  const double scale = std::max({std::abs(s[0]), std::abs(s[2]), strength.cohesion_Pa});
  const double tolerance = 1e-9 * scale;
  MohrCoulombFlow out;
  if (strength.yield(s) < -tolerance) return out;
  const double spread = s[0] - s[2];
  if (spread <= tolerance) {
    out.region = ReturnRegion::apex;
  } else if (s[0] - s[1] <= 1e-9 * spread) {
    out.region = ReturnRegion::edge_compression;  // σ1 = σ2 (triaxial compression)
  } else if (s[1] - s[2] <= 1e-9 * spread) {
    out.region = ReturnRegion::edge_extension;  // σ2 = σ3 (triaxial extension)
  } else {
    out.region = ReturnRegion::plane;
    // f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2c cos φ, g the same with ψ:
    // ∂f/∂σ = (1 + sin φ) e1⊗e1 − (1 − sin φ) e3⊗e3 on σ's own principal axes.
    out.flow.yield_normal = principal.with_values({1.0 + strength.sin_phi, 0.0, -(1.0 - strength.sin_phi)});
    out.flow.flow_direction = principal.with_values({1.0 + strength.sin_psi, 0.0, -(1.0 - strength.sin_psi)});
  }
  return out;
}

}  // namespace ffp
