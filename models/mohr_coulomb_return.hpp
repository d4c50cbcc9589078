#pragma once
/// The exact Mohr-Coulomb return in principal stress space, shared by MC and
/// SSMC. Tension positive, σ_1 ≥ σ_2 ≥ σ_3.
///
/// Yield  f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2 c cos φ
/// Flow   g = (σ1 − σ3) + (σ1 + σ3) sin ψ         (non-associated, ψ ≤ φ)
/// For a linear yield surface and constant elastic stiffness the backward-Euler
/// return is closed form on each part of the surface:
///   plane  σ = σ_tr − Δλ D g_a,                Δλ from f_a = 0
///   edge   σ = σ_tr − Δλ_a D g_a − Δλ_b D g_b,  Δλ_a, Δλ_b from f_a = f_b = 0
///          (compression edge σ1 = σ2, extension edge σ2 = σ3)
///   apex   σ = c cot φ (1, 1, 1)
/// The first one that is admissible (ordering kept, Δλ ≥ 0, not past the apex)
/// is the answer. The apex needs no flow direction, so ψ = 0 is not a special
/// case; φ = 0 (Tresca) has no apex and never reaches it.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "models/elastic.hpp"
#include "models/return_region.hpp"

namespace ffp {

/// Elasticity in principal axes: Δσ_i = a_ii Δε_i + a_ij Δε_j.
struct PrincipalStiffness {
  double diagonal = 0.0;      ///< K + 4G/3
  double off_diagonal = 0.0;  ///< K − 2G/3

  static PrincipalStiffness of(const ElasticConstants& e) {
    const double k = e.bulk_modulus();
    const double g = e.shear_modulus();
    return {k + 4.0 * g / 3.0, k - 2.0 * g / 3.0};
  }
};

/// The strength a return works with (angles through their sines).
struct MohrCoulombStrength {
  double sin_phi = 0.0;
  double cos_phi = 1.0;
  double sin_psi = 0.0;
  double cohesion_Pa = 0.0;

  static MohrCoulombStrength of(double phi_rad, double psi_rad, double cohesion_Pa) {
    return {std::sin(phi_rad), std::cos(phi_rad), std::sin(psi_rad), cohesion_Pa};
  }
  double yield(double major, double minor) const {
    return (major - minor) + (major + minor) * sin_phi - 2.0 * cohesion_Pa * cos_phi;
  }
  double yield(const Eigen::Vector3d& s) const { return yield(s[0], s[2]); }
};

/// What a return needs of a strength and a stiffness besides the trial: the flow
/// directions D g of the planes that meet the σ1 ≥ σ2 ≥ σ3 sector and their
/// stiffnesses against plastic flow. Once per law where the strength is fixed
/// (Mohr–Coulomb), per point where it changes (strain softening); the same values
/// either way.
struct ReturnDirections {
  // D g_a of the plane (1,3): along its major, idle and minor axes; g_b on (2,3)
  // (compression edge) and g_c on (1,2) (extension edge) take the same terms in
  // other places.
  double major_term = 0.0, middle_term = 0.0, minor_term = 0.0;
  double plane_stiffness = 0.0;  ///< n_a · D g_a (> 0 for G, K > 0)

  static ReturnDirections of(const MohrCoulombStrength& strength, const PrincipalStiffness& d) {
    const double sf = strength.sin_phi, sp = strength.sin_psi, a = d.diagonal, b = d.off_diagonal;
    ReturnDirections r;
    r.major_term = a * (1.0 + sp) - b * (1.0 - sp);
    r.middle_term = 2.0 * b * sp;
    r.minor_term = b * (1.0 + sp) - a * (1.0 - sp);
    r.plane_stiffness = (1.0 + sf) * r.major_term - (1.0 - sf) * r.minor_term;
    return r;
  }
};

/// Returns `stress` (principal, descending, trial on entry) onto the surface;
/// `directions` are ReturnDirections::of(strength, the stiffness).
inline ReturnRegion return_to_mohr_coulomb(Eigen::Vector3d& stress, const MohrCoulombStrength& strength,
                                           const ReturnDirections& directions) {
  const double f_trial = strength.yield(stress);
  if (!(f_trial > 0.0)) return ReturnRegion::elastic;

  const double sf = strength.sin_phi;
  // Rounding in the comparisons below is judged against the trial's size.
  const double scale = std::max({std::abs(stress[0]), std::abs(stress[2]), strength.cohesion_Pa});
  const double tolerance = 1e-13 * scale;

  const double major_term = directions.major_term, middle_term = directions.middle_term,
               minor_term = directions.minor_term, plane_stiffness = directions.plane_stiffness;
  const Eigen::Vector3d dg_a(major_term, middle_term, minor_term);

  const double multiplier = f_trial / plane_stiffness;
  const Eigen::Vector3d on_plane = stress - multiplier * dg_a;
  const bool upper_order = on_plane[0] - on_plane[1] >= -tolerance;
  const bool lower_order = on_plane[1] - on_plane[2] >= -tolerance;
  if (upper_order && lower_order) {
    stress = on_plane;
    return ReturnRegion::plane;
  }

  // Two active planes. By the symmetry of each edge (swap 1↔2 or 2↔3) the 2×2
  // system is [[A, B], [B, A]], solved through the sum and difference of Δλ.
  auto edge = [&](bool compression, Eigen::Vector3d& out) {
    Eigen::Vector3d dg_b;
    double f_b;
    if (compression) {
      dg_b << middle_term, major_term, minor_term;
      f_b = strength.yield(stress[1], stress[2]);
    } else {
      dg_b << major_term, minor_term, middle_term;
      f_b = strength.yield(stress[0], stress[1]);
    }
    const double coupling = (1.0 + sf) * dg_b[0] - (1.0 - sf) * dg_b[2];  // n_a · D g_b
    const double sum = (f_trial + f_b) / (plane_stiffness + coupling);
    const double difference = (f_trial - f_b) / (plane_stiffness - coupling);
    const double lambda_a = 0.5 * (sum + difference);
    const double lambda_b = 0.5 * (sum - difference);
    out = stress - lambda_a * dg_a - lambda_b * dg_b;
    // Make the two equal stresses exactly equal (they differ only by rounding).
    if (compression) {
      out[0] = out[1] = 0.5 * (out[0] + out[1]);
    } else {
      out[1] = out[2] = 0.5 * (out[1] + out[2]);
    }
    const double lambda_tolerance = tolerance / plane_stiffness;
    return lambda_a >= -lambda_tolerance && lambda_b >= -lambda_tolerance &&
           out[0] - out[2] >= -tolerance;  // beyond the apex the edge line leaves the surface
  };

  // The edge the plane return overshot first; the other one only if that fails.
  const bool compression_first = !upper_order;
  Eigen::Vector3d first_edge, second_edge;
  if (edge(compression_first, first_edge)) {
    stress = first_edge;
    return compression_first ? ReturnRegion::edge_compression : ReturnRegion::edge_extension;
  }
  if (edge(!compression_first, second_edge)) {
    stress = second_edge;
    return compression_first ? ReturnRegion::edge_extension : ReturnRegion::edge_compression;
  }
  if (sf > 0.0) {
    stress.setConstant(strength.cohesion_Pa * strength.cos_phi / sf);  // c cot φ
    return ReturnRegion::apex;
  }
  // Tresca (φ = 0) has no apex and its edges cover the whole corner region,
  // so this is reached only through rounding at a corner: keep the closer edge.
  const bool first = std::abs(strength.yield(first_edge)) <= std::abs(strength.yield(second_edge));
  stress = first ? first_edge : second_edge;
  return first == compression_first ? ReturnRegion::edge_compression : ReturnRegion::edge_extension;
}

/// The same, the directions formed here (a strength that changes from point to point).
inline ReturnRegion return_to_mohr_coulomb(Eigen::Vector3d& stress, const MohrCoulombStrength& strength,
                                           const PrincipalStiffness& d) {
  if (!(strength.yield(stress) > 0.0)) return ReturnRegion::elastic;  // no directions needed
  return return_to_mohr_coulomb(stress, strength, ReturnDirections::of(strength, d));
}

}  // namespace ffp
