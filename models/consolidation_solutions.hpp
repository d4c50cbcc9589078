#pragma once
/// Exact solutions of the saturated (two-phase) problems the MPM is verified against, in one
/// place for the tests and the report: Terzaghi's 1D consolidation, radial consolidation of a
/// cylinder drained at its rim, and the two compression waves of a saturated column
/// (Verruijt 2010, An Introduction to Soil Dynamics, ch. 6). Pure math; SI units, pore
/// pressure compression positive, depth measured down from the drained top.
#include <vector>

namespace ffp {

/// The gravity with which a hydraulic conductivity k (m/s) is defined, k = κ ρ_w g/μ
/// (κ the intrinsic permeability, μ the viscosity): a lab's, whatever the model's
/// gravity. The drag n ρ_w g/k then stands for n μ/κ.
inline constexpr double kConductivityGravity_m_s2 = 9.81;

/// Terzaghi (1923): a layer of height H drained at its top and impermeable at its base, its
/// excess p_0 at t = 0. With depth ζ, T = c_v t/H², M = π(2m + 1)/2,
///   p(ζ, t) = Σ (2 p_0/M) sin(Mζ/H) e^{−M²T},
/// and the downward displacement of the point at depth ζ (the compression of what lies below
/// it, Δσ' = p_0 − p over E_c):
///   w(ζ, t) = (p_0/E_c) [(H − ζ) − Σ (2H/M²) cos(Mζ/H) e^{−M²T}].
struct Terzaghi {
  double initial_pressure_Pa, height_m, consolidation_coefficient_m2_s, constrained_modulus_Pa;
  double pressure(double depth_m, double t_s) const;
  double displacement(double depth_m, double t_s) const;
  /// The top's settlement relative to its final value: U(T) = 1 − Σ (2/M²) e^{−M²T}.
  double degree_of_consolidation(double t_s) const;
};

/// Terzaghi's coefficient of consolidation with a compressible fluid,
/// c_v = k/(γ_w (1/E_c + n/K_w)), γ_w = ρ_w g with the g of the conductivity's definition.
double consolidation_coefficient(double permeability_m_s, double fluid_density_kg_m3, double constrained_modulus_Pa,
                                 double porosity, double fluid_bulk_modulus_Pa, double conductivity_gravity_m_s2);

/// The share of a 1D load the pore fluid takes undrained: (K_w/n)/(E_c + K_w/n)
/// (Verruijt 2010; Anura3D Verification Manual §1.2).
double undrained_share(double constrained_modulus_Pa, double fluid_bulk_modulus_Pa, double porosity);

/// The first zeros of J_0, by Newton from McMahon's (m − 1/4)π (J_0' = −J_1).
std::vector<double> bessel_j0_zeros(int count);

/// ∂p/∂t = c (∂²p/∂r² + (1/r) ∂p/∂r) in 0 ≤ r ≤ R, p(R) = 0, p(r, 0) = p_0 (Crank 1975, ch. 5,
/// the long cylinder with its surface held at zero):
///   p = 2 p_0 Σ J_0(α_m r/R)/(α_m J_1(α_m)) e^{−α_m² c t/R²}.
struct RadialDiffusion {
  double initial_pressure_Pa, radius_m, diffusivity_m2_s;
  std::vector<double> alpha = bessel_j0_zeros(300);
  double pressure(double r_m, double t_s) const;
  /// Its mean over r0 ≤ r ≤ r1 weighted by r (a cell column's particles): Gauss–Legendre, 5 points.
  double cell_mean(double r0_m, double r1_m, double t_s) const;
};

/// One-dimensional Biot waves (no added mass, incompressible grains) in the velocity–velocity
/// form the MPM solves (docs/theory.md#saturated): with u_s, u_w the phases' displacements,
/// K = K_w/n, ρ_d = (1 − n) ρ_s, β = n² ρ_w g/k,
///   ρ_d ü_s   = E_c u_s'' + (1 − n) K [(1 − n) u_s'' + n u_w''] + β (u̇_w − u̇_s),
///   n ρ_w ü_w = n K [(1 − n) u_s'' + n u_w''] − β (u̇_w − u̇_s),
/// i.e. M ü + C u̇ = K u'' with M = diag(ρ_d, n ρ_w), K symmetric, C = β [[1, −1], [−1, 1]].
/// Without drag its two waves travel at c² the eigenvalues of M⁻¹K; a front (a jump) on
/// mode φ travels at that speed and its jump decays as e^{−γt}, γ = φᵀCφ/(2 φᵀMφ) (the
/// transport equation of a discontinuity of a damped hyperbolic system). These hold for any
/// parameters.
///
/// When (E_c + (1 − n) K)/ρ_d = K/ρ_w the in-phase motion φ_1 = (1, 1) is itself a mode
/// (Verruijt's uncoupled case), C φ_1 = 0, and M-orthogonality makes the other φ_2 =
/// (1, −ρ_d/(n ρ_w)): the system splits exactly into an undamped wave at
/// c_1 = √((E_c + K)/ρ_sat) = √(K/ρ_w) and a telegraph equation q̈ + 2γ q̇ = c_2² q'' with
/// c_2 = √(n E_c/ρ_d) (Verruijt's √(n E_c/(n E_c + (1 − n) K_w)) √(K_w/ρ_w) there) and
/// c_2²/(2γ) = c_v. Under a load P stepped onto the drained top at t = 0 (σ' = −P, p = 0
/// there; both fields at rest), each mode's strain takes its share of the top's and
///   p(x, t)  = P_1 H(t − x/c_1) + P_2 F(x/c_2, t),
///   σ'(x, t) = S_1 H(t − x/c_1) + S_2 F(x/c_2, t),
/// with F the telegraph equation's response to a unit step at x = 0 (Laplace pair of
/// e^{−a√(s² + 2γs)}/s: Abramowitz & Stegun 1964, §29.3, shifted by s → s + γ),
///   F(a, t) = H(t − a) [e^{−γa} + γa ∫_a^t e^{−γτ} I_1(γ√(τ² − a²))/√(τ² − a²) dτ],
/// exact until the first wave's reflection returns from the base (t < (2H − x)/c_1).
struct BiotColumn {
  double constrained_modulus_Pa, fluid_bulk_modulus_Pa, porosity;
  double dry_density_kg_m3, fluid_density_kg_m3;
  double permeability_m_s, conductivity_gravity_m_s2;

  struct Wave {
    double speed_m_s;      ///< c of the drag-free mode
    double damping_1_s;    ///< γ: its front's jump decays as e^{−γt}
    double liquid_motion;  ///< φ_w with φ_s = 1: the liquid's velocity per unit of the solid's
  };
  /// The fast (index 0) and slow (index 1) waves.
  Wave wave(int index) const;
  /// The relative mismatch of Verruijt's condition, (E_c + (1 − n)K) ρ_w/(K ρ_d) − 1.
  double uncoupling_mismatch() const;

  /// In the uncoupled case (uncoupling_mismatch() ≈ 0): p and σ'_zz (tension positive) at depth x
  /// under a load P on the drained top, before the first wave's reflection returns. The load
  /// rises along a half cosine over `ramp_s` (0: a step), P(t) = P (1 − cos(πt/t_r))/2, and the
  /// answer is the step's by Duhamel's integral, ∫ P'(τ) G(x, t − τ) dτ (16-point Gauss–Legendre
  /// over the part of the ramp whose slow front has passed x, where the integrand is smooth).
  double pressure(double load_Pa, double ramp_s, double depth_m, double t_s) const;
  double effective_stress(double load_Pa, double ramp_s, double depth_m, double t_s) const;
  /// The slow wave's share of the load's pore pressure, −P_2/P: what its front takes away.
  double slow_wave_pressure_share() const;
  /// The fast wave's share, P_1/P (the undrained share of this column).
  double fast_wave_pressure_share() const;
  /// F(a, t) of the slow wave, a = x/c_2.
  double slow_step_response(double delay_s, double t_s) const;
  /// Its response to the half-cosine ramp over t_r, ∫ (P'(τ)/P) F(a, t − τ) dτ.
  double ramped_slow_response(double ramp_s, double delay_s, double t_s) const;
};

}  // namespace ffp
