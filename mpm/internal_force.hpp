#pragma once
/// A particle's share of the internal force, f_i^int −= V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r]
/// (the hoop term of axisymmetry beside the plane ones), and the stress it takes under
/// B-bar: the one definition that the soil's scatter and a subcycled body's substeps share.
#include <cstddef>

#include "models/voigt.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp::mpm {

/// The components of σ_p the internal force takes (rr, zz, θθ, rz). Four doubles
/// rather than a Voigt copy, which the scatter loops kept on the stack.
struct ForceStress {
  double rr, zz, tt, rz;
};

inline ForceStress own_force_stress(const Voigt& own) { return {own[0], own[1], own[2], own[3]}; }

/// B-bar (Hughes 1980): the cell's mean stress σ̄_m stands in for the particle's tr(σ_p)/3.
inline ForceStress b_bar_force_stress(const Voigt& own, double cell_mean_stress) {
  const double shift = cell_mean_stress - trace(own) / 3.0;
  return {own[0] + shift, own[1] + shift, own[2] + shift, own[3]};
}

/// f_i^int −= V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r] over the particle's S×S support; node(a, b)
/// is where the support's node (a, b) sits in force_r and force_z (for_support_at).
template <int S, class Node>
inline void add_internal_force(const ShapeWeights& w, const ForceStress& sig, double V, Node&& node, double* force_r,
                               double* force_z) {
  const double hoop = sig.tt * w.inverse_r;
  for_support_at<S>(w, node, [&](std::size_t i, double N, double Gr, double Gz) {
    force_r[i] -= V * (sig.rr * Gr + sig.rz * Gz + hoop * N);
    force_z[i] -= V * (sig.rz * Gr + sig.zz * Gz);
  });
}

}  // namespace ffp::mpm
