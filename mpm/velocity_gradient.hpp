#pragma once
/// A particle's strain increment, spin and volume from its velocity gradient over
/// one step, in axisymmetry (L_θθ = v_r/r): the one definition that the soil's
/// step and a subcycled body's substeps share.
#include "models/voigt.hpp"

namespace ffp::mpm {

/// The velocity gradient L_p = Σ_i v_i ⊗ G_ip (r, z) and L_θθ = Σ_i S_ip v_r,i / r_p.
struct VelocityGradient {
  double rr = 0.0, rz = 0.0, zr = 0.0, zz = 0.0, tt = 0.0;
};

/// Δε = Δt sym(L), spin·Δt = Δt skew(L)_rz, V ← V det(I + Δt L).
inline void apply_velocity_gradient(const VelocityGradient& L, double dt, Voigt& strain_increment, double& spin_dt,
                                    double& volume) {
  strain_increment << dt * L.rr, dt * L.zz, dt * L.tt, 0.5 * dt * (L.rz + L.zr), 0.0, 0.0;
  spin_dt = 0.5 * dt * (L.rz - L.zr);
  volume *= ((1.0 + dt * L.rr) * (1.0 + dt * L.zz) - dt * dt * L.rz * L.zr) * (1.0 + dt * L.tt);
}

}  // namespace ffp::mpm
