#pragma once
/// Axial shear of a thick hollow Cosserat-elastic cylinder (docs/theory.md#micropolar-cylinder):
/// u_z(r) only, ω(r) about e_θ, u_z(r_o) = 0, ω(r_i) = ω(r_o) = 0, the inner face loaded by an
/// axial traction τ. Two independent solutions of the same boundary-value problem:
///
/// - the closed form: with C = −τ r_i (r T = C, T = (G + G_c) u' + 2 G_c ω the axial traction on
///   a face of normal e_r), k² = 2 G_c / (ℓ² (G + G_c)),
///     ω(r) = −C/(2 G r) + a I_1(k r) + b K_1(k r),   u'(r) = (C/r − 2 G_c ω)/(G + G_c);
/// - a finite-difference solve of the two equilibrium equations as they come from the energy
///   (no first integral used): block-tridiagonal, second order in the spacing.
#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace ffp::mpm::testing {

struct CosseratCylinder {
  double shear_modulus_Pa, cosserat_shear_modulus_Pa, length_m;
  double inner_m, outer_m, traction_Pa;  ///< r_i, r_o, τ (upward on the inner face)

  double constant() const { return -traction_Pa * inner_m; }  ///< C = r T
  double k() const {
    const double G = shear_modulus_Pa, Gc = cosserat_shear_modulus_Pa;
    return std::sqrt(2.0 * Gc / (length_m * length_m * (G + Gc)));
  }
};

/// The closed form of CosseratCylinder (G_c > 0, ℓ > 0).
class CosseratCylinderSolution {
 public:
  explicit CosseratCylinderSolution(const CosseratCylinder& c) : c_(c), k_(c.k()) {
    // ω(r_i) = ω(r_o) = 0: a I_1 + b K_1 = C/(2 G r) at both faces.
    const double G = c.shear_modulus_Pa, C = c.constant();
    const double i1 = std::cyl_bessel_i(1.0, k_ * c.inner_m), k1 = std::cyl_bessel_k(1.0, k_ * c.inner_m);
    const double o1 = std::cyl_bessel_i(1.0, k_ * c.outer_m), p1 = std::cyl_bessel_k(1.0, k_ * c.outer_m);
    const double rhs_i = C / (2.0 * G * c.inner_m), rhs_o = C / (2.0 * G * c.outer_m);
    const double det = i1 * p1 - k1 * o1;
    a_ = (rhs_i * p1 - k1 * rhs_o) / det;
    b_ = (i1 * rhs_o - o1 * rhs_i) / det;
  }

  double rotation(double r) const {
    return -c_.constant() / (2.0 * c_.shear_modulus_Pa * r) + a_ * std::cyl_bessel_i(1.0, k_ * r) +
           b_ * std::cyl_bessel_k(1.0, k_ * r);
  }
  /// u_z(r) = −∫_r^{r_o} u'(s) ds.
  double displacement(double r) const {
    const double G = c_.shear_modulus_Pa, Gc = c_.cosserat_shear_modulus_Pa, C = c_.constant(), ro = c_.outer_m;
    const double log_ratio = std::log(ro / r);
    const double rotation_integral = -C / (2.0 * G) * log_ratio +
                                     a_ / k_ * (std::cyl_bessel_i(0.0, k_ * ro) - std::cyl_bessel_i(0.0, k_ * r)) -
                                     b_ / k_ * (std::cyl_bessel_k(0.0, k_ * ro) - std::cyl_bessel_k(0.0, k_ * r));
    return -(C * log_ratio - 2.0 * Gc * rotation_integral) / (G + Gc);
  }

 private:
  CosseratCylinder c_;
  double k_, a_ = 0.0, b_ = 0.0;
};

/// The classical answer (G_c = 0 or ℓ = 0): u_z(r) = −(C/G) ln(r_o/r).
inline double classical_displacement(const CosseratCylinder& c, double r) {
  return -c.constant() / c.shear_modulus_Pa * std::log(c.outer_m / r);
}

/// u_k, ω_k at r_k = r_i + k (r_o − r_i)/n by finite differences of
///   (r T)' = 0,  T = (G + G_c) u' + 2 G_c ω     (r_i T(r_i) = C, u(r_o) = 0),
///   G ℓ² [(r ω')'/r − ω/r²] = G_c (u' + 2 ω)      (ω(r_i) = ω(r_o) = 0),
/// the first as fluxes through the cell faces (a half cell at r_i), the second centred.
struct CosseratProfile {
  std::vector<double> r, u, omega;
};
inline CosseratProfile solve_cosserat_cylinder(const CosseratCylinder& c, int n) {
  using Block = Eigen::Matrix2d;
  using Pair = Eigen::Vector2d;
  const double G = c.shear_modulus_Pa, Gc = c.cosserat_shear_modulus_Pa, L2 = c.length_m * c.length_m;
  const double dr = (c.outer_m - c.inner_m) / n;
  const auto radius = [&](double k) { return c.inner_m + k * dr; };
  // Row k: lower[k] x_{k−1} + diag[k] x_k + upper[k] x_{k+1} = rhs[k], x_k = (u_k, ω_k).
  std::vector<Block> lower(n + 1, Block::Zero()), diag(n + 1, Block::Zero()), upper(n + 1, Block::Zero());
  std::vector<Pair> rhs(n + 1, Pair::Zero());
  // r_{k+½} T_{k+½} as coefficients of x_k and x_{k+1}.
  const auto flux = [&](double k, Block& own, Block& next, double sign) {
    const double rf = radius(k + 0.5);
    own(0, 0) += sign * rf * (-(G + Gc) / dr);
    own(0, 1) += sign * rf * Gc;
    next(0, 0) += sign * rf * ((G + Gc) / dr);
    next(0, 1) += sign * rf * Gc;
  };
  for (int k = 0; k <= n; ++k) {
    const double r = radius(k);
    if (k == n) {
      diag[k](0, 0) = 1.0;  // u(r_o) = 0
    } else {
      flux(k, diag[k], upper[k], 1.0);  // + r_{k+½} T_{k+½}
      if (k == 0) {
        rhs[k](0) = c.constant();  // r_½ T_½ = C (the half cell at r_i)
      } else {
        flux(k - 1, lower[k], diag[k], -1.0);  // − r_{k−½} T_{k−½}
      }
    }
    if (k == 0 || k == n) {
      diag[k](1, 1) = 1.0;  // ω = 0 on both faces
      continue;
    }
    const double rp = radius(k + 0.5), rm = radius(k - 0.5), s = G * L2 / (r * dr * dr);
    lower[k](1, 1) = s * rm;
    upper[k](1, 1) = s * rp;
    diag[k](1, 1) = -s * (rp + rm) - G * L2 / (r * r) - 2.0 * Gc;
    lower[k](1, 0) = Gc / (2.0 * dr);
    upper[k](1, 0) = -Gc / (2.0 * dr);
  }
  // Block Thomas: forward elimination, back substitution.
  for (int k = 1; k <= n; ++k) {
    const Block factor = lower[k] * diag[k - 1].inverse();
    diag[k] -= factor * upper[k - 1];
    rhs[k] -= factor * rhs[k - 1];
  }
  std::vector<Pair> x(n + 1);
  x[n] = diag[n].inverse() * rhs[n];
  for (int k = n - 1; k >= 0; --k) x[k] = diag[k].inverse() * (rhs[k] - upper[k] * x[k + 1]);
  CosseratProfile out;
  for (int k = 0; k <= n; ++k) {
    out.r.push_back(radius(k));
    out.u.push_back(x[k](0));
    out.omega.push_back(x[k](1));
  }
  return out;
}

}  // namespace ffp::mpm::testing
