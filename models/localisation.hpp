#pragma once
/// Loss of ellipticity of an elastoplastic tangent: the onset of a shear band
/// (Rudnicki & Rice 1975, J. Mech. Phys. Solids 23, 371–394).
///
/// Continuum tangent of one active mechanism, yield normal n_f = ∂f/∂σ, flow
/// direction m = ∂g/∂σ, hardening modulus H (0: perfectly plastic, < 0: softening):
///   D^ep = D − (D:m) ⊗ (n_f:D) / (n_f:D:m + H)
/// A band with unit normal n can form when the acoustic tensor
///   A_jk(n) = n_i D^ep_ijkl n_l = A^e_jk − (a·n)_j (b·n)_k / χ,
///   A^e = (λ + G) n⊗n + G I,  a = D:m,  b = D:n_f,  χ = n_f:D:m + H
/// is singular, det A(n) ≤ 0. The rank-one form above is D^ep contracted term by
/// term (D isotropic, so a and b are symmetric); its 81 components are never stored.
///
/// The diagnostic reports r(θ) = det A(n) / det A^e(n) for n = (cos θ, sin θ, 0) in
/// the (r, z, θθ) axes, i.e. in-plane directions of the axisymmetric r–z plane.
/// det A^e = G²(λ + 2G) for every n, so r is scale-free (1 when elastic) and, by
/// the matrix determinant lemma, r = 1 − (b·n)·(A^e)⁻¹(a·n)/χ with
/// (A^e)⁻¹ = (I − n⊗n / (2(1 − ν)))/G: a quartic form in n, hence a trigonometric
/// polynomial in θ with harmonics 0, 2θ and 4θ only. Its derivative has at most
/// four zeros in [0, π): r has at most two local minima there. A 1° sampling
/// therefore brackets the global minimum's basin unless two minima lie within 2°
/// of each other, in which case their values differ by at most |r''|(1°)²/2
/// (|r''| ≤ 16 times the harmonics' amplitude, < 5e-3 of it). In the bracket, where r
/// is unimodal, Newton's steps on r' = 0 (kept inside by bisection; golden section where
/// the ends do not bracket a minimum) converge to it. The five harmonics are formed once
/// per point, so the 180 samples cost a few multiplications each.
///
/// r is affine in the H-free term t(n) = G (b·n)·(A^e)⁻¹(a·n): r = 1 − t/(Gχ). The search
/// maximises t, which gives Rudnicki & Rice's critical hardening modulus
///   H_crit = max_n t(n)/G − n_f:D:m,
/// and the band is possible (r_min ≤ 0) exactly when H ≤ H_crit. It also covers χ ≤ 0
/// (a law softening faster than elastic unloading, H ≤ −n_f:D:m), where the tangent has no
/// loading branch and r no meaning: there H ≤ H_crit decides, as it does on the way down.
///
/// A softening Mohr–Coulomb face (φ', c' falling with κ = ε_d^p, ψ with it) has, from the
/// consistency ḟ = n_f:σ̇ + (∂f/∂κ) κ̇ = 0 with κ̇ = λ̇ √(2/3) |dev m|:
///   H = −√(2/3) |dev m| ∂f/∂κ,  ∂f/∂κ = [(σ1 + σ3) cos φ' + 2c' sin φ'] dφ'/dκ − 2 cos φ' dc'/dκ,
///   √(2/3) |dev m| = (2/3) √(3 + sin²ψ)
/// (f of models/mohr_coulomb_return.hpp; κ as the SSMC accumulates it). Under compression
/// (σ1 + σ3 < 0) a falling φ' gives H < 0.
///
/// An edge of the Mohr–Coulomb surface (two equal principal stresses) is a corner of two
/// planes a, b (Koiter 1953, Q. Appl. Math. 11, 350). With both active the continuum tangent is
///   D^ep = D − Σ_ab (D:m_a) (G⁻¹)_ab (n_b:D),  G_ab = n_a:D:m_b + H_ab,
/// from ḟ_a = n_a:σ̇ − Σ_b H_ab λ̇_b = 0, and A(n) = A^e − Σ_ab (a_a·n) (G⁻¹)_ab (b_b·n) is A^e
/// less a rank-two term: by the matrix determinant lemma
///   r(n) = det A / det A^e = det(G − T(n)) / det G,  T_ab(n) = (b_a·n)·(A^e)⁻¹(a_b·n),
/// each T_ab the face's quartic form, so r is a trigonometric polynomial with harmonics up
/// to 8θ: r' has at most eight zeros in [0, π), r at most four local minima, and the 1°
/// sampling brackets the global minimum's basin as above (two minima within 2° differ by at
/// most |r''|(1°)²/2, |r''| ≤ 120 times the harmonics' amplitude, < 2e-2 of it). The search
/// then takes the same Newton steps on r' = 0 from the products of the T_ab's harmonics.
/// The band needs G to be a P-matrix (G_aa > 0, det G > 0): only then does every rate have
/// one solution of the corner's multipliers (the linear complementarity problem of the
/// corner; Cottle, Pang & Stone 1992, Thm 3.3.7), the analogue of χ > 0. Where it is not,
/// the planes together soften faster than elastic unloading and the point counts as
/// localised, as a face with χ ≤ 0 does: on the way down, before det G reaches 0, r_min is
/// already at or below 0 on every Mohr–Coulomb edge with 0 ≤ ψ ≤ φ' (tested). det(G − T) is
/// judged against its two products (their difference is what rounds), not r against 1: r's
/// rounding grows as det G shrinks.
///
/// What the corner tangent is, and why it is the one tested. The rate-independent response
/// at a corner is piecewise linear: a rate whose multipliers λ̇ = G⁻¹(n_b:D:ε̇) are both
/// positive keeps the stress on the edge (this tangent); one that makes a multiplier
/// negative moves the stress onto the other plane's face (that face's tangent). So D^ep is
/// not one tensor at a corner, and a band could pair different branches inside and outside.
/// The diagnostic tests the branch with both planes active: the one the return's edge
/// region produces (a stress sits on an edge after a plastic step only because both Δλ were
/// positive), Rice's (1976) "continued loading" across the band. With associated flow it
/// is the softest branch (ε:D^ep:ε = ε:D:ε − qᵀG⁻¹q, q_a = n_a:D:ε, and qᵀG⁻¹q ≥ q_a²/G_aa
/// for a symmetric positive definite G), so its acoustic tensor is the first to lose
/// ellipticity; with ψ < φ' the branches are not ordered (at the paper's sand's
/// compression edge the corner's r_min lies below the plane-strain face's, at its extension
/// edge above), and the faces' branches are not tested at an edge.
///
/// The corner's planes are those of the return (models/mohr_coulomb_return.hpp): the
/// compression edge σ1 = σ2 is (1,3) and (2,3), the extension edge σ2 = σ3 is (1,3) and
/// (1,2), on the stress's principal axes. Two equal principal values leave their axes free
/// within their plane. In the axisymmetric model θθ is always principal, so where θθ is one
/// of the pair the axes are fixed (θθ and the in-plane one); where the r–z pair is equal,
/// a turn of the axes about θθ turns D^ep, hence r(θ), by the same angle: the minimum is the
/// same and only its θ follows the axes (those of the stress's decomposition, r and z).
/// Such a corner keeps the two in-plane stresses equal, so it has no stiffness against
/// their difference: r = 0 exactly at 45° to its axes, whatever φ', ψ (the onset, counted
/// as localised, as the associated plane-strain face is). With associated flow every edge
/// sits at the onset: D^ep on the principal strains is u⊗u/(u·D⁻¹u), u the edge's direction
/// in principal stress space, and 2G on the shears, so r(α) = (u_i cos²α − u_j sin²α)² /
/// ((u·D⁻¹u)(λ + 2G)), α from the in-plane axis i: zero at Coulomb's angle where θθ is one
/// of the pair (tested).
///
/// A softening corner: κ̇ = √(2/3) |dev(λ̇_a m_a + λ̇_b m_b)| is not linear in the
/// multipliers; it depends on how the flow splits between the planes, which the stress does
/// not give. The tangent takes it at the even split λ̇_a = λ̇_b, the flow that keeps the
/// edge's symmetry (triaxial compression or extension about the distinct axis). κ̇ is
/// homogeneous in λ̇, so there κ̇ = k (λ̇_a + λ̇_b) exactly, k = √(2/3) |dev(m_a + m_b)|/2 =
/// 1 − sin ψ/3 (compression), 1 + sin ψ/3 (extension); and ∂f_a/∂κ is the same for both
/// planes (they share the major and minor stresses' sum), so H_ab = −k ∂f/∂κ for every a, b.
/// Another split gives a κ̇ up to √(4/3)× larger (one plane alone: (2/3)√(3 + sin²ψ) against
/// k, at ψ = 0): the tangent is exact for the even split and first-order for the others.
#include <array>

#include <Eigen/Core>

#include "models/elastic.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/mohr_coulomb_return.hpp"
#include "models/return_region.hpp"
#include "models/voigt.hpp"

namespace ffp {

/// One active plastic mechanism, Voigt storage with tensor shears (models/voigt.hpp).
struct PlasticFlow {
  Voigt yield_normal = Voigt::Zero();    ///< n_f = ∂f/∂σ
  Voigt flow_direction = Voigt::Zero();  ///< m = ∂g/∂σ
  double hardening_modulus_Pa = 0.0;     ///< H in ḟ = n_f:σ̇ − H λ̇ = 0
};

/// det A ≤ this (relative to det A^e) counts as singular: r is O(1) and is found to
/// rounding (a few 1e-16), so the onset itself (r = 0 exactly, e.g. associated
/// perfect plasticity in plane strain) is counted as localised, as det ≤ 0 says.
inline constexpr double kSingularAcousticRatio = 1e-12;

/// A(n) of the elastic law (no flow) or of D^ep. Needs χ = n_f:D:m + H ≠ 0.
Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticFlow* flow,
                                const Eigen::Vector3d& normal);

/// r(θ) = det A(n) / det A^e for n = (cos θ, sin θ, 0); flow null: elastic (r = 1). Needs χ ≠ 0.
double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticFlow* flow, double theta_rad);

struct Localisation {
  double determinant_ratio = 1.0;      ///< min over θ ∈ [0, π) of r(θ); −∞ where χ ≤ 0 (G no P-matrix)
  double band_normal_rad = 0.0;        ///< the minimising θ: band normal from the r axis, in [0, π)
  double critical_hardening_Pa = 0.0;  ///< H_crit over the in-plane normals (a face; NaN at a corner)
  /// A face: determinant_ratio ≤ kSingularAcousticRatio (χ > 0), H ≤ H_crit (χ ≤ 0). A corner:
  /// det(G − T) ≤ kSingularAcousticRatio times its products (G a P-matrix), else true.
  bool localised = false;
};

/// The in-plane minimum of r(θ) (the maximum of t(θ), sampled every 1°, refined in the bracket).
Localisation find_localisation(const ElasticConstants& elastic, const PlasticFlow& flow);

/// Two active mechanisms at a corner (an edge of the Mohr–Coulomb surface): the header's
/// Koiter tangent. Voigt storage with tensor shears.
struct PlasticCorner {
  std::array<Voigt, 2> yield_normals = {Voigt::Zero(), Voigt::Zero()};    ///< n_a = ∂f_a/∂σ
  std::array<Voigt, 2> flow_directions = {Voigt::Zero(), Voigt::Zero()};  ///< m_a = ∂g_a/∂σ
  Eigen::Matrix2d hardening_Pa = Eigen::Matrix2d::Zero();  ///< H_ab in ḟ_a = n_a:σ̇ − Σ_b H_ab λ̇_b = 0
};

/// G_ab = n_a:D:m_b + H_ab, the corner's stiffness against its multipliers.
Eigen::Matrix2d corner_stiffness(const ElasticConstants& elastic, const PlasticCorner& corner);

/// A(n) of the corner's D^ep. Needs det G ≠ 0.
Eigen::Matrix3d acoustic_tensor(const ElasticConstants& elastic, const PlasticCorner& corner,
                                const Eigen::Vector3d& normal);

/// r(θ) = det A(n) / det A^e = det(G − T(n)) / det G for n = (cos θ, sin θ, 0). Needs det G ≠ 0.
double acoustic_determinant_ratio(const ElasticConstants& elastic, const PlasticCorner& corner, double theta_rad);

/// The in-plane minimum of the corner's r(θ). critical_hardening_Pa is NaN: a corner's
/// moduli are a 2×2 matrix, with no one critical value. Where G is not a P-matrix:
/// localised, determinant_ratio −∞ (the header says why).
Localisation find_localisation(const ElasticConstants& elastic, const PlasticCorner& corner);

/// Where a Mohr–Coulomb stress sits and its flow: one face's, or an edge's two planes.
struct MohrCoulombFlow {
  ReturnRegion region = ReturnRegion::elastic;  ///< elastic, plane, an edge or the apex
  PlasticFlow flow;                             ///< set on `plane` only
  PlasticCorner corner;                         ///< set on an edge only
};

/// H of a face (1,3) mechanism whose strength falls with κ at `slopes` (the header's formula):
/// `major` and `minor` are σ1 and σ3.
double mohr_coulomb_softening_modulus(double major, double minor, const MohrCoulombStrength& strength,
                                      const StrengthSlopes& slopes);

/// The perfectly plastic face (1,3) mechanism of a stress on the Mohr–Coulomb
/// surface: n_f = (1 + sin φ) e1⊗e1 − (1 − sin φ) e3⊗e3, m the same with ψ, on the
/// stress's principal directions (e1 major, e3 minor; the yield and flow functions
/// of models/mohr_coulomb_return.hpp). Inside the surface: `elastic`. On an edge (two
/// equal principal stresses): that region and the return's two planes there, with the
/// softening moduli H_ab of the even split (the header's corner). At the apex: that region
/// and no flow: the stress is fixed there (c cot φ on every axis), the yield function has
/// no gradient and the tangent no definition, so the apex is not evaluated.
/// `slopes` (a softening law's, zero by default) give the hardening moduli.
MohrCoulombFlow mohr_coulomb_flow(const Voigt& stress, const MohrCoulombStrength& strength,
                                  const StrengthSlopes& slopes = {});

}  // namespace ffp
