#pragma once
/// The stages of the explicit step, in their usual order. Each is short
/// enough to read whole; each transfer opens with the formula it implements.
/// Notation: S_ip, G_ip = ∇S_ip particle–node weights; m, V per radian.
#include <cstdint>
#include <span>
#include <vector>

#include "mpm/simulation.hpp"

namespace ffp::mpm {

/// The stage list a simulation's settings call for (a model gets only what it needs).
StageList build_stages(const Simulation& simulation);

/// The cell means of the strain smoothing leave out the particles of a granular
/// body that are at or below its disconnection density (by default half the
/// initial density: J = V/V0 ≥ 2): they carry no stress and neither give nor
/// take the cell's mean (pushed off the axis to the shaft, they reached
/// J = 10–36 and diluted the mean stress there).
/// Per body: the density (kg/m³) at or below which a particle is left out of the cell means (0: none).
std::vector<double> cell_mean_density_limits(const Simulation& s);
inline bool takes_part_in_cell_means(const Particles& P, std::size_t p, const std::vector<double>& limit) {
  return P.mass[p] > limit[P.body[p]] * P.volume[p];
}

/// Whether the step uses linear hats (two nodes per direction) rather than GIMP (three).
inline bool uses_linear_hats(const Simulation& s) { return s.settings.shape_function == ShapeFunction::linear; }

void reset_grid(Simulation& s);               ///< zero mass, momentum and forces of every field
void compute_shape_functions(Simulation& s);  ///< S_ip, G_ip at start-of-step positions; strip bins
void map_particles_to_grid(Simulation& s);    ///< m_i, p_i
void smooth_mean_stress(Simulation& s);       ///< cell-averaged mean stress for the internal force
/// The pieces of smooth_mean_stress: zero the cell sums; then, per strip, sum and
/// divide the strip's own cells (no other strip touches them).
void clear_cell_mean_stress(Simulation& s);
void strip_cell_mean_stress(Simulation& s, int strip, std::span<const std::uint32_t> particles,
                            const std::vector<double>& limit);
void compute_internal_forces(Simulation& s);     ///< f_i^int incl. the hoop term
void apply_gravity(Simulation& s);               ///< f_i^ext += m_i g
void apply_surface_pressure(Simulation& s);      ///< nodal forces of pressures on r grid lines
void apply_local_damping(Simulation& s);         ///< Cundall: f_i −= α |f_i| sign(v_i)
void integrate_grid(Simulation& s);              ///< v_i^n = p_i/m_i, v_i^{n+1} = v_i^n + Δt f_i/m_i
void apply_boundary_conditions(Simulation& s);   ///< zero constrained velocity components
void apply_absorbing_boundaries(Simulation& s);  ///< dashpots and the held static reaction on absorbing sides
void update_particles(Simulation& s);            ///< FLIP/PIC velocity; position (but musl_remapped); MUSL: p_i
void move_particles(Simulation& s);              ///< musl_remapped: position from the remapped velocities
void map_velocities_to_grid(Simulation& s);      ///< MUSL: v_i = Σ S m v_p^{n+1} / m_i (sum from update_particles)

void compute_strain_increments(Simulation& s, StrainVelocity source);  ///< Δε, spin, volume
void smooth_volumetric_strain(Simulation& s);                          ///< cell-averaged Δε_vol
/// Δε, spin and volume of a strip's particles (smooth_volumetric_strain, when
/// compute_strain_increments deferred them: Simulation::strain_deferred).
void strain_increments_of_strip(Simulation& s, std::span<const std::uint32_t> strip);
void smooth_strain_increment(Simulation& s);  ///< cell-averaged whole Δε (strain_smoothing full)
void update_stresses(Simulation& s);          ///< Jaumann rotation, then the law
void update_time_step(Simulation& s);         ///< CFL Δt for the next step (or check a fixed Δt)

// The micropolar option's stages (mpm/stage_micropolar.cpp; inserted by insert_micropolar_stages).
void map_micropolar_to_grid(Simulation& s);          ///< Θ_i, angular momentum, couple force; skew stress into f_i^int
void integrate_micro_rotation(Simulation& s);        ///< ω̇_i^n, ω̇_i^{n+1}; fixities of ω
void update_particle_micro_rotation(Simulation& s);  ///< FLIP/PIC ω̇_p
void map_micro_spin_to_grid(Simulation& s);          ///< MUSL: ω̇_i = Σ S m j ω̇_p / Θ_i
void update_micropolar_stresses(Simulation& s);      ///< ω_p, skew and couple stresses

// Saturated bodies (mpm/two_phase.hpp, mpm/stage_two_phase.cpp), inserted by build_stages.
void map_liquid_to_grid(Simulation& s);                ///< M_w, M̄_w, liquid momentum, drag Q
void add_pore_pressure_forces(Simulation& s);          ///< f_e of the excess p − p_h (cell-smoothed) on both phases
void integrate_liquid(Simulation& s);                  ///< a_w with drag, v_w^{n+1}; M̄_w (g − a_w) on the solid
void apply_liquid_boundary_conditions(Simulation& s);  ///< v_w,n = 0 on impermeable sides and the axis
void update_liquid_particles(Simulation& s);           ///< v_w,p FLIP/PIC; MUSL: the liquid's remap
void compute_liquid_strain(Simulation& s);             ///< Δε_v,w = Δt ∇·v_w (hoop term included)
void update_pore_pressure(Simulation& s);              ///< storage equation, cavitation floor, porosity
void limit_two_phase_time_step(Simulation& s);         ///< Δt ≤ C · Mieremet's two-phase step

}  // namespace ffp::mpm
