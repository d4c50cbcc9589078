#include "models/localisation.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

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
/// major symmetry, so n_f:D = D:n_f), n_f:D:m and χ = n_f:D:m + H.
struct AcousticTerms {
  double lambda = 0.0, shear = 0.0;
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero(), b = Eigen::Matrix3d::Zero();
  double plastic_stiffness = 0.0, chi = 1.0, coupling = 0.0, inverse_shear_chi = 0.0;
  bool plastic = false;

  AcousticTerms(const ElasticConstants& elastic, const PlasticFlow* flow)
      : lambda(elastic.lame_lambda()), shear(elastic.shear_modulus()), plastic(flow != nullptr) {
    if (!plastic) return;
    const ElasticStiffness d = ElasticStiffness::of(elastic);
    const Voigt dm = d.stress_increment(flow->flow_direction);  // D:t = λ tr(t) I + 2G t
    a = to_matrix(dm);
    b = to_matrix(d.stress_increment(flow->yield_normal));
    plastic_stiffness = contract(flow->yield_normal, dm);
    chi = plastic_stiffness + flow->hardening_modulus_Pa;
    coupling = (lambda + shear) / (lambda + 2.0 * shear);
    inverse_shear_chi = chi != 0.0 ? 1.0 / (shear * chi) : 0.0;
  }

  Eigen::Matrix3d tensor(const Eigen::Vector3d& n) const {
    // A^e_jk = (λ + G) n_j n_k + G δ_jk
    const Eigen::Matrix3d elastic = (lambda + shear) * (n * n.transpose()) + shear * Eigen::Matrix3d::Identity();
    if (!plastic) return elastic;
    assert(chi != 0.0 && "A(n) needs χ = n_f:D:m + H ≠ 0");
    // A_jk = A^e_jk − (a·n)_j (b·n)_k / χ (Rudnicki & Rice 1975)
    return elastic - ((a * n) * (b * n).transpose()) / chi;
  }

  /// t(n) = G (b·n)·(A^e)⁻¹(a·n), (A^e)⁻¹ = (I − (λ + G)/(λ + 2G) n⊗n)/G: the H-free part of
  /// det A(n) / det A^e = 1 − t/(Gχ) (the matrix determinant lemma: A is A^e less a rank-one
  /// term). No determinant and no division per direction: the search takes 180 of them per point.
  double coupling_term(const Eigen::Vector3d& n) const {
    const Eigen::Vector3d an = a * n, bn = b * n;
    return bn.dot(an) - coupling * n.dot(bn) * n.dot(an);
  }
  double coupling_term(double theta_rad) const { return coupling_term(in_plane_normal(theta_rad)); }
  double ratio(double theta_rad) const {
    if (!plastic) return 1.0;
    assert(chi != 0.0 && "r(θ) needs χ = n_f:D:m + H ≠ 0");
    return 1.0 - coupling_term(theta_rad) * inverse_shear_chi;
  }
};

struct Maximum {
  double theta_rad, value;
};

/// The largest t(θ) over θ ∈ [0, π): every 1° (the header says why this finds the global
/// maximum), then golden section on [θ_best − 1°, θ_best + 1°] (t is π-periodic: the bracket
/// may cross 0).
Maximum largest_coupling(const AcousticTerms& terms) {
  const double step = kPi / kSamples;
  static const std::array<Eigen::Vector3d, kSamples> sampled = [] {
    std::array<Eigen::Vector3d, kSamples> n;
    for (int k = 0; k < kSamples; ++k) n[k] = in_plane_normal(k * (kPi / kSamples));
    return n;
  }();
  int best = 0;
  double best_value = terms.coupling_term(sampled[0]);
  for (int k = 1; k < kSamples; ++k) {
    const double t = terms.coupling_term(sampled[k]);
    if (t > best_value) best = k, best_value = t;
  }
  auto t = [&](double theta) { return terms.coupling_term(theta); };
  constexpr double kInverseGolden = 0.6180339887498949;  // (√5 − 1)/2
  double lo = (best - 1) * step, hi = (best + 1) * step;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double t1 = t(x1), t2 = t(x2);
  // Stop at 1e-10 rad (about 40 iterations from 2°): near √ε, where t stops changing in
  // double precision at a quadratic maximum.
  while (hi - lo > 1e-10) {
    if (t1 >= t2) {
      hi = x2, x2 = x1, t2 = t1;
      x1 = hi - kInverseGolden * (hi - lo), t1 = t(x1);
    } else {
      lo = x1, x1 = x2, t1 = t2;
      x2 = lo + kInverseGolden * (hi - lo), t2 = t(x2);
    }
  }
  double theta = t1 >= t2 ? x1 : x2;
  const double maximum = std::max({t1, t2, best_value});
  if (best_value > std::max(t1, t2)) theta = best * step;  // never worse than the best sample
  theta = std::fmod(theta, kPi);
  if (theta < 0.0) theta += kPi;
  return {theta, maximum};
}

}  // namespace

Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticFlow* flow, const Eigen::Vector3d& n) {
  return AcousticTerms(elastic, flow).tensor(n);
}

double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticFlow* flow, double theta_rad) {
  return AcousticTerms(elastic, flow).ratio(theta_rad);
}

Localisation find_localisation(const ElasticConstants& elastic, const PlasticFlow& flow) {
  const AcousticTerms terms(elastic, &flow);
  const Maximum top = largest_coupling(terms);
  Localisation out;
  out.band_normal_rad = top.theta_rad;
  out.critical_hardening_Pa = top.value / terms.shear - terms.plastic_stiffness;
  if (terms.chi > 0.0) {
    out.determinant_ratio = 1.0 - top.value * terms.inverse_shear_chi;
    out.localised = out.determinant_ratio <= kSingularAcousticRatio;
  } else {
    out.determinant_ratio = -std::numeric_limits<double>::infinity();
    out.localised = flow.hardening_modulus_Pa <= out.critical_hardening_Pa;
  }
  return out;
}

double mohr_coulomb_softening_modulus(double major, double minor, const MohrCoulombStrength& strength,
                                      const StrengthSlopes& slopes) {
  // ∂f/∂κ of f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2c cos φ through φ(κ) and c(κ).
  const double df_dkappa =
      ((major + minor) * strength.cos_phi + 2.0 * strength.cohesion_Pa * strength.sin_phi) * slopes.friction_rad -
      2.0 * strength.cos_phi * slopes.cohesion_Pa;
  // κ̇ = √(2/3 ė^p:ė^p) = λ̇ √(2/3) |dev m|, m = diag(1 + sin ψ, 0, −(1 − sin ψ)): (2/3)√(3 + sin²ψ).
  const double strain_per_multiplier = (2.0 / 3.0) * std::sqrt(3.0 + strength.sin_psi * strength.sin_psi);
  return -strain_per_multiplier * df_dkappa;
}

MohrCoulombFlow mohr_coulomb_flow(const Voigt& stress, const MohrCoulombStrength& strength,
                                  const StrengthSlopes& slopes) {
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
    out.flow.hardening_modulus_Pa = mohr_coulomb_softening_modulus(s[0], s[2], strength, slopes);
  }
  return out;
}

}  // namespace ffp
