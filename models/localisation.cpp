#include "models/localisation.hpp"

#include <algorithm>
#include <array>
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

constexpr int kSamples = 180;  // every 1°: the header says why this finds the global minimum

Eigen::Vector3d in_plane_normal(double theta_rad) { return {std::cos(theta_rad), std::sin(theta_rad), 0.0}; }

/// What A(n) needs of the law, formed once per point: λ, G, a = D:m, b = D:n_f (D has
/// major symmetry, so n_f:D = D:n_f) and χ = n_f:D:m + H.
struct AcousticTerms {
  double lambda = 0.0, shear = 0.0;
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero(), b = Eigen::Matrix3d::Zero();
  double chi = 1.0, coupling = 0.0, inverse_shear_chi = 0.0;
  bool plastic = false;

  AcousticTerms(const ElasticConstants& elastic, const PlasticFlow* flow)
      : lambda(elastic.lame_lambda()), shear(elastic.shear_modulus()), plastic(flow != nullptr) {
    if (!plastic) return;
    const ElasticStiffness d = ElasticStiffness::of(elastic);
    const Voigt dm = d.stress_increment(flow->flow_direction);  // D:t = λ tr(t) I + 2G t
    a = to_matrix(dm);
    b = to_matrix(d.stress_increment(flow->yield_normal));
    chi = contract(flow->yield_normal, dm) + flow->hardening_modulus_Pa;
    assert(chi > 0.0 && "the plastic multiplier needs n_f:D:m + H > 0");
    coupling = (lambda + shear) / (lambda + 2.0 * shear);
    inverse_shear_chi = 1.0 / (shear * chi);
  }

  Eigen::Matrix3d tensor(const Eigen::Vector3d& n) const {
    // A^e_jk = (λ + G) n_j n_k + G δ_jk
    const Eigen::Matrix3d elastic = (lambda + shear) * (n * n.transpose()) + shear * Eigen::Matrix3d::Identity();
    if (!plastic) return elastic;
    // A_jk = A^e_jk − (a·n)_j (b·n)_k / χ (Rudnicki & Rice 1975)
    return elastic - ((a * n) * (b * n).transpose()) / chi;
  }

  /// det A(n) / det A^e by the matrix determinant lemma (A is A^e less a rank-one term):
  /// r = 1 − (b·n)·(A^e)⁻¹(a·n)/χ, (A^e)⁻¹ = (I − (λ + G)/(λ + 2G) n⊗n)/G. No determinant
  /// and no division per direction: the sampling below takes 180 of them per point.
  double ratio(const Eigen::Vector3d& n) const {
    if (!plastic) return 1.0;
    const Eigen::Vector3d an = a * n, bn = b * n;
    return 1.0 - (bn.dot(an) - coupling * n.dot(bn) * n.dot(an)) * inverse_shear_chi;
  }
  double ratio(double theta_rad) const { return ratio(in_plane_normal(theta_rad)); }
};

}  // namespace

Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticFlow* flow, const Eigen::Vector3d& n) {
  return AcousticTerms(elastic, flow).tensor(n);
}

double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticFlow* flow, double theta_rad) {
  return AcousticTerms(elastic, flow).ratio(theta_rad);
}

Localisation find_localisation(const ElasticConstants& elastic, const PlasticFlow& flow) {
  const AcousticTerms terms(elastic, &flow);
  auto ratio = [&](double theta) { return terms.ratio(theta); };
  const double step = kPi / kSamples;
  static const std::array<Eigen::Vector3d, kSamples> sampled = [] {
    std::array<Eigen::Vector3d, kSamples> n;
    for (int k = 0; k < kSamples; ++k) n[k] = in_plane_normal(k * (kPi / kSamples));
    return n;
  }();
  int best = 0;
  double best_ratio = terms.ratio(sampled[0]);
  for (int k = 1; k < kSamples; ++k) {
    const double r = terms.ratio(sampled[k]);
    if (r < best_ratio) best = k, best_ratio = r;
  }
  // Golden section on [θ_best − 1°, θ_best + 1°] (r is π-periodic: the bracket may cross 0).
  constexpr double kInverseGolden = 0.6180339887498949;  // (√5 − 1)/2
  double lo = (best - 1) * step, hi = (best + 1) * step;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double r1 = ratio(x1), r2 = ratio(x2);
  // Stop at 1e-10 rad (about 40 iterations from 2°): near √ε, where r stops changing in
  // double precision at a quadratic minimum.
  while (hi - lo > 1e-10) {
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
