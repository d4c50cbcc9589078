#include "mpm/stages.hpp"

namespace ffp::mpm {

StageList build_stages(const Simulation& s) {
  StageList list;
  list.append({"reset_grid", reset_grid});
  list.append({"compute_shape_functions", compute_shape_functions});
  list.append({"map_particles_to_grid", map_particles_to_grid});
  const StrainSmoothing smoothing = s.settings.strain_smoothing;
  if (smoothing != StrainSmoothing::off) list.append({"smooth_mean_stress", smooth_mean_stress});
  list.append({"compute_internal_forces", compute_internal_forces});
  if (s.gravity_m_s2) list.append({"apply_gravity", apply_gravity});
  if (!s.pressures.empty()) list.append({"apply_surface_pressure", apply_surface_pressure});
  if (s.settings.local_damping > 0.0) list.append({"apply_local_damping", apply_local_damping});
  list.append({"integrate_grid", integrate_grid});
  if (!s.absorbing.empty()) list.append({"apply_absorbing_boundaries", apply_absorbing_boundaries});
  list.append({"apply_boundary_conditions", apply_boundary_conditions});
  list.append({"update_particles", update_particles});
  if (s.settings.transfer != Transfer::usl) {
    list.append({"map_velocities_to_grid", map_velocities_to_grid});
    list.append({"apply_boundary_conditions", apply_boundary_conditions});
    list.append({"compute_strain_increments",
                 [](Simulation& sim) { compute_strain_increments(sim, StrainVelocity::remapped); }});
    if (s.settings.transfer == Transfer::musl_remapped) list.append({"move_particles", move_particles});
  } else {
    list.append({"compute_strain_increments",
                 [](Simulation& sim) { compute_strain_increments(sim, StrainVelocity::updated_grid); }});
  }
  if (smoothing == StrainSmoothing::volumetric) list.append({"smooth_volumetric_strain", smooth_volumetric_strain});
  if (smoothing == StrainSmoothing::full) list.append({"smooth_strain_increment", smooth_strain_increment});
  list.append({"update_stresses", update_stresses});
  list.append({s.settings.fixed_dt_s ? "check_time_step" : "update_time_step", update_time_step});
  if (s.micropolar.active()) insert_micropolar_stages(list, s.settings.transfer);
  return list;
}

}  // namespace ffp::mpm
