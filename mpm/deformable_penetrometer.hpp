#pragma once
/// The deformable alternative of the paper's section 5.1 (Fig. 7): the
/// penetrometer is a body of particles (linear elastic) with its own nodal
/// velocity field, in contact with the soil's field by the two-body form of
/// Bardenhagen et al. (2000): at nodes where both fields have mass and that lie
/// inside the outline or within the detection distance of it (the rigid body's
/// rule, so that both models meet the soil on the same surface),
///   v_cm = (m_s v*_s + m_f v*_f)/(m_s + m_f),
///   v_s  = contact law of v*_s against a surface moving at v_cm,
///   v_f  = v*_f − (m_s/m_f)(v_s − v*_s)     (momentum is conserved node by node).
/// The normal is the exact outline's, placed at the body's centre-of-mass
/// displacement (the outline moves with the body; its elastic deformation is
/// small). Its p-wave speed enters the time step like any material's, unless
/// the body is subcycled (settings.subcycle, mpm/body_subcycle.hpp): then the
/// step is the soil's, the body's velocity for contact is its particles' mapped
/// velocity plus gravity, and the body takes the soil's corrections at the
/// shared nodes, −m_s(v_s − v*_s), as impulses over its own substeps.
#include <cstdint>
#include <memory>
#include <vector>

#include "mpm/body_subcycle.hpp"
#include "mpm/contact_law.hpp"
#include "mpm/penetrometer_geometry.hpp"
#include "mpm/penetrometer_state.hpp"
#include "mpm/simulation.hpp"

namespace ffp::mpm {

struct DeformablePenetrometerSettings {
  PenetrometerShape shape;
  double tip_z_m = 0.0;  ///< initial tip height
  std::size_t body = 1;  ///< the penetrometer's body in the simulation
  std::uint8_t soil_field = 0, penetrometer_field = 1;
  ContactLaw contact;
  /// Shared nodes with signed distance ≤ this take part (0: inside or on the
  /// outline; a few cells: every node both bodies' supports reach, the classical rule).
  double detection_distance_m = 0.0;
  /// The body takes its own substeps inside the soil's step (it must be the last body).
  bool subcycle = false;
};

class DeformablePenetrometer {
 public:
  /// Reads the body's initial centre of mass and velocity from the simulation.
  DeformablePenetrometer(const Simulation& simulation, const DeformablePenetrometerSettings& settings);
  DeformablePenetrometer(const DeformablePenetrometer&) = delete;
  DeformablePenetrometer& operator=(const DeformablePenetrometer&) = delete;

  /// Insert apply_two_body_contact (after the grid update and fixities),
  /// apply_two_body_contact_remapped (classic MUSL) and follow_deformable_penetrometer
  /// (centre of mass, before the time-step update); subcycled, also
  /// predict_penetrometer_velocity (before the contact) and subcycle_penetrometer
  /// (before follow_deformable_penetrometer). Keeps a pointer to this.
  void attach(Simulation& simulation);

  void apply_contact(Simulation& simulation);
  void apply_contact_remapped(Simulation& simulation);
  /// Centre-of-mass displacement and velocity of the body's particles.
  void follow(const Simulation& simulation);

  const PenetrometerState& state() const { return state_; }
  /// Where the outline's tip is taken to be: initial tip + centre-of-mass displacement.
  double tip_z_m() const { return tip_z0_ + state_.displacement_m; }
  const PenetrometerGeometry& geometry() const { return geometry_; }
  double mass_kg() const { return mass_kg_; }
  /// The substeps of the subcycled body (nullptr when it steps with the soil).
  const BodySubcycle* subcycle() const { return subcycle_.get(); }

 private:
  /// Corrects both fields' velocities (the arrays `vr`, `vz`) at shared nodes;
  /// returns Σ m_s (v_s − v*_s)_z per radian, counts corrected nodes and, given
  /// `impulses`, lists the body's share −m_s (v_s − v*_s) node by node.
  double correct(Simulation& simulation, std::vector<double> NodalField::*vr, std::vector<double> NodalField::*vz,
                 std::size_t* corrected, std::vector<NodalImpulse>* impulses);

  DeformablePenetrometerSettings settings_;
  PenetrometerGeometry geometry_;
  double tip_z0_;
  double mass_kg_ = 0.0, z_cm0_ = 0.0;
  PenetrometerState state_;
  std::vector<ContactNode> nodes_;
  std::unique_ptr<BodySubcycle> subcycle_;
  std::vector<NodalImpulse> impulses_;  ///< of the last contact, for the substeps
};

}  // namespace ffp::mpm
