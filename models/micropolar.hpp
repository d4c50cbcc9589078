#pragma once
/// The micropolar (Cosserat) option of a material: the linear elastic micro terms added to a
/// classical law, which itself stays a black box on the symmetric strain (docs/theory.md#micropolar).
///
/// A micro-rotation ω about the hoop axis, independent of the macro rotation ω_M = ½(∂u_r/∂z − ∂u_z/∂r),
/// stores energy in two linear elastic terms (the linear Cosserat elasticity of Mühlhaus &
/// Vardoulakis 1987 and de Borst 1991, restricted to a rotation about e_θ; the hoop curvature −ω/r
/// is the θ-derivative of the vector ω e_θ in cylindrical coordinates):
///
///   W_micro = 2 G_c (ω_M − ω)² + G ℓ² κ·κ,   κ = (∂ω/∂r, ∂ω/∂z, −ω/r),
///
/// whence the skew (relative-rotation) stress s = σ_rz − σ_zr part and the couple stresses
///
///   s = 2 G_c (ω_M − ω)   (the skew part of σ: σ_rz += s, σ_zr −= s),   m = 2 G ℓ² κ,
///
/// with G the law's elastic shear modulus, G_c = cosserat_shear_ratio · G, ℓ the internal length,
/// and j (m²) the rotational inertia per unit mass (ρ j per unit volume). Only these terms are
/// new: the law's return (MC, SSMC) acts on the symmetric strain increment as before.
#include <algorithm>
#include <cmath>

namespace ffp {

struct MicropolarParameters {
  double length_m = 0.0;              ///< ℓ, the internal length (≈ d50: Mühlhaus & Vardoulakis 1987)
  double cosserat_shear_ratio = 0.5;  ///< G_c / G
  double micro_inertia_m2 = 0.0;      ///< j: ρ j is the rotational inertia per unit volume (sphere: d²/10)
  /// Whether the micro terms slip at the sand's friction: |s| ≤ tan φ' p and |m| ≤ ℓ tan φ' p
  /// (p the mean pressure), as a grain contact's tangential force and rolling moment are bounded
  /// by its normal force (Iwashita & Oda 1998). Off: the micro terms stay elastic at any rotation.
  bool friction_limited = false;

  /// G_c = ratio · G (Pa).
  double cosserat_shear_modulus(double shear_modulus_Pa) const { return cosserat_shear_ratio * shear_modulus_Pa; }
  /// 2 G ℓ² (N): m = 2 G ℓ² κ.
  double couple_modulus(double shear_modulus_Pa) const { return 2.0 * shear_modulus_Pa * length_m * length_m; }
  /// The micro-rotation's own angular frequency √(4 G_c/(ρ j)) (rad/s): the rate at which ω
  /// returns to ω_M with no curvature (a uniform field: ρ j ω̈ = −4 G_c (ω − ω_M)).
  double rotation_frequency(double shear_modulus_Pa, double density_kg_m3) const {
    return std::sqrt(4.0 * cosserat_shear_modulus(shear_modulus_Pa) / (density_kg_m3 * micro_inertia_m2));
  }
  /// The couple-stress wave speed ℓ √(2 G/(ρ j)) (m/s): ρ j ω̈ = 2 G ℓ² ∇²ω at short wavelengths.
  double couple_wave_speed(double shear_modulus_Pa, double density_kg_m3) const {
    return length_m * std::sqrt(2.0 * shear_modulus_Pa / (density_kg_m3 * micro_inertia_m2));
  }
};

/// A particle's micro stresses: the skew stress s (Pa) and the couple vector m (N/m).
struct MicroStresses {
  double skew = 0.0;
  double couple_r = 0.0, couple_z = 0.0, couple_hoop = 0.0;

  double couple_norm() const {
    return std::sqrt(couple_r * couple_r + couple_z * couple_z + couple_hoop * couple_hoop);
  }
};

/// The micro stresses held to the sand's friction (MicropolarParameters::friction_limited):
/// |s| ≤ μ p and |m| ≤ ℓ μ p, μ = tan φ', p ≥ 0 the mean pressure. A trial beyond a limit is
/// returned onto it along its own direction (the closest point of each convex set, so the
/// slip's dissipation μ p |Δω^p| + ℓ μ p |Δκ^p| is positive); inside, it is unchanged.
inline MicroStresses held_at_friction(MicroStresses trial, double friction_tangent, double length_m,
                                      double pressure_Pa) {
  const double skew_limit = friction_tangent * std::max(0.0, pressure_Pa), couple_limit = length_m * skew_limit;
  trial.skew = std::clamp(trial.skew, -skew_limit, skew_limit);
  const double couple = trial.couple_norm();
  if (couple > couple_limit) {
    const double scale = couple_limit / couple;
    trial.couple_r *= scale;
    trial.couple_z *= scale;
    trial.couple_hoop *= scale;
  }
  return trial;
}

}  // namespace ffp
