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

constexpr int kSamples = 180;  // every 1°: the header says why this finds the global maximum

Eigen::Vector3d in_plane_normal(double theta_rad) { return {std::cos(theta_rad), std::sin(theta_rad), 0.0}; }

/// p(θ) = a_0 + Σ_{k=1..K} (a_k cos 2kθ + b_k sin 2kθ), and its derivatives: t(θ) of one
/// mechanism pair (K = 2) and det(G − T(θ)) of a corner (K = 4, products of K = 2 ones).
template <int K>
struct TrigPolynomial {
  std::array<double, K + 1> a{}, b{};  ///< b_0 is 0

  /// cos 2kθ, sin 2kθ for k = 0..K from one cos and one sin (Chebyshev's recurrences,
  /// cos 2(k+1)θ = 2 cos 2θ cos 2kθ − cos 2(k−1)θ, and the same for sin).
  struct Angles {
    std::array<double, K + 1> cos, sin;
    explicit Angles(double theta) {
      cos[0] = 1.0, sin[0] = 0.0;
      cos[1] = std::cos(2.0 * theta), sin[1] = std::sin(2.0 * theta);
      for (int k = 2; k <= K; ++k) {
        cos[k] = 2.0 * cos[1] * cos[k - 1] - cos[k - 2];
        sin[k] = 2.0 * cos[1] * sin[k - 1] - sin[k - 2];
      }
    }
  };
  double value(const Angles& x) const {
    double sum = a[0];
    for (int k = 1; k <= K; ++k) {
      sum += a[k] * x.cos[k];
      sum += b[k] * x.sin[k];
    }
    return sum;
  }
  double slope(const Angles& x) const {
    double sum = 0.0;
    for (int k = 1; k <= K; ++k) sum += 2.0 * k * (b[k] * x.cos[k] - a[k] * x.sin[k]);
    return sum;
  }
  double curvature(const Angles& x) const {
    double sum = 0.0;
    for (int k = 1; k <= K; ++k) sum -= 4.0 * k * k * (a[k] * x.cos[k] + b[k] * x.sin[k]);
    return sum;
  }
  double value(double theta) const { return value(Angles(theta)); }
  double slope(double theta) const { return slope(Angles(theta)); }
};
using Harmonics = TrigPolynomial<2>;
using CornerHarmonics = TrigPolynomial<4>;

/// p q by the product-to-sum formulas: (a_k cos kφ + b_k sin kφ)(a_l cos lφ + b_l sin lφ) =
/// ½[(a_k a_l − b_k b_l) cos(k+l)φ + (a_k a_l + b_k b_l) cos(k−l)φ + (a_k b_l + b_k a_l) sin(k+l)φ
///    + (b_k a_l − a_k b_l) sin(k−l)φ], φ = 2θ, with sin(−mφ) = −sin mφ.
template <int K, int L>
TrigPolynomial<K + L> operator*(const TrigPolynomial<K>& p, const TrigPolynomial<L>& q) {
  TrigPolynomial<K + L> out;
  for (int k = 0; k <= K; ++k)
    for (int l = 0; l <= L; ++l) {
      const double aa = p.a[k] * q.a[l], bb = p.b[k] * q.b[l], ab = p.a[k] * q.b[l], ba = p.b[k] * q.a[l];
      out.a[k + l] += 0.5 * (aa - bb);
      out.b[k + l] += 0.5 * (ab + ba);
      const int m = k - l, sign = m < 0 ? -1 : 1;
      out.a[sign * m] += 0.5 * (aa + bb);
      out.b[sign * m] += sign * 0.5 * (ba - ab);
    }
  out.b[0] = 0.0;  // sin 0 = 0: what the products put there
  return out;
}

template <int K>
TrigPolynomial<K> operator-(TrigPolynomial<K> p, const TrigPolynomial<K>& q) {
  for (int k = 0; k <= K; ++k) p.a[k] -= q.a[k], p.b[k] -= q.b[k];
  return p;
}

/// t(n) = G (b·n)·(A^e)⁻¹(a·n) = (b·n)·(a·n) − κ (n·b·n)(n·a·n), (A^e)⁻¹ = (I − κ n⊗n)/G,
/// κ = (λ + G)/(λ + 2G): the H-free part of a mechanism pair's term in det A / det A^e.
double coupling_term(const Eigen::Matrix3d& b, const Eigen::Matrix3d& a, double coupling, const Eigen::Vector3d& n) {
  const Eigen::Vector3d an = a * n, bn = b * n;
  return bn.dot(an) - coupling * n.dot(bn) * n.dot(an);
}

/// t(θ) for n = (cos θ, sin θ, 0) as its harmonics: with c = cos θ, s = sin θ, b_i the i-th
/// column of b and B_ij = b_i·a_j, (b·n)·(a·n) = c² B00 + cs (B01 + B10) + s² B11 and
/// n·b·n = c² b00 + 2cs b01 + s² b11 (the same for a); c² = (1 + cos 2θ)/2, s² = (1 − cos 2θ)/2
/// and cs = sin 2θ/2 turn t = (b·n)·(a·n) − κ (n·b·n)(n·a·n) into five numbers: the search
/// then costs a few multiplications per direction.
Harmonics coupling_harmonics(const Eigen::Matrix3d& b, const Eigen::Matrix3d& a, double coupling) {
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
  h.a[0] = product.x0 - k * (nb.x0 * na.x0 + 0.5 * (nb.x2c * na.x2c + nb.x2s * na.x2s));
  h.a[1] = product.x2c - k * (nb.x0 * na.x2c + na.x0 * nb.x2c);
  h.b[1] = product.x2s - k * (nb.x0 * na.x2s + na.x0 * nb.x2s);
  h.a[2] = -k * 0.5 * (nb.x2c * na.x2c - nb.x2s * na.x2s);
  h.b[2] = -k * 0.5 * (nb.x2c * na.x2s + nb.x2s * na.x2c);
  return h;
}

/// A^e_jk = (λ + G) n_j n_k + G δ_jk
Eigen::Matrix3d elastic_acoustic_tensor(double lambda, double shear, const Eigen::Vector3d& n) {
  return (lambda + shear) * (n * n.transpose()) + shear * Eigen::Matrix3d::Identity();
}

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
    const Eigen::Matrix3d elastic = elastic_acoustic_tensor(lambda, shear, n);
    if (!plastic) return elastic;
    assert(chi != 0.0 && "A(n) needs χ = n_f:D:m + H ≠ 0");
    // A_jk = A^e_jk − (a·n)_j (b·n)_k / χ (Rudnicki & Rice 1975)
    return elastic - ((a * n) * (b * n).transpose()) / chi;
  }

  /// det A(n) / det A^e = 1 − t/(Gχ) (the matrix determinant lemma: A is A^e less a rank-one term).
  double ratio(double theta_rad) const {
    if (!plastic) return 1.0;
    assert(chi != 0.0 && "r(θ) needs χ = n_f:D:m + H ≠ 0");
    return 1.0 - coupling_term(b, a, coupling, in_plane_normal(theta_rad)) * inverse_shear_chi;
  }
  Harmonics harmonics() const { return coupling_harmonics(b, a, coupling); }
};

/// What a corner's A(n) needs, formed once per point: a_a = D:m_a, b_a = D:n_a and G.
struct CornerTerms {
  double lambda = 0.0, shear = 0.0, coupling = 0.0;
  std::array<Eigen::Matrix3d, 2> a, b;
  Eigen::Matrix2d g;

  CornerTerms(const ElasticConstants& elastic, const PlasticCorner& corner)
      : lambda(elastic.lame_lambda()), shear(elastic.shear_modulus()) {
    coupling = (lambda + shear) / (lambda + 2.0 * shear);
    const ElasticStiffness d = ElasticStiffness::of(elastic);
    std::array<Voigt, 2> dm;
    for (int k = 0; k < 2; ++k) {
      dm[k] = d.stress_increment(corner.flow_directions[k]);
      a[k] = to_matrix(dm[k]);
      b[k] = to_matrix(d.stress_increment(corner.yield_normals[k]));
    }
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) g(i, j) = contract(corner.yield_normals[i], dm[j]) + corner.hardening_Pa(i, j);
  }

  /// G a P-matrix: one solution of the multipliers for every rate (models/localisation.hpp).
  bool loading_branch() const { return g(0, 0) > 0.0 && g(1, 1) > 0.0 && g.determinant() > 0.0; }

  Eigen::Matrix3d tensor(const Eigen::Vector3d& n) const {
    assert(g.determinant() != 0.0 && "A(n) needs det G ≠ 0");
    // A = A^e − Σ_ab (a_a·n) (G⁻¹)_ab (b_b·n) (Koiter's tangent contracted with n on both sides)
    const Eigen::Matrix2d inverse = g.inverse();
    Eigen::Matrix3d out = elastic_acoustic_tensor(lambda, shear, n);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) out -= inverse(i, j) * ((a[i] * n) * (b[j] * n).transpose());
    return out;
  }

  /// det A / det A^e = det(G − T(n)) / det G, T_ab = t(b_a, a_b)/G (the matrix determinant lemma).
  double ratio(double theta_rad) const {
    assert(g.determinant() != 0.0 && "r(θ) needs det G ≠ 0");
    const Eigen::Vector3d n = in_plane_normal(theta_rad);
    Eigen::Matrix2d t;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) t(i, j) = coupling_term(b[i], a[j], coupling, n) / shear;
    return (g - t).determinant() / g.determinant();
  }

  /// T_ab(θ) = t(b_a, a_b)/G as harmonics, row-major (T_11, T_12, T_21, T_22).
  std::array<Harmonics, 4> coupling_harmonics_over_shear() const {
    std::array<Harmonics, 4> t;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        Harmonics& h = t[2 * i + j];
        h = coupling_harmonics(b[i], a[j], coupling);
        for (int k = 0; k <= 2; ++k) h.a[k] /= shear, h.b[k] /= shear;
      }
    return t;
  }
};

/// M(θ) = G − T(θ) entry by entry, and F(θ) = −det M(θ) = M12 M21 − M11 M22: what the search
/// maximises (r = −F/det G).
struct CornerDeterminant {
  std::array<Harmonics, 4> m;  ///< M_11, M_12, M_21, M_22
  CornerHarmonics minus_determinant;

  explicit CornerDeterminant(const CornerTerms& terms) {
    const std::array<Harmonics, 4> t = terms.coupling_harmonics_over_shear();
    const std::array<double, 4> g = {terms.g(0, 0), terms.g(0, 1), terms.g(1, 0), terms.g(1, 1)};
    for (int k = 0; k < 4; ++k) {
      Harmonics constant;
      constant.a[0] = g[k];
      m[k] = constant - t[k];
    }
    minus_determinant = m[1] * m[2] - m[0] * m[3];
  }
  /// A bound on |M11 M22| + |M12 M21| over θ (each entry's harmonics' absolute sum): the size
  /// of the two products det M is the difference of, hence of its rounding, wherever it is
  /// evaluated and however its harmonics are formed.
  double products_bound() const {
    auto size = [](const Harmonics& h) {
      double sum = 0.0;
      for (int k = 0; k <= 2; ++k) sum += std::abs(h.a[k]) + std::abs(h.b[k]);
      return sum;
    };
    return size(m[0]) * size(m[3]) + size(m[1]) * size(m[2]);
  }
};

struct Maximum {
  double theta_rad, value;
};

/// Golden section for the largest f on [lo, hi], stopping at 1e-10 rad (about 40 steps from
/// 2°): near √ε, where f stops changing in double precision at a quadratic maximum.
template <int K>
Maximum golden_section(const TrigPolynomial<K>& f, double lo, double hi) {
  constexpr double kInverseGolden = 0.6180339887498949;  // (√5 − 1)/2
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double f1 = f.value(x1), f2 = f.value(x2);
  while (hi - lo > 1e-10) {
    if (f1 >= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kInverseGolden * (hi - lo), f1 = f.value(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kInverseGolden * (hi - lo), f2 = f.value(x2);
    }
  }
  return f1 >= f2 ? Maximum{x1, f1} : Maximum{x2, f2};
}

/// f' = 0 between lo (f' > 0) and hi (f' < 0): Newton's steps, a bisection wherever a step
/// would leave the bracket or f'' ≥ 0, until Newton's step is below 1e-13 rad (a few steps
/// from 1°; near the rounding of θ).
template <int K>
Maximum newton(const TrigPolynomial<K>& f, double lo, double hi, double start) {
  double x = start;
  for (int k = 0; k < 60 && hi - lo > 1e-13; ++k) {
    const typename TrigPolynomial<K>::Angles at(x);
    const double slope = f.slope(at), curvature = f.curvature(at);
    if (curvature < 0.0 && std::abs(slope) <= 1e-13 * -curvature) break;
    (slope > 0.0 ? lo : hi) = x;
    const double step = curvature < 0.0 ? x - slope / curvature : lo;
    x = step > lo && step < hi ? step : 0.5 * (lo + hi);
  }
  return {x, f.value(x)};
}

using Samples = std::array<double, kSamples>;

/// The sampled directions' cos 2kθ and sin 2kθ, k = 1..4, one array each: a polynomial's
/// samples are then one vectorised loop.
struct SampledAngles {
  std::array<Samples, 5> cos, sin;  ///< [k][sample]; k = 0 unused
};
const SampledAngles& sampled_angles() {
  static const SampledAngles table = [] {
    SampledAngles d;
    for (int i = 0; i < kSamples; ++i) {
      const CornerHarmonics::Angles x(i * (kPi / kSamples));
      for (int k = 1; k <= 4; ++k) d.cos[k][i] = x.cos[k], d.sin[k][i] = x.sin[k];
    }
    return d;
  }();
  return table;
}

template <int K>
Samples sampled(const TrigPolynomial<K>& p) {
  const SampledAngles& table = sampled_angles();
  Samples values;
  for (int i = 0; i < kSamples; ++i) {  // each sample whole in registers, the samples side by side
    double sum = p.a[0];
    for (int k = 1; k <= K; ++k) {
      sum += p.a[k] * table.cos[k][i];
      sum += p.b[k] * table.sin[k][i];
    }
    values[i] = sum;
  }
  return values;
}

/// The largest f(θ) over θ ∈ [0, π): every 1° (the header says why this brackets the global
/// maximum), then refined in [θ_best − 1°, θ_best + 1°] (f is π-periodic: the bracket may cross 0).
template <int K>
Maximum largest(const TrigPolynomial<K>& f) {
  const double step = kPi / kSamples;
  const Samples values = sampled(f);
  // The first largest sample, as std::max_element finds it, in two passes without its chain of
  // dependent compares (measured: that chain took 60 % of the whole search): the maximum over
  // twelve running maxima side by side, then where it first occurs.
  constexpr int kLanes = 12;
  static_assert(kSamples % kLanes == 0);
  std::array<double, kLanes> lanes;
  std::copy_n(values.begin(), kLanes, lanes.begin());
  for (int k = kLanes; k < kSamples; k += kLanes)
    for (int j = 0; j < kLanes; ++j) lanes[j] = values[k + j] > lanes[j] ? values[k + j] : lanes[j];
  double best_value = lanes[0];
  for (const double v : lanes) best_value = v > best_value ? v : best_value;
  const auto first = std::find(values.begin(), values.end(), best_value);
  const int best = first == values.end() ? 0 : static_cast<int>(first - values.begin());  // end: NaN samples
  const double lo = (best - 1) * step, hi = (best + 1) * step;
  // A maximum strictly inside a bracket whose ends rise and fall takes Newton's steps; two
  // maxima within 2° (or a flat f) take the golden section.
  Maximum found = f.slope(lo) > 0.0 && f.slope(hi) < 0.0 ? newton(f, lo, hi, best * step) : golden_section(f, lo, hi);
  if (best_value > found.value) found = {best * step, best_value};  // never worse than the best sample
  found.theta_rad = std::fmod(found.theta_rad, kPi);
  if (found.theta_rad < 0.0) found.theta_rad += kPi;
  return found;
}

/// The principal-axis tensor Σ_k v_k e_k⊗e_k of a plane (i, j): (1 + sin x) e_i⊗e_i − (1 − sin x) e_j⊗e_j.
Eigen::Vector3d plane_gradient(int major, int minor, double sin_angle) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v[major] = 1.0 + sin_angle;
  v[minor] = -(1.0 - sin_angle);
  return v;
}

/// ∂f/∂κ of f = (σi − σj) + (σi + σj) sin φ − 2c cos φ through φ(κ) and c(κ).
double yield_slope(double major, double minor, const MohrCoulombStrength& strength, const StrengthSlopes& slopes) {
  return ((major + minor) * strength.cos_phi + 2.0 * strength.cohesion_Pa * strength.sin_phi) * slopes.friction_rad -
         2.0 * strength.cos_phi * slopes.cohesion_Pa;
}

/// The return's two planes at an edge (models/mohr_coulomb_return.hpp), with H_ab of the even split.
PlasticCorner edge_corner(const PrincipalStresses& principal, bool compression, const MohrCoulombStrength& strength,
                          const StrengthSlopes& slopes) {
  const Eigen::Vector3d& s = principal.values();
  // Compression σ1 = σ2: planes (1,3) and (2,3). Extension σ2 = σ3: planes (1,3) and (1,2).
  const std::array<std::array<int, 2>, 2> planes = compression ? std::array<std::array<int, 2>, 2>{{{0, 2}, {1, 2}}}
                                                               : std::array<std::array<int, 2>, 2>{{{0, 2}, {0, 1}}};
  PlasticCorner corner;
  for (int k = 0; k < 2; ++k) {
    corner.yield_normals[k] = principal.with_values(plane_gradient(planes[k][0], planes[k][1], strength.sin_phi));
    corner.flow_directions[k] = principal.with_values(plane_gradient(planes[k][0], planes[k][1], strength.sin_psi));
  }
  // κ̇ = k (λ̇_a + λ̇_b) at the even split, k = √(2/3)|dev(m_a + m_b)|/2 = 1 ∓ sin ψ/3; both
  // planes share σi + σj (σ1 + σ3), so ∂f_a/∂κ = ∂f_b/∂κ and H_ab = −k ∂f/∂κ for every a, b.
  const double strain_per_multiplier = compression ? 1.0 - strength.sin_psi / 3.0 : 1.0 + strength.sin_psi / 3.0;
  corner.hardening_Pa.setConstant(-strain_per_multiplier * yield_slope(s[0], s[2], strength, slopes));
  return corner;
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
  const Maximum top = largest(terms.harmonics());
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

Eigen::Matrix2d corner_stiffness(const ElasticConstants& elastic, const PlasticCorner& corner) {
  return CornerTerms(elastic, corner).g;
}

Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticCorner& corner,
                                const Eigen::Vector3d& n) {
  return CornerTerms(elastic, corner).tensor(n);
}

double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticCorner& corner, double theta_rad) {
  return CornerTerms(elastic, corner).ratio(theta_rad);
}

Localisation find_localisation(const ElasticConstants& elastic, const PlasticCorner& corner) {
  const CornerTerms terms(elastic, corner);
  Localisation out;
  out.critical_hardening_Pa = std::numeric_limits<double>::quiet_NaN();
  if (!terms.loading_branch()) {
    out.determinant_ratio = -std::numeric_limits<double>::infinity();
    out.localised = true;
    return out;
  }
  const CornerDeterminant f(terms);
  const Maximum top = largest(f.minus_determinant);
  out.band_normal_rad = top.theta_rad;
  out.determinant_ratio = -top.value / terms.g.determinant();
  // det(G − T) = M11 M22 − M12 M21 is judged against its two products, whose difference it is:
  // its rounding is a few 1e-16 of them, and r's grows as det G shrinks (where the onset is
  // exact, e.g. a corner that keeps two in-plane stresses equal, r = 0 by construction).
  out.localised = -top.value <= kSingularAcousticRatio * f.products_bound();
  return out;
}

double mohr_coulomb_softening_modulus(double major, double minor, const MohrCoulombStrength& strength,
                                      const StrengthSlopes& slopes) {
  // κ̇ = √(2/3 ė^p:ė^p) = λ̇ √(2/3) |dev m|, m = diag(1 + sin ψ, 0, −(1 − sin ψ)): (2/3)√(3 + sin²ψ).
  const double strain_per_multiplier = (2.0 / 3.0) * std::sqrt(3.0 + strength.sin_psi * strength.sin_psi);
  return -strain_per_multiplier * yield_slope(major, minor, strength, slopes);
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
    out.corner = edge_corner(principal, true, strength, slopes);
  } else if (s[1] - s[2] <= 1e-9 * spread) {
    out.region = ReturnRegion::edge_extension;  // σ2 = σ3 (triaxial extension)
    out.corner = edge_corner(principal, false, strength, slopes);
  } else {
    out.region = ReturnRegion::plane;
    // f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2c cos φ, g the same with ψ:
    // ∂f/∂σ = (1 + sin φ) e1⊗e1 − (1 − sin φ) e3⊗e3 on σ's own principal axes.
    out.flow.yield_normal = principal.with_values(plane_gradient(0, 2, strength.sin_phi));
    out.flow.flow_direction = principal.with_values(plane_gradient(0, 2, strength.sin_psi));
    out.flow.hardening_modulus_Pa = mohr_coulomb_softening_modulus(s[0], s[2], strength, slopes);
  }
  return out;
}

}  // namespace ffp
