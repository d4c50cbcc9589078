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
  double determinant_ratio = 1.0;      ///< min over θ ∈ [0, π) of r(θ); −∞ where χ ≤ 0
  double band_normal_rad = 0.0;        ///< the minimising θ: band normal from the r axis, in [0, π)
  double critical_hardening_Pa = 0.0;  ///< H_crit over the in-plane normals
  bool localised = false;  ///< determinant_ratio ≤ kSingularAcousticRatio (χ > 0), H ≤ H_crit (χ ≤ 0)
};

/// The in-plane minimum of r(θ) (the maximum of t(θ), sampled every 1°, refined by golden section).
Localisation find_localisation(const ElasticConstants& elastic, const PlasticFlow& flow);

/// Where a Mohr–Coulomb stress sits and, on a face, its flow.
struct MohrCoulombFlow {
  ReturnRegion region = ReturnRegion::elastic;  ///< elastic, plane, an edge or the apex
  PlasticFlow flow;                             ///< set on `plane` only
};

/// H of a face (1,3) mechanism whose strength falls with κ at `slopes` (the header's formula):
/// `major` and `minor` are σ1 and σ3.
double mohr_coulomb_softening_modulus(double major, double minor, const MohrCoulombStrength& strength,
                                      const StrengthSlopes& slopes);

/// The perfectly plastic face (1,3) mechanism of a stress on the Mohr–Coulomb
/// surface: n_f = (1 + sin φ) e1⊗e1 − (1 − sin φ) e3⊗e3, m the same with ψ, on the
/// stress's principal directions (e1 major, e3 minor; the yield and flow functions
/// of models/mohr_coulomb_return.hpp). Inside the surface: `elastic`. On an edge
/// (two equal principal stresses) or at the apex: that region and no flow, because
/// the tangent there is not evaluated: at an edge the two faces' multipliers split
/// the flow in a ratio the stress alone does not give, and the face's own principal
/// axis is any direction of the repeated eigenspace, so picking one face would pick
/// a band arbitrarily; at the apex there is no flow direction at all.
/// `slopes` (a softening law's, zero by default) give the face's hardening modulus H.
MohrCoulombFlow mohr_coulomb_flow(const Voigt& stress, const MohrCoulombStrength& strength,
                                  const StrengthSlopes& slopes = {});

}  // namespace ffp
