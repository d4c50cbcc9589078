#pragma once
/// Saturated bodies: the pore fluid's state per particle and its nodal field, for the
/// single-point, two-velocity formulation of Jassim, Stolle & Vermeer (2013), in the
/// order Anura3D runs it (docs/theory.md#saturated). Solid and liquid each have their
/// own velocity; one material point carries both, with its porosity n and one pore
/// pressure p (gauge, compression positive). Particles::stress holds the effective
/// stress σ' (tension positive), which the laws update unchanged; the total stress is
///   σ = σ' − p I.
/// A particle's mass is its solid's, m_s = (1 − n) ρ_s V; its liquid's is n ρ_w V.
///
/// The pore pressure is the hydrostatic one of the water table z_wt plus an excess,
/// p = p_h + p_e, p_h = ρ_w g (z_wt − z). Since −∇p_h + ρ_w g = 0 exactly, the liquid's
/// weight and the hydrostatic gradient cancel before they are discretised (a
/// well-balanced form): the liquid is driven by p_e alone, the mixture carries its
/// buoyant weight, and p_e = 0 is the natural boundary condition of every side without a
/// liquid fixity (a drained side, the free surface). Per radian and lumped, with S_ip,
/// G_ip the particle–node weights and gradients:
///   liquid:   M_w a_w = f_e − Q (v_w − v_s)
///   mixture:  M_s a_s + M̄_w a_w = f^int(σ') + f_e + (M_s + M̄_w − M_w) g + f^ext
///   M_w = Σ_p S_ip ρ_w V_p,  M̄_w = Σ_p S_ip n_p ρ_w V_p,  Q = Σ_p S_ip n_p ρ_w g V_p / k_p,
///   f_e = Σ_p V_p p_e,p (G_ip + S_ip/r_p e_r)   (the internal force of −p_e I)
///   storage:  Δp* = −(K_w/n) [(1 − n) Δε_v,s + n Δε_v,w],  p = max(p*, −(p_atm − p_vap))
///   porosity: n = max(1 − m_s/(ρ_s V), 0.5 n_0)   (incompressible grains; kClosedPorosityRatio)
#include <cstddef>
#include <optional>
#include <vector>

#include "mpm/boundary_conditions.hpp"
#include "mpm/grid.hpp"
#include "mpm/model.hpp"
#include "mpm/nodal_field.hpp"
#include "mpm/particles.hpp"

namespace ffp::mpm {

/// The least porosity the two-phase terms take, as a fraction of a body's initial one. The laws
/// let a skeleton compress without bound, and a few particles squeezed on the axis under a cone's
/// apex do (the dry reference drop's deepest: V/V0 = 0.47); with incompressible grains their
/// porosity n = 1 − m_s/(ρ_s V) would fall to 0 and below, where the storage K_w/n, the drag and
/// the step have no meaning. Below this the pores count as closed: n is held at the floor
/// (TwoPhase::closed_pores counts the particles there), below any sand's densest packing
/// (n_min ≈ 0.3 for quartz sands, e_min ≈ 0.45), so no physical state reaches it.
inline constexpr double kClosedPorosityRatio = 0.5;

/// A body's pores.
struct PoreSpace {
  bool saturated = false;
  double grain_density_kg_m3 = 0.0;  ///< ρ_s = ρ_d/(1 − n_0)
  double initial_porosity = 0.0;
  double initial_permeability_m_s = 0.0;
  PermeabilityLaw permeability_law = PermeabilityLaw::constant;
};

struct TwoPhase {
  PoreFluid fluid;
  std::vector<PoreSpace> bodies;  ///< per body
  double gravity_m_s2 = 0.0;      ///< the model's (0 without gravity)
  /// The water table z_wt of the hydrostatic pore pressure p_h = ρ_w g (z_wt − z): the model's
  /// (ModelDescription::water_table_z_m), else the first saturated body's K0 surface. None (no
  /// gravity or no K0 stress): p_h = 0.
  std::optional<double> water_table_z_m;

  // Per particle (all of them; a dry body's entries stay 0).
  std::vector<double> porosity;
  std::vector<double> liquid_vr, liquid_vz;  ///< the liquid's velocity v_w (m/s)
  std::vector<double> pore_pressure;         ///< p (Pa, gauge, compression positive), hydrostatic included
  /// The pressure the storage equation gives the liquid, p* (Pa); p = max(p*, p_cavitation).
  /// Below the floor, (p_cavitation − p*) n/K_w is the vapour's volume per unit volume: a
  /// recompression condenses it before the pressure rises again.
  std::vector<double> liquid_pressure;
  std::vector<double> liquid_strain;  ///< Δε_v,w = Δt ∇·v_w of this step
  /// Particles whose porosity is held at kClosedPorosityRatio × n_0 after the last step, and the
  /// most at any step.
  std::size_t closed_pores = 0, closed_pores_max = 0;

  /// The liquid's nodes: mass = M_w, momentum Σ S ρ_w V v_w, internal force f_e;
  /// velocities as a NodalField's (its external force stays zero).
  NodalField liquid;
  std::vector<double> porous_mass;                 ///< M̄_w,i = Σ S n ρ_w V
  std::vector<double> drag;                        ///< Q_i = Σ S n ρ_w g V/k (kg/s per radian)
  std::vector<NodeConstraint> liquid_constraints;  ///< impermeable sides and the axis: v_w,n = 0

  /// Per (cell, body) slot, slot = cell·bodies + body: V, V-weighted p (pore-pressure smoothing).
  std::vector<double> cell_volume, cell_pressure;
  /// Per slot: V, V-weighted Δε_v,w (the storage equation's cell mean of the liquid's strain).
  std::vector<double> cell_strain_volume, cell_liquid_strain;

  bool saturated(const Particles& P, std::size_t p) const { return bodies[P.body[p]].saturated; }
  /// k of a body at porosity n (kozeny_carman: k_0 [n³/(1 − n)²]/[n_0³/(1 − n_0)²]).
  double permeability(std::size_t body, double n) const;
  /// The hydrostatic pore pressure p_h at height z (Pa; negative above the water table).
  double hydrostatic_pressure(double z_m) const;
  /// Sets a particle's pore pressure (and its liquid's, which then holds no vapour).
  void set_pore_pressure(std::size_t p, double value) { pore_pressure[p] = liquid_pressure[p] = value; }
  /// A particle's excess pore pressure p_e = p − p_h(z_p) (Pa).
  double excess_pressure(const Particles& P, std::size_t p) const {
    return pore_pressure[p] - hydrostatic_pressure(P.z[p]);
  }
};

/// The two-phase state of a model whose bodies have been seeded into `particles`:
/// porosity n_0, liquid velocity = the body's initial velocity, pore pressure hydrostatic;
/// the liquid's fixities from `model.drainage`.
/// Throws std::invalid_argument on a combination it cannot run (an impermeable side that
/// does not hold the solid's normal velocity, absorbing sides, a porosity outside (0, 1)).
TwoPhase make_two_phase(const ModelDescription& model, const Grid& grid, const Particles& particles);

/// The buoyant unit weight of a saturated body's effective stress, γ' = γ_sat − γ_w =
/// (ρ_d − (1 − n) ρ_w) g, or ρ g for a dry body: the K0 stress's unit weight.
double geostatic_unit_weight(const BodyDescription& body, const PoreFluid& fluid, double gravity_m_s2);

/// The critical time step of the explicit two-phase scheme on 1D linear elements of
/// length L (Mieremet 2015, as Anura3D takes it), no mass scaling:
///   Δt = [−2a + √(4a² + 8(b + √(b² − 4c)))] / [b + √(b² − 4c)]
///      = 8 / [2a + √(4a² + 8(b + √(b² − 4c)))]   (the same, without the cancellation at small k),
///   a = n ρ_sat g/((1 − n) ρ_s k),
///   b = 4 (n ρ_sat K_w + (1 − 2n) ρ_w K_w + n ρ_w E_c)/(n (1 − n) ρ_s ρ_w L²),
///   c = 16 E_c K_w/((1 − n) ρ_s ρ_w L⁴),
/// b and c the trace and determinant of M⁻¹K of the lumped system's shortest mode, a the
/// trace of the drag's (rank one) M⁻¹C, ρ_sat = (1 − n) ρ_s + n ρ_w; with k → ∞ it is
/// 2/ω_max of the undamped system, with k → 0 it tends to 2/a (the drag's own limit).
struct TwoPhaseWave {
  double porosity, permeability_m_s;
  double grain_density_kg_m3, fluid_density_kg_m3;
  double constrained_modulus_Pa, fluid_bulk_modulus_Pa;
};
double mieremet_time_step(const TwoPhaseWave& w, double element_length_m);

/// The two simpler bounds Anura3D gives beside Mieremet's step (Scientific Manual 2022 §4.7.3):
/// the undrained wave's L/c_1, c_1 = √((E_c + K_w/n)/ρ_sat), and the drag's 2ρ̃k/(ρ_w g),
/// ρ̃ = ρ_sat + (1/n − 2) ρ_w. The smaller of them names the term that limits the step.
struct TwoPhaseStepBounds {
  double undrained_wave_s = 0.0, drag_s = 0.0;
  bool drag_limited() const { return drag_s < undrained_wave_s; }
};
TwoPhaseStepBounds two_phase_step_bounds(const TwoPhaseWave& w, double element_length_m);

}  // namespace ffp::mpm
