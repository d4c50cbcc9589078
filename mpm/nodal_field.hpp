#pragma once
/// One velocity field on the grid nodes (structure of arrays, per radian).
///
/// Without contact every body maps into field 0. Contact (Bardenhagen et al.
/// 2001) gives each body its own field plus a system field; the per-body
/// arrays stay what they are here, so soil nodal forces (paper eq. 1,
/// f_soil^i) are read straight from the soil field's internal_force_z.
#include <cstddef>
#include <vector>

namespace ffp::mpm {

struct NodalField {
  std::vector<double> mass;                                ///< m_i = Σ_p S_ip m_p
  std::vector<double> momentum_r, momentum_z;              ///< p_i = Σ_p S_ip m_p v_p
  std::vector<double> internal_force_r, internal_force_z;  ///< from particle stresses
  std::vector<double> external_force_r, external_force_z;  ///< gravity, surface loads, damping
  /// v_i^n = p_i/m_i (MUSL: remapped v_i^{n+1}; while a MUSL step's update_particles
  /// runs, v_i^{n+1} − v_i^n)
  std::vector<double> velocity_r, velocity_z;
  std::vector<double> velocity_new_r, velocity_new_z;  ///< v_i^{n+1} = v_i^n + Δt f_i/m_i

  void resize(std::size_t nodes);
  std::size_t size() const { return mass.size(); }
  /// Zero what particles map each step (mass, momentum, forces).
  void reset();
};

}  // namespace ffp::mpm
