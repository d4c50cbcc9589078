#pragma once
/// Multi-time-step explicit integration of one stiff body (the steel
/// penetrometer): the step Δt_s is the soft material's CFL step, and the body
/// takes N = ⌈Δt_s/Δt_b⌉ substeps δt = Δt_s/N of its own inside it, Δt_b its
/// own CFL step (Courant · h_min/(c_p + |v|)). Only its particles and the nodes
/// they reach are touched, so a substep costs O(body particles), not O(grid).
///
/// Within the step the grid is the Lagrangian grid of MPM (Sulsky et al. 1994):
/// it moves with the body, so the particles' weights S_ip and gradients G_ip of
/// the step's start hold for every substep, and the nodal velocities live on
/// the grid from substep to substep (as nodes of a finite-element mesh with the
/// particles as its quadrature points):
///   f_i^int,k = −Σ_p V_p^k [σ_p^k·G_ip + σ_θθ,p^k S_ip/r_p e_r]   (as compute_internal_forces)
///   v_i^{k+1} = v_i^k + δt (f_i^int,k + f_i^ext + J_i/Δt_s)/m_i,   v_i^0 = p_i/m_i of the step's mapping
///   Δε_p^k = δt sym(Σ_i v_i^{k+1} ⊗ G_ip) (+ hoop), σ_p^{k+1} = law(σ_p^k, Δε_p^k),  V_p ← V_p det(I + δt L)
/// and once at the step's end the particles take the grid's change (USL, FLIP/PIC):
///   v_p ← α (v_p + Σ_i S_ip (v_i^N − v_i^0)) + (1 − α) Σ_i S_ip v_i^N,   x_p ← x_p + Σ_i S_ip Σ_k δt v_i^{k+1}.
/// The soft material's contact with the body is exchanged once per step: the
/// nodal impulses J_i it hands the body (per radian) act as the constant force
/// J_i/Δt_s over the substeps, so the body gains Σ J_i and momentum is conserved
/// as in the single step (Σ_i f_i^int,z = 0 by the partition of unity, up to the
/// forces on nodes below the mass floor: ~1e-8 of the exchange). Its substeps start
/// from v_i^0 = p_i/m_i, which nothing but J_i may change (the classic MUSL's
/// remapped contact corrects the soil's side only).
/// Contact once per step is no loss for a body the soil sees as rigid (steel: its
/// p-wave crosses it within a soil step): the subcycled run is the rigid FFP's at
/// the soil's step; what it misses against the single step is the soil's step.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/simulation.hpp"

namespace ffp::mpm {

/// An impulse on a node of the body's field over the step (per radian, N·s).
struct NodalImpulse {
  std::size_t node = 0;
  double r = 0.0, z = 0.0;
};

class BodySubcycle {
 public:
  /// `body` must be the simulation's last body; from now on the step's own
  /// stages leave its particles to advance() (Simulation::main_step_end).
  BodySubcycle(Simulation& simulation, std::size_t body);

  /// The body's nodal velocity for contact at the step (integrate_grid's v_i^{n+1}
  /// without the body's internal force, which its substeps resolve):
  /// v*_i = p_i/m_i + Δt_s f_i^ext/m_i; and the step's substep count N from the
  /// body's CFL step at the step's start.
  void predict_contact_velocity(Simulation& simulation);

  /// How many times its nodal mass a body node weighs in the step's contact: the
  /// body's impedance over the step. A force held for Δt_s on an elastic column moves
  /// the mass its p-wave reaches in that time, ρ A (c_p + |v|) Δt_s = m_f (c_p + |v|) Δt_s/h
  /// ≈ N·C nodal masses (1D wave, Z·Δt; ≥ 1: the single step, N = 1, sees the nodal
  /// mass alone). For steel (N·C ≈ 40–100) the soil takes the body's velocity at the
  /// contact, as it does over the single step's N tiny steps (with the nodal mass alone
  /// the peak fell by 30 % at 2 cm), and the result is the rigid FFP's at the soil's
  /// step (measured at 1 cm, 50 ms: 0.1721 m against the rigid's 0.1719 m), which the
  /// exact momentum exchange of a rigid body (RigidPenetrometer, contact_impulse) is.
  double contact_mass_factor() const { return contact_mass_factor_; }

  /// The N substeps over the step's Δt_s and the final particle update.
  void advance(Simulation& simulation, const std::vector<NodalImpulse>& impulses);

  int last_substeps() const { return last_substeps_; }
  long total_substeps() const { return total_substeps_; }
  /// Work of the impulses' forces on the body's nodes over all steps, full 2π (J):
  /// Σ_steps Σ_k Σ_i δt (J_i/Δt_s)·½(v_i^k + v_i^{k+1}).
  double contact_work_J() const { return contact_work_J_; }

 private:
  template <int S>
  void run(Simulation& simulation, const std::vector<NodalImpulse>& impulses);
  // The pieces of run(), each the counterpart of a stage of the step on the body's own nodes.
  template <int S>
  void collect_support(const Simulation& simulation);
  template <int S>
  auto support_of(std::size_t body_particle) const;
  void load_nodes(const Simulation& simulation);
  std::vector<std::int32_t> add_impulses(const Simulation& simulation, const std::vector<NodalImpulse>& impulses);
  template <int S>
  void substep(Simulation& simulation, double h);
  template <class Term>
  void sum_cells(const Simulation& simulation, Term&& term);
  void mean_stress_of_cells(const Simulation& simulation);
  template <int S>
  void internal_forces(const Simulation& simulation, bool smoothed);
  void integrate_nodes(const Simulation& simulation, double h);
  template <int S>
  void strain_increments(Simulation& simulation, double h);
  void smooth_volumetric_strain(Simulation& simulation);
  void update_stresses(Simulation& simulation, double h);
  void add_contact_work(const Simulation& simulation, const std::vector<NodalImpulse>& impulses,
                        const std::vector<std::int32_t>& impulse_slots, double h);
  template <int S>
  void update_particles(Simulation& simulation);

  std::size_t body_;
  std::vector<std::uint8_t> constraint_bits_;  ///< per grid node
  std::vector<std::int32_t> node_slot_;        ///< grid node → compact node (−1: not the body's)
  std::vector<std::int32_t> cell_slot_;        ///< grid cell → compact cell (−1)
  // Compact nodes of the step: grid index, mass, velocities, forces, displacement.
  std::vector<std::size_t> nodes_;
  std::vector<double> mass_, vr_, vz_, vr0_, vz0_, fr_, fz_, er_, ez_, ur_, uz_;
  std::vector<std::int32_t> particle_nodes_;  ///< S² compact nodes per particle
  // Compact cells of the step (strain smoothing): grid cell, volume, V-weighted means.
  std::vector<std::size_t> cells_;
  std::vector<std::int32_t> particle_cell_;
  std::vector<double> cell_volume_, cell_mean_;
  int substeps_ = 1;
  double contact_mass_factor_ = 1.0;
  int last_substeps_ = 0;
  long total_substeps_ = 0;
  double contact_work_J_ = 0.0;
};

}  // namespace ffp::mpm
