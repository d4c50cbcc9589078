#pragma once
/// The nodal contact law of multi-field MPM (Bardenhagen et al. 2000): at a
/// node shared by a body and a surface, the body's velocity is corrected only
/// when it approaches the surface; the normal relative velocity is removed and
/// the tangential slip is reduced as Coulomb friction allows. Separating
/// bodies are left alone (free separation).
namespace ffp::mpm {

struct Vector2 {
  double r = 0.0, z = 0.0;
};

struct ContactLaw {
  double friction = 0.0;  ///< μ = tan δ
  bool rough = false;     ///< no slip at all (the limit μ → ∞)
  /// Cap on a correction's strain per step (Bardenhagen et al. 2001, as the paper's
  /// code applies it: Anura3D's MaxStrainRate, 0.75 in the paper): a correction
  /// |v' − v| with |v' − v|·Δt/h > cap is scaled down to cap·h/Δt. It removes only
  /// pathological corrections (where the soil's nodal mass is tiny): in the FFP
  /// runs |v' − v|Δt/h ≈ 0.06. 0: no cap.
  double velocity_scaling = 0.75;
};

/// The velocity of a body at a node after contact with a surface moving at
/// `surface` (the rigid body's velocity, or the centre-of-mass velocity of the
/// two bodies). `normal` is the surface's unit outward normal, pointing into
/// the body. Approaching when (v − v_s)·n < 0; then, with Δv = v − v_s,
///   Δv_n = (Δv·n) n,  Δv_t = Δv − Δv_n,
///   slip: Δv_t' = Δv_t (1 − μ|Δv·n|/|Δv_t|)  if |Δv_t| > μ|Δv·n|, else 0 (stick),
///   v' = v_s + Δv_t'                         (Bardenhagen, Brackbill & Sulsky 2000, frictional contact),
/// and the returned velocity is v + s (v' − v), s = min(1, cap·h/(Δt|v' − v|)) (the
/// velocity scaling cap of Bardenhagen et al. 2001). `dt_over_h` = Δt/h of the
/// node (0: no cap).
Vector2 contact_velocity(Vector2 body, Vector2 surface, Vector2 normal, const ContactLaw& law, double dt_over_h = 0.0);

}  // namespace ffp::mpm
