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

constexpr int kSamples = 180;  // every 1°: the header says why this finds the global maximum of t

Eigen::Vector3d in_plane_normal(double theta_rad) { return {std::cos(theta_rad), std::sin(theta_rad), 0.0}; }

/// t(θ) = t0 + c2 cos 2θ + s2 sin 2θ + c4 cos 4θ + s4 sin 4θ, and its derivatives.
struct Harmonics {
  double t0 = 0.0, c2 = 0.0, s2 = 0.0, c4 = 0.0, s4 = 0.0;

  /// cos 2θ, sin 2θ, cos 4θ, sin 4θ from one sincos (4θ by the double-angle formulas).
  struct Angles {
    double cos2, sin2, cos4, sin4;
    explicit Angles(double theta)
        : cos2(std::cos(2.0 * theta)),
          sin2(std::sin(2.0 * theta)),
          cos4(2.0 * cos2 * cos2 - 1.0),
          sin4(2.0 * sin2 * cos2) {}
  };
  double value(const Angles& a) const { return t0 + c2 * a.cos2 + s2 * a.sin2 + c4 * a.cos4 + s4 * a.sin4; }
  double slope(const Angles& a) const { return 2.0 * (s2 * a.cos2 - c2 * a.sin2) + 4.0 * (s4 * a.cos4 - c4 * a.sin4); }
  double curvature(const Angles& a) const {
    return -4.0 * (c2 * a.cos2 + s2 * a.sin2) - 16.0 * (c4 * a.cos4 + s4 * a.sin4);
  }
  double value(double theta) const { return value(Angles(theta)); }
  double slope(double theta) const { return slope(Angles(theta)); }
};

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
  /// det A(n) / det A^e = 1 − t/(Gχ) (the matrix determinant lemma: A is A^e less a rank-one term).
  double coupling_term(const Eigen::Vector3d& n) const {
    const Eigen::Vector3d an = a * n, bn = b * n;
    return bn.dot(an) - coupling * n.dot(bn) * n.dot(an);
  }
  double ratio(double theta_rad) const {
    if (!plastic) return 1.0;
    assert(chi != 0.0 && "r(θ) needs χ = n_f:D:m + H ≠ 0");
    return 1.0 - coupling_term(in_plane_normal(theta_rad)) * inverse_shear_chi;
  }

  /// t(θ) for n = (cos θ, sin θ, 0) as its harmonics: with c = cos θ, s = sin θ, b_i the i-th
  /// column of b and B_ij = b_i·a_j, (b·n)·(a·n) = c² B00 + cs (B01 + B10) + s² B11 and
  /// n·b·n = c² b00 + 2cs b01 + s² b11 (the same for a); c² = (1 + cos 2θ)/2, s² = (1 − cos 2θ)/2
  /// and cs = sin 2θ/2 turn t = (b·n)·(a·n) − κ (n·b·n)(n·a·n), κ = (λ + G)/(λ + 2G), into five
  /// numbers: the search then costs a few multiplications per direction.
  Harmonics harmonics() const {
    struct Pair {  // x0 + x2c cos 2θ + x2s sin 2θ
      double x0, x2c, x2s;
    };
    auto of_normal = [](const Eigen::Matrix3d& m) {
      return Pair{0.5 * (m(0, 0) + m(1, 1)), 0.5 * (m(0, 0) - m(1, 1)), m(0, 1)};
    };
    const double b00 = b.col(0).dot(a.col(0)), b01 = b.col(0).dot(a.col(1)), b10 = b.col(1).dot(a.col(0)),
                 b11 = b.col(1).dot(a.col(1));
    const Pair product{0.5 * (b00 + b11), 0.5 * (b00 - b11), 0.5 * (b01 + b10)};  // (b·n)·(a·n)
    const Pair nb = of_normal(b), na = of_normal(a);
    // (n·b·n)(n·a·n), with cos² 2θ = (1 + cos 4θ)/2, sin² 2θ = (1 − cos 4θ)/2, cos 2θ sin 2θ = sin 4θ/2.
    const double k = coupling;
    Harmonics h;
    h.t0 = product.x0 - k * (nb.x0 * na.x0 + 0.5 * (nb.x2c * na.x2c + nb.x2s * na.x2s));
    h.c2 = product.x2c - k * (nb.x0 * na.x2c + na.x0 * nb.x2c);
    h.s2 = product.x2s - k * (nb.x0 * na.x2s + na.x0 * nb.x2s);
    h.c4 = -k * 0.5 * (nb.x2c * na.x2c - nb.x2s * na.x2s);
    h.s4 = -k * 0.5 * (nb.x2c * na.x2s + nb.x2s * na.x2c);
    return h;
  }
};

struct Maximum {
  double theta_rad, value;
};

/// Golden section for the largest t on [lo, hi], stopping at 1e-10 rad (about 40 steps from
/// 2°): near √ε, where t stops changing in double precision at a quadratic maximum.
Maximum golden_section(const Harmonics& t, double lo, double hi) {
  constexpr double kInverseGolden = 0.6180339887498949;  // (√5 − 1)/2
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double t1 = t.value(x1), t2 = t.value(x2);
  while (hi - lo > 1e-10) {
    if (t1 >= t2) {
      hi = x2, x2 = x1, t2 = t1;
      x1 = hi - kInverseGolden * (hi - lo), t1 = t.value(x1);
    } else {
      lo = x1, x1 = x2, t1 = t2;
      x2 = lo + kInverseGolden * (hi - lo), t2 = t.value(x2);
    }
  }
  return t1 >= t2 ? Maximum{x1, t1} : Maximum{x2, t2};
}

/// t' = 0 between lo (t' > 0) and hi (t' < 0): Newton's steps, a bisection wherever a step
/// would leave the bracket or t'' ≥ 0, until Newton's step is below 1e-13 rad (a few steps
/// from 1°; near the rounding of θ).
Maximum newton(const Harmonics& t, double lo, double hi, double start) {
  double x = start;
  for (int k = 0; k < 60 && hi - lo > 1e-13; ++k) {
    const Harmonics::Angles at(x);
    const double slope = t.slope(at), curvature = t.curvature(at);
    if (curvature < 0.0 && std::abs(slope) <= 1e-13 * -curvature) break;
    (slope > 0.0 ? lo : hi) = x;
    const double step = curvature < 0.0 ? x - slope / curvature : lo;
    x = step > lo && step < hi ? step : 0.5 * (lo + hi);
  }
  return {x, t.value(x)};
}

/// The largest t(θ) over θ ∈ [0, π): every 1° (the header says why this brackets the global
/// maximum), then refined in [θ_best − 1°, θ_best + 1°] (t is π-periodic: the bracket may cross 0).
Maximum largest_coupling(const AcousticTerms& terms) {
  const double step = kPi / kSamples;
  // The sampled directions' cos 2θ, sin 2θ, cos 4θ, sin 4θ, one array each: the values
  // below are then one vectorised loop.
  struct Table {
    std::array<double, kSamples> cos2, sin2, cos4, sin4;
  };
  static const Table table = [] {
    Table d;
    for (int k = 0; k < kSamples; ++k) {
      const Harmonics::Angles a(k * (kPi / kSamples));
      d.cos2[k] = a.cos2, d.sin2[k] = a.sin2, d.cos4[k] = a.cos4, d.sin4[k] = a.sin4;
    }
    return d;
  }();
  const Harmonics t = terms.harmonics();
  std::array<double, kSamples> values;
  for (int k = 0; k < kSamples; ++k)
    values[k] = t.t0 + t.c2 * table.cos2[k] + t.s2 * table.sin2[k] + t.c4 * table.cos4[k] + t.s4 * table.sin4[k];
  const int best = static_cast<int>(std::max_element(values.begin(), values.end()) - values.begin());
  const double best_value = values[best];
  const double lo = (best - 1) * step, hi = (best + 1) * step;
  // A maximum strictly inside a bracket whose ends rise and fall takes Newton's steps; two
  // maxima within 2° (or a flat t) take the golden section.
  Maximum found = t.slope(lo) > 0.0 && t.slope(hi) < 0.0 ? newton(t, lo, hi, best * step) : golden_section(t, lo, hi);
  if (best_value > found.value) found = {best * step, best_value};  // never worse than the best sample
  found.theta_rad = std::fmod(found.theta_rad, kPi);
  if (found.theta_rad < 0.0) found.theta_rad += kPi;
  return found;
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
