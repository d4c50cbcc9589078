#include "mpm/stages.hpp"

namespace ffp::mpm {

namespace {

/// A saturated body's stages, around the dry step's (docs/theory.md#saturated): the liquid is
/// mapped and its pore pressure pushes both phases after the solid's internal force; the liquid
/// is integrated before the solid (whose acceleration takes −M̄_w a_w), and before any local
/// damping, which then sees the mixture's whole force; the liquid's particles follow the
/// solid's; the storage equation takes both phases' strains before the effective stress.
void insert_two_phase_stages(StageList& list, const Simulation& s) {
  list.insert_after("compute_internal_forces", {"map_liquid_to_grid", map_liquid_to_grid});
  list.insert_after("map_liquid_to_grid", {"add_pore_pressure_forces", add_pore_pressure_forces});
  list.insert_before(list.contains("apply_local_damping") ? "apply_local_damping" : "integrate_grid",
                     {"integrate_liquid", integrate_liquid});
  list.insert_after("apply_boundary_conditions",
                    {"apply_liquid_boundary_conditions", apply_liquid_boundary_conditions});
  list.insert_after("update_particles", {"update_liquid_particles", update_liquid_particles});
  list.insert_before("update_stresses", {"compute_liquid_strain", compute_liquid_strain});
  list.insert_before("update_stresses", {"update_pore_pressure", update_pore_pressure});
  list.insert_after(s.settings.fixed_dt_s ? "check_time_step" : "update_time_step",
                    {"limit_two_phase_time_step", limit_two_phase_time_step});
}

}  // namespace

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
  if (s.two_phase) insert_two_phase_stages(list, s);
  return list;
}

}  // namespace ffp::mpm
