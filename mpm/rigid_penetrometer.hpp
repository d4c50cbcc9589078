#pragma once
/// The rigid penetrometer of the paper's section 4.1: no particles and no
/// constitutive update, only its exact outline, its mass and one vertical
/// velocity. It is coupled to the soil at the grid nodes it covers by the
/// frictional contact law (mpm/contact_law.hpp), or (ContactSurface::particles)
/// through each soil particle's domain against the exact outline
/// (mpm/particle_contact.hpp), and it does not limit the time step.
///
/// Rigid-body force (paper eqs. 1–3). Two variants:
/// - contact_impulse (default): the impulse the soil receives at the contact
///   nodes is exactly the impulse the penetrometer loses. The new velocity v
///   solves the scalar equation
///       M'(v − v_free) + Σ_i m_i (v_s,i(v) − v*_s,i)_z = 0,
///   v_free = v_n + Δt(−g + t/M), M' = M/2π (per radian like the nodal masses),
///   v*_s,i the soil's nodal velocity after its own forces and v_s,i(v) the
///   velocity the contact law gives it against a body moving at v. The left
///   side is strictly increasing in v (its slope is at least M' − μΣm_i/2 > 0),
///   so a bracketed regula falsi finds the root to round-off. The reaction is
///   R = −2π Σ_i m_i (v_s,i − v*_s,i)_z / Δt, and a_rb = (−Mg + t + R)/M is eq. 1
///   with the soil's force measured by the momentum it exchanges.
/// - soil_internal_force: eq. 1 as printed: R = 2π Σ_i f^int_soil,z,i over the
///   contact nodes, a_rb = −g + (R + t)/M, v = v_n + a_rb Δt (eq. 3), then the
///   contact law against v. The soil then does not receive exactly −R·Δt (the
///   inertia of the soil mass at the contact nodes is missed).
/// In both, the velocity is prescribed to every penetrometer node (eq. 2–3) by
/// using it as the contact law's surface velocity, before the soil's particles
/// are updated (Fig. 5).
///
/// Saturated sand (mpm/two_phase.hpp): the body is impermeable. At every contact node the
/// liquid's velocity takes the same law, frictionless (its normal velocity follows the body's
/// while it approaches, its tangential velocity is free, it separates freely), against the
/// same body velocity v. The liquid's nodal equation is the true liquid's divided by n, so the
/// momentum the pores' water exchanges is M̄_w Δv_w (M̄_w = Σ S n ρ_w V): the soil's impulse
/// above becomes Σ_i [m_i (v_s,i(v) − v*_s,i) + M̄_w,i (v_w,i(v) − v*_w,i)]_z, whose slope in v
/// is still bounded, and the body's reaction is the sum of both phases' (the mixture's; the
/// solid's nodal force already holds the excess pore pressure, less the liquid's inertia
/// M̄_w a_w that the liquid's share returns). The hydrostatic part of the water pressure, which
/// the two-phase step balances before it discretises, acts on the body as a whole as its
/// buoyancy ρ_w g V_below(z_wt) (Archimedes), added to the reaction.
///
/// Particle projection (optional, project_particles): after the body has moved,
/// every soil particle inside the exact outline is put back onto it along the
/// outline's normal. Why: the contact acts at nodes, and a particle moves with
/// the blend of corrected and uncorrected nodes in its support, so on a
/// non-conforming cone it creeps into the body a little every step while the
/// soil slides up the flank; the creep accumulates (0.07 / 0.16 / 0.34 / 0.41 cells at
/// 2 / 1 / 0.5 / 0.25 cm on the reference FFP). The
/// projection is purely positional: the particle keeps its velocity, which the
/// grid contact has already corrected (and will again at the next step), so the
/// soil's momentum, the body's impulse and their exact balance are unchanged.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/contact_law.hpp"
#include "mpm/particle_contact.hpp"
#include "mpm/penetrometer_geometry.hpp"
#include "mpm/penetrometer_state.hpp"
#include "mpm/simulation.hpp"

namespace ffp::mpm {

enum class RigidMotion : std::uint8_t {
  free,        ///< driven by gravity, the external load and the soil (FFP)
  prescribed,  ///< constant velocity (CPT-like push, a fixed floor)
};

enum class RigidBodyForce : std::uint8_t { contact_impulse, soil_internal_force };
using RigidBodyForceName = std::pair<RigidBodyForce, std::string_view>;
/// The scene's names of RigidBodyForce, in the order messages list them.
inline constexpr auto kRigidBodyForceNames =
    std::to_array<RigidBodyForceName>({{RigidBodyForce::contact_impulse, "contact_impulse"},
                                       {RigidBodyForce::soil_internal_force, "soil_internal_force"}});
inline std::string to_string(RigidBodyForce f) {
  return std::string(std::ranges::find(kRigidBodyForceNames, f, &RigidBodyForceName::first)->second);
}

/// Where the contact acts: at the nodes taken as the body's (contact_law.hpp), or on each
/// soil particle's domain against the exact outline (particle_contact.hpp).
enum class ContactSurface : std::uint8_t { nodes, particles };
using ContactSurfaceName = std::pair<ContactSurface, std::string_view>;
inline constexpr auto kContactSurfaceNames =
    std::to_array<ContactSurfaceName>({{ContactSurface::nodes, "nodes"}, {ContactSurface::particles, "particles"}});

struct RigidPenetrometerSettings {
  PenetrometerShape shape;
  double mass_kg = 0.0;       ///< whole body (unused for a prescribed motion)
  double tip_z_m = 0.0;       ///< initial tip height
  double velocity_m_s = 0.0;  ///< initial (free) or prescribed vertical velocity, + up
  RigidMotion motion = RigidMotion::free;
  RigidBodyForce force = RigidBodyForce::contact_impulse;
  double external_force_N = 0.0;  ///< t_rb of eq. 1, vertical, + up
  ContactLaw contact;
  ContactSurface surface = ContactSurface::nodes;
  /// Nodes with signed distance ≤ this are penetrometer nodes (0: inside or on the outline).
  double detection_distance_m = 0.0;
  std::uint8_t soil_field = 0;
  /// Put soil particles found inside the outline after a step back onto it (see above).
  bool project_particles = false;
  /// The water the body stands in (saturated sand): its density (0: none, no buoyancy) and the
  /// height of its free surface (the water table).
  double water_density_kg_m3 = 0.0;
  double water_surface_z_m = 0.0;
};

class RigidPenetrometer {
 public:
  explicit RigidPenetrometer(const RigidPenetrometerSettings& settings);
  RigidPenetrometer(const RigidPenetrometer&) = delete;
  RigidPenetrometer& operator=(const RigidPenetrometer&) = delete;

  /// Insert the stages into the simulation's step: apply_rigid_contact after
  /// the grid update and its fixities, apply_rigid_contact_remapped after the
  /// remap of the classic MUSL (musl_remapped moves and strains particles with
  /// the remapped field uncorrected), move_rigid_penetrometer before the time-step update. The stages
  /// keep a pointer to this object: it must outlive the simulation's use.
  void attach(Simulation& simulation);

  /// Lagrangian phase: contact nodes, the rigid velocity, the soil's corrected velocity.
  void apply_contact(Simulation& simulation);
  /// Classic MUSL only: the same law on the soil's remapped velocities, so that its strain
  /// rates see the contact (a second correction: such a step moves particles with one velocity
  /// field and strains them with another).
  void apply_contact_remapped(Simulation& simulation);
  /// x_tip ← x_tip + Δt·v (the particles' update rule).
  void move(Simulation& simulation);
  /// Soil particles inside the outline (at the body's new position) onto it, along its normal.
  void project_particles(Simulation& simulation);

  const PenetrometerState& state() const { return state_; }
  double tip_z_m() const { return tip_z_; }
  const PenetrometerGeometry& geometry() const { return geometry_; }
  const RigidPenetrometerSettings& settings() const { return settings_; }
  /// Penetrometer nodes holding soil mass in the last step, with their normals.
  const std::vector<ContactNode>& nodes() const { return nodes_; }
  /// The water's buoyancy on the body at its current position, ρ_w g V_below (N, + up).
  double buoyancy_N(double gravity_m_s2) const;

 private:
  void find_nodes(const Simulation& simulation);
  /// ContactSurface::particles: the step's exchange on the updated grid velocities.
  void apply_particle_contact(Simulation& simulation);
  /// What the soil receives from the contact law against a body moving at v (per radian):
  /// Σ_i m_i (v_s,i(v) − v*_s,i)_z, its split (on the cone, n_z < 0, with the cone's normal
  /// part (Δp·n) n_z; on the shaft, n_z = 0), and the nodes whose velocity the law changes.
  struct SoilExchange {
    double impulse_z = 0.0, cone = 0.0, cone_normal = 0.0, shaft = 0.0;
    double liquid_z = 0.0;  ///< the pore water's part of impulse_z (saturated sand)
    std::size_t corrected = 0;
  };
  /// The pore water's share of the exchange at contact node c against v into liquid_after_.
  void exchange_with_liquid(const Simulation& simulation, double v, std::size_t c, SoilExchange& out);
  /// The exchange against v into exchange_, and each node's v_s,i(v) into soil_after_;
  /// nothing written to the grid (the residual of the free body's velocity tries many v).
  const SoilExchange& exchange_with_soil(const Simulation& simulation, double v);
  /// The exchange against v made final: v_s,i(v) to the soil's nodes and the body's share
  /// of its split to the state. Returns the soil's z impulse (per radian).
  double correct_soil(Simulation& simulation, double v);
  /// The body's share (−2π × the soil's, per radian) of the soil's z impulse on the cone,
  /// its normal part and on the shaft, added to the state.
  void take_soil_impulse_split(double cone, double cone_normal, double shaft);
  double solve_free_velocity(Simulation& simulation, double v_free);

  RigidPenetrometerSettings settings_;
  PenetrometerGeometry geometry_;
  double tip_z0_, tip_z_;
  PenetrometerState state_;
  std::vector<ContactNode> nodes_;
  std::vector<Vector2> soil_star_;     ///< v*_s at the nodes, before contact
  std::vector<Vector2> soil_after_;    ///< v_s(v) at the nodes, of the last exchange
  std::vector<Vector2> liquid_star_;   ///< saturated sand: v*_w at the nodes, before contact
  std::vector<Vector2> liquid_after_;  ///< v_w(v) of the last exchange
  /// V_below(k·Δ) for k = 0…n: the body's volume up to each height above the tip (buoyancy).
  std::vector<double> volume_below_m3_;
  double volume_step_m_ = 0.0;
  SoilExchange exchange_;             ///< the last exchange
  ParticleContact particle_contact_;  ///< ContactSurface::particles: this step's candidates
};

}  // namespace ffp::mpm
