#pragma once
/// Spectral decomposition of a symmetric stress, σ = Σ_k σ_k n_k ⊗ n_k with
/// σ_1 ≥ σ_2 ≥ σ_3, and the way back to Voigt storage with new principal
/// values on the same directions (what every principal-space return needs).
///
/// Fast path: when the 23 and 13 shears are exactly zero (the axisymmetric MPM,
/// where θθ is always principal) the in-plane pair comes from a closed-form
/// 2×2 (Mohr's circle: no trigonometry, no iteration). Otherwise Eigen's
/// closed-form 3×3 solver. Coincident principal values are harmless: any basis
/// of a repeated eigenspace rebuilds the same tensor as long as the new values
/// keep them equal, which every Mohr-Coulomb return (plane, edge, apex) does.
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "models/elastic.hpp"
#include "models/voigt.hpp"

namespace ffp {

/// Mohr's circle backwards: the planar tensor whose in-plane principal values are v[slot_major],
/// v[slot_minor] on the directions of a circle with half-difference (σ_rr − σ_zz)/2, shear σ_rz
/// and radius `radius` (cos 2θ, sin 2θ formed only here: an elastic point never needs them), and
/// whose θθ is v[slot_tt]. Shared by ElasticTrial and PrincipalStresses (the same bits).
inline void planar_with_values(const Eigen::Vector3d& v, int slot_tt, int slot_major, int slot_minor,
                               double half_difference, double shear, double radius, Voigt& out) {
  double cos_2theta = 1.0, sin_2theta = 0.0;
  if (radius > 0.0) {
    cos_2theta = half_difference / radius;
    sin_2theta = shear / radius;
  }
  const double centre = 0.5 * (v[slot_major] + v[slot_minor]);
  const double new_radius = 0.5 * (v[slot_major] - v[slot_minor]);
  out[0] = centre + new_radius * cos_2theta;
  out[1] = centre - new_radius * cos_2theta;
  out[2] = v[slot_tt];
  out[3] = new_radius * sin_2theta;
  out[4] = 0.0;
  out[5] = 0.0;
}

/// The elastic trial σ + λ tr(Δε) I + 2G Δε and, where θθ is principal (zero 23 and 13
/// shears: the axisymmetric MPM), its major and minor principal values σ_1, σ_3, in
/// scalars by the same operations in the same order as ElasticStiffness::stress_increment
/// and PrincipalStresses (so the same bits): the whole cost of a point that stays elastic,
/// without the principal-space object (measured: that object, built for every point of an
/// MPM step, took 60 % of the Mohr-Coulomb update's time).
struct ElasticTrial {
  double rr, zz, tt, rz, zt, rt;  ///< the trial in Voigt order
  bool planar = false;
  double major = 0.0, minor = 0.0;  ///< σ_1, σ_3 (planar only)

  ElasticTrial() = default;
  ElasticTrial(const Voigt& stress, const Voigt& strain_increment, const ElasticStiffness& d) {
    const Voigt& de = strain_increment;
    const double lambda_tr = d.lambda * (de[0] + de[1] + de[2]);
    rr = stress[0] + (d.two_shear * de[0] + lambda_tr);
    zz = stress[1] + (d.two_shear * de[1] + lambda_tr);
    tt = stress[2] + (d.two_shear * de[2] + lambda_tr);
    rz = stress[3] + d.two_shear * de[3];
    zt = stress[4] + d.two_shear * de[4];
    rt = stress[5] + d.two_shear * de[5];
    decompose();
  }
  /// A trial already formed (screen_elastic_trials): the same bits as forming it here.
  explicit ElasticTrial(const Voigt& trial)
      : rr(trial[0]), zz(trial[1]), tt(trial[2]), rz(trial[3]), zt(trial[4]), rt(trial[5]) {
    decompose();
  }
  void store(Voigt& out) const {
    out[0] = rr;
    out[1] = zz;
    out[2] = tt;
    out[3] = rz;
    out[4] = zt;
    out[5] = rt;
  }

  /// Planar only: σ_1 ≥ σ_2 ≥ σ_3, as PrincipalStresses::values().
  Eigen::Vector3d values() const {
    const double in_major = centre_ + radius_, in_minor = centre_ - radius_;
    if (tt >= in_major) return {tt, in_major, in_minor};
    if (tt >= in_minor) return {in_major, tt, in_minor};
    return {in_major, in_minor, tt};
  }
  /// Planar only: the tensor with principal values v (values()' order) on the trial's
  /// directions, as PrincipalStresses::with_values (Mohr's circle backwards).
  void store_with_values(const Eigen::Vector3d& v, Voigt& out) const {
    const double in_major = centre_ + radius_, in_minor = centre_ - radius_;
    const int slot_tt = tt >= in_major ? 0 : (tt >= in_minor ? 1 : 2);
    const int slot_major = slot_tt == 0 ? 1 : 0, slot_minor = slot_tt == 2 ? 1 : 2;
    planar_with_values(v, slot_tt, slot_major, slot_minor, half_difference_, rz, radius_, out);
  }

 private:
  void decompose() {
    planar = zt == 0.0 && rt == 0.0;
    if (planar) {
      centre_ = 0.5 * (rr + zz);
      half_difference_ = 0.5 * (rr - zz);
      radius_ = std::sqrt(half_difference_ * half_difference_ + rz * rz);
      major = std::max(centre_ + radius_, tt);  // PrincipalStresses' order: θθ above, between or below
      minor = std::min(centre_ - radius_, tt);
    }
  }

  double centre_ = 0.0, half_difference_ = 0.0, radius_ = 0.0;  ///< the trial's in-plane Mohr circle
};

class PrincipalStresses {
 public:
  explicit PrincipalStresses(const Voigt& stress) {
    if (stress[4] == 0.0 && stress[5] == 0.0) {
      decompose_in_plane(stress);
    } else {
      decompose_general(stress);
    }
  }

  /// σ_1 ≥ σ_2 ≥ σ_3 (tension positive: σ_3 is the major compression).
  const Eigen::Vector3d& values() const { return values_; }
  bool planar() const { return planar_; }

  /// The tensor with these principal values (same order) on the same directions.
  Voigt with_values(const Eigen::Vector3d& v) const {
    Voigt out;
    if (planar_) {
      planar_with_values(v, slot_33_, slot_major_in_plane_, slot_minor_in_plane_, half_difference_, shear_, radius_,
                         out);
      return out;
    }
    // σ_ij = Σ_k σ_k n_ik n_jk
    const Eigen::Matrix3d& n = vectors_;
    auto entry = [&](int i, int j) {
      return v[0] * n(i, 0) * n(j, 0) + v[1] * n(i, 1) * n(j, 1) + v[2] * n(i, 2) * n(j, 2);
    };
    out << entry(0, 0), entry(1, 1), entry(2, 2), entry(0, 1), entry(1, 2), entry(0, 2);
    return out;
  }

 private:
  void decompose_in_plane(const Voigt& s) {
    planar_ = true;
    const double centre = 0.5 * (s[0] + s[1]);
    const double half_difference = 0.5 * (s[0] - s[1]);
    const double radius = std::sqrt(half_difference * half_difference + s[3] * s[3]);
    half_difference_ = half_difference;
    shear_ = s[3];
    radius_ = radius;
    const double major = centre + radius;
    const double minor = centre - radius;
    const double out_of_plane = s[2];
    if (out_of_plane >= major) {
      values_ << out_of_plane, major, minor;
      slot_33_ = 0, slot_major_in_plane_ = 1, slot_minor_in_plane_ = 2;
    } else if (out_of_plane >= minor) {
      values_ << major, out_of_plane, minor;
      slot_major_in_plane_ = 0, slot_33_ = 1, slot_minor_in_plane_ = 2;
    } else {
      values_ << major, minor, out_of_plane;
      slot_major_in_plane_ = 0, slot_minor_in_plane_ = 1, slot_33_ = 2;
    }
  }

  void decompose_general(const Voigt& s) {
    planar_ = false;
    Eigen::Matrix3d a;
    a << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(a);
    // The closed form loses accuracy where two eigenvalues nearly coincide
    // (~1e-8 relative: exactly the states an edge return produces). A Jacobi
    // polish of Vᵀ A V, already nearly diagonal, restores full precision.
    Eigen::Matrix3d v = solver.eigenvectors();
    Eigen::Matrix3d b = v.transpose() * a * v;
    for (int sweep = 0; sweep < 4; ++sweep) {
      const double off = std::abs(b(0, 1)) + std::abs(b(0, 2)) + std::abs(b(1, 2));
      const double diagonal = std::abs(b(0, 0)) + std::abs(b(1, 1)) + std::abs(b(2, 2));
      if (!(off > 1e-18 * diagonal)) break;
      rotate(b, v, 0, 1);
      rotate(b, v, 0, 2);
      rotate(b, v, 1, 2);
    }
    // Descending order, columns following their values.
    int order[3] = {0, 1, 2};
    if (b(order[0], order[0]) < b(order[1], order[1])) std::swap(order[0], order[1]);
    if (b(order[1], order[1]) < b(order[2], order[2])) std::swap(order[1], order[2]);
    if (b(order[0], order[0]) < b(order[1], order[1])) std::swap(order[0], order[1]);
    for (int k = 0; k < 3; ++k) {
      values_[k] = b(order[k], order[k]);
      vectors_.col(k) = v.col(order[k]);
    }
  }

  /// One Jacobi rotation annihilating b(p, q) (Golub & Van Loan, sym.schur2); v accumulates it.
  static void rotate(Eigen::Matrix3d& b, Eigen::Matrix3d& v, int p, int q) {
    if (b(p, q) == 0.0) return;
    const double tau = (b(q, q) - b(p, p)) / (2.0 * b(p, q));
    const double t =
        std::abs(tau) > 1e150 ? 0.5 / tau : (tau >= 0.0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
    const double c = 1.0 / std::sqrt(1.0 + t * t);
    const double s = t * c;
    Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
    j(p, p) = c;
    j(p, q) = s;
    j(q, p) = -s;
    j(q, q) = c;
    b = j.transpose() * b * j;
    b(p, q) = b(q, p) = 0.0;
    v = v * j;
  }

  Eigen::Vector3d values_;
  bool planar_ = true;
  // The in-plane Mohr circle of the trial: 2θ from (σ_rr − σ_zz)/2 and σ_rz over its radius.
  double half_difference_ = 0.0;
  double shear_ = 0.0;
  double radius_ = 0.0;
  int slot_33_ = 2;
  int slot_major_in_plane_ = 0;
  int slot_minor_in_plane_ = 1;
  Eigen::Matrix3d vectors_;
};

}  // namespace ffp
