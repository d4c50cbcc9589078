#pragma once
/// A particle's strain increment, spin and volume from its velocity gradient over
/// one step, in axisymmetry (L_θθ = v_r/r), and the Jaumann rotation its spin gives
/// the stress: the one definition that the soil's step and a subcycled body's
/// substeps share.
#include <cstddef>

#include "models/voigt.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp::mpm {

/// The velocity gradient L_p = Σ_i v_i ⊗ G_ip (r, z) and L_θθ = Σ_i S_ip v_r,i / r_p.
struct VelocityGradient {
  double rr = 0.0, rz = 0.0, zr = 0.0, zz = 0.0, tt = 0.0;
};

/// L_p over a particle's S×S support node by node; node(a, b) is where the support's
/// node (a, b) sits in vr and vz (for_support_at).
template <int S, class Node>
inline VelocityGradient velocity_gradient(const ShapeWeights& w, Node&& node, const double* vr, const double* vz) {
  VelocityGradient L;
  for_support_at<S>(w, node, [&](std::size_t i, double N, double Gr, double Gz) {
    L.rr += vr[i] * Gr;
    L.rz += vr[i] * Gz;
    L.zr += vz[i] * Gr;
    L.zz += vz[i] * Gz;
    L.tt += vr[i] * N;
  });
  L.tt *= w.inverse_r;
  return L;
}

/// Δε = Δt sym(L), spin·Δt = Δt skew(L)_rz, V ← V det(I + Δt L).
inline void apply_velocity_gradient(const VelocityGradient& L, double dt, Voigt& strain_increment, double& spin_dt,
                                    double& volume) {
  strain_increment << dt * L.rr, dt * L.zz, dt * L.tt, 0.5 * dt * (L.rz + L.zr), 0.0, 0.0;
  spin_dt = 0.5 * dt * (L.rz - L.zr);
  volume *= ((1.0 + dt * L.rr) * (1.0 + dt * L.zz) - dt * dt * L.rz * L.zr) * (1.0 + dt * L.tt);
}

/// Jaumann rate (objective for large rotations), before the law:
///   σ ← σ + ΔW σ − σ ΔW,  ΔW = [[0, w], [−w, 0]] in (r, z), w = W_rz Δt:
///   σ_rr += 2wσ_rz,  σ_zz −= 2wσ_rz,  σ_rz += w(σ_zz − σ_rr);  σ_θθ unchanged.
inline void rotate_by_spin(Voigt& stress, double spin_dt) {
  const double w = spin_dt, rr = stress[0], zz = stress[1], rz = stress[3];
  stress[0] = rr + 2.0 * w * rz;
  stress[1] = zz - 2.0 * w * rz;
  stress[3] = rz + w * (zz - rr);
}

}  // namespace ffp::mpm
