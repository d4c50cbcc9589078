#pragma once
/// What a penetrometer model (rigid or deformable) reports after each step,
/// and the contact normal it uses at a grid node.
#include <cstddef>

#include "mpm/contact_law.hpp"
#include "mpm/penetrometer_geometry.hpp"

namespace ffp::mpm {

/// Full body (not per radian), SI, z up.
struct PenetrometerState {
  double displacement_m = 0.0;  ///< of the tip (rigid) or of the centre of mass (deformable) since t = 0
  double velocity_m_s = 0.0;    ///< vertical velocity at the end of the last step
  double reaction_N = 0.0;      ///< vertical force of the soil on the penetrometer over the last step
  double impulse_N_s = 0.0;     ///< Σ reaction·Δt over all steps (exact, not sampled)
  /// Rigid body only: the parts of impulse_N_s taken at the cone's nodes (outward normal pointing
  /// down: cone, apex and fillet), of which along the normal (bearing: Σ (Δp·n) n_z), and at
  /// the shaft's (horizontal normal: friction only). impulse − cone − shaft is the top's.
  double cone_impulse_N_s = 0.0;
  double cone_normal_impulse_N_s = 0.0;
  double shaft_impulse_N_s = 0.0;
  /// Saturated sand: the part of impulse_N_s the pore water's contact gave (in the cone's and
  /// the shaft's too), and the water's buoyancy on the body, now and summed (in impulse_N_s,
  /// in neither of the splits: impulse − cone − shaft − buoyancy is the top's).
  double pore_water_impulse_N_s = 0.0;
  double buoyancy_N = 0.0;
  double buoyancy_impulse_N_s = 0.0;
  std::size_t contact_nodes = 0;  ///< nodes where the soil's velocity was corrected in the last step
                                  ///< (contact.surface particles: particles pressed against the outline)
  /// contact.surface particles: the last Gauss–Seidel sweep's largest velocity change (m/s).
  double contact_residual_m_s = 0.0;
  /// Particle projection (rigid, contact.project_particles): soil particles put back onto the
  /// outline in the last step, and how deep the deepest of them was before that.
  std::size_t projected_particles = 0;
  double projection_depth_m = 0.0;
};

/// A node shared by soil and penetrometer, with the outline's outward normal there.
struct ContactNode {
  std::size_t node = 0;
  Vector2 normal;
};

/// The outline's unit outward normal at the point closest to node (r, z). On
/// the axis the azimuthal average of the normals is what a ring of zero radius
/// sees, so only the vertical part survives (the apex of the cone pushes
/// straight down, not along one flank).
inline Vector2 contact_normal(const PenetrometerGeometry& geometry, double r_m, double z_m, double tip_z_m,
                              double* signed_distance_m = nullptr) {
  const SurfaceQuery q = geometry.query(r_m, z_m, tip_z_m);
  if (signed_distance_m != nullptr) *signed_distance_m = q.signed_distance_m;
  if (r_m <= 0.0) return {0.0, q.normal_z >= 0.0 ? 1.0 : -1.0};
  return {q.normal_r, q.normal_z};
}

}  // namespace ffp::mpm
