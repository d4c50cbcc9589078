#pragma once
/// The state of an axisymmetric explicit MPM run and its step. Stages
/// (mpm/stages.hpp) are free functions on this state; the step runs them in
/// the order of `stages`.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/voigt.hpp"
#include "mpm/grid.hpp"
#include "mpm/material_group.hpp"
#include "mpm/micropolar.hpp"
#include "mpm/model.hpp"
#include "mpm/particle_bins.hpp"
#include "mpm/particles.hpp"
#include "mpm/shape_functions.hpp"
#include "mpm/signal_maxima.hpp"
#include "mpm/stage_list.hpp"
#include "mpm/two_phase.hpp"

namespace ffp::mpm {

/// A step that cannot go on (a particle left the grid, NaN, Δt above the CFL
/// limit): the caller reports it; mpm/ itself prints nothing.
class StepFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The nodal velocities compute_strain_increments reads: v^{n+1} of the grid update, or
/// the MUSL-remapped ones.
enum class StrainVelocity : std::uint8_t { updated_grid, remapped };

/// Where particles are kept by constrained grid sides (±∞ on free sides).
struct Walls {
  double r_min, r_max, z_min, z_max;
};

struct Body {
  std::string name;
  std::size_t group = 0;           ///< its material group
  std::uint8_t field = 0;          ///< the nodal field its particles map to (0 without contact)
  std::size_t begin = 0, end = 0;  ///< particle range
};

class Simulation {
 public:
  explicit Simulation(const ModelDescription& model);

  /// One explicit step: every stage in order, then t ← t + Δt.
  void advance();

  // --- configuration (fixed after construction) -----------------------------
  SolverSettings settings;
  std::optional<double> gravity_m_s2;  ///< magnitude along −z
  std::vector<SurfacePressure> pressures;
  double mass_floor_kg = 0.0;  ///< nodes lighter than this are empty

  // --- state ----------------------------------------------------------------
  Grid grid;
  Particles particles;
  std::vector<MaterialGroup> groups;
  std::vector<Body> bodies;
  StageList stages;
  double time_s = 0.0;
  double dt_s = 0.0;        ///< step of the current (next) advance()
  double dt_next_s = 0.0;   ///< set by update_time_step; becomes dt_s after the step
  double dt_limit_s = 0.0;  ///< CFL limit h_min/(c_p + |v|_max) at the last check
  long step = 0;
  /// Speed of the fastest rigid body that has no particles (the rigid
  /// penetrometer): the CFL step counts it like a particle's |v|, since the soil
  /// it touches moves with it, and a body that crosses more than a cell per step
  /// jumps over its contact nodes (measured: a 200 m/s impact failed at step 0).
  double rigid_speed_m_s = 0.0;
  Walls walls{};                         ///< from the boundary conditions
  std::vector<AbsorbingNode> absorbing;  ///< nodes on absorbing sides (mpm/boundary_conditions.hpp)
  Impedance beyond{};                    ///< the material beyond them: the first body's
  /// The static reaction each absorbing node carried at the first step, per field (field-major,
  /// N per radian): held constant, so that a sand at rest stays at rest.
  std::vector<double> absorbing_reaction_r, absorbing_reaction_z;
  /// Each absorbing node's displacement since the start, per field (the springs' extension).
  std::vector<double> absorbing_displacement_r, absorbing_displacement_z;
  MicropolarFields micropolar;  ///< the micropolar bodies' fields (inactive when there are none)
  long wall_clamps = 0;         ///< particle moves stopped at a wall or the axis (should stay 0)
  /// The pore fluid of the saturated bodies (mpm/two_phase.hpp); none when every body is dry.
  std::optional<TwoPhase> two_phase;
  /// Particles [0, main_step_end) are moved, strained and stressed by the step's stages;
  /// those after it belong to a body that takes its own substeps inside the step
  /// (mpm/body_subcycle.hpp) and only lend their mass and momentum to the grid.
  /// All particles unless a body is subcycled.
  std::size_t main_step_end = 0;

  // --- per-step scratch, valid from compute_shape_functions to the step's end
  std::vector<ShapeWeights> weights;
  ParticleBins bins;
  std::vector<std::uint32_t> strip;  ///< each particle's ParticleBins strip
  std::vector<std::uint32_t>
      cell;  ///< each particle's grid cell (apart from its weights: the cell means read only this)
  std::vector<Voigt> strain_increment;  ///< Δε_p this step (Voigt)
  bool internal_forces_mapped = false;  ///< map_particles_to_grid made f_i^int (and the cell means) too
  /// compute_strain_increments left Δε to smooth_volumetric_strain, right after it
  /// (one pass over each strip: the increments, the cell sums, the shifts).
  bool strain_deferred = false;
  StrainVelocity strain_source = StrainVelocity::updated_grid;  ///< the nodal velocities of the deferred Δε
  bool gravity_deferred = false;   ///< apply_gravity left m_i g to integrate_grid, right after it
  bool momentum_remapped = false;  ///< update_particles summed p_i = Σ S m v^{n+1} (MUSL) for map_velocities_to_grid
  std::vector<double> spin_dt;     ///< W_rz·Δt, W = ½(L − Lᵀ), for the Jaumann rate
  /// Per group, the CFL maxima update_stresses formed as it stressed the group's particles,
  /// for update_time_step right after it (empty otherwise; only that stage reads them).
  std::vector<std::optional<SignalMaxima>> stressed_signal;
  /// Smoothing per (cell, body), slot = cell·bodies + body: volume, V-weighted Δε_v, mean stress.
  std::vector<double> cell_volume, cell_volumetric_strain, cell_mean_stress;
  std::vector<Voigt> cell_strain_increment, cell_stress;  ///< strain_smoothing full: whole cell-mean tensors
};

/// The CFL limit Δt_crit = h_min / (c_p + |v|_max): c_p = √(M/ρ) of each group at
/// its lowest current density, |v|_max of its particles (throws StepFailure on NaN).
/// A micropolar group's c² adds its micro terms' stiffness (MicropolarGroup::wave_modulus).
/// A subcycled group (past main_step_end) counts with its speed only: its own
/// substeps keep its p-wave stable.
double cfl_time_step_limit(const Simulation& simulation);
/// The same limit, with the maxima of the groups that `formed` holds (update_stresses'
/// Simulation::stressed_signal, this step's) instead of a pass of their own: the same bits.
double cfl_time_step_limit(const Simulation& simulation, const std::vector<std::optional<SignalMaxima>>& formed);

/// The same limit for one group alone (one of simulation.groups), its p-wave included (a
/// subcycled body's substep).
double group_time_step_limit(const Simulation& simulation, const MaterialGroup& group);

/// The critical step of the explicit two-phase scheme (mieremet_time_step, L = h_min) at the
/// stiffest saturated particle, its current porosity and permeability; +∞ without a saturated body.
double two_phase_time_step_limit(const Simulation& simulation);

}  // namespace ffp::mpm
