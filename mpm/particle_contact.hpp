#pragma once
/// Contact of the soil's particles with a rigid body's exact outline, as an
/// alternative to the node-based law of
/// mpm/contact_law.hpp. Why: at nodes the contact surface is the staircase of
/// the nodes taken as the body's, which sits up to a cell off a slanted flank;
/// here each particle's own domain is tested against the exact outline.
///
/// Particle p (centre at signed distance d_p from the outline, closest-point
/// outward normal n_p, GIMP half-lengths l_r, l_z) has the gap
///     g_p = d_p − (l_r |n_r| + l_z |n_z|),
/// the distance from its square domain to the outline along n_p (exact for a flat
/// face). Over the step its velocity relative to the body, u_p = Σ_i S_ip v_i − v_b,
/// may close the gap but not more:
///     u_p·n_p ≥ −g_p/Δt   (g_p ≥ 0),      u_p·n_p ≥ 0   (g_p < 0: no deeper),
/// with a compressive normal impulse J_n ≥ 0 and Coulomb friction |J_t| ≤ μ J_n
/// (rough: no slip while J_n > 0). The impulses J_p = J_n n + J_t t act on the
/// nodes as Δv_i = S_ip J_p / m_i (and on a free body as Δv_b = −J_p,z / M',
/// M' = M/2π per radian like the nodal masses), so momentum is exchanged exactly.
/// Particles share nodes, so the constraints are coupled; they are solved by
/// projected Gauss–Seidel over the particles in index order (deterministic),
/// accumulating each particle's impulses, until no impulse changes the velocity
/// of its particle by more than the tolerance (or 200 sweeps, see the .cpp). The grid's fixities
/// hold: a constrained nodal component takes no impulse (v_r = 0 on the axis under the apex).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/contact_law.hpp"
#include "mpm/penetrometer_geometry.hpp"
#include "mpm/simulation.hpp"

namespace ffp::mpm {

struct ParticleContactOutcome {
  double impulse_z = 0.0;      ///< Σ J_p,z received by the soil (per radian)
  double cone_z = 0.0;         ///< its part on the cone (n_z < 0)
  double cone_normal_z = 0.0;  ///< the cone's normal part (J_n n_z)
  double shaft_z = 0.0;        ///< its part on the shaft (n_z = 0)
  double body_velocity = 0.0;  ///< the body's vertical velocity after the exchange
  std::size_t active = 0;      ///< particles with J_n > 0
  int sweeps = 0;              ///< Gauss–Seidel sweeps taken
  double residual_m_s = 0.0;   ///< the largest velocity change of the last sweep
};

class ParticleContact {
 public:
  /// The soil particles (of nodal field `soil_field`) whose gap is below `band_m`, with
  /// their normals and gaps against the outline with its tip at `tip_z_m`.
  void collect(const Simulation& s, const PenetrometerGeometry& geometry, double tip_z_m, std::uint8_t soil_field,
               double band_m);
  /// Enforce the constraints on the nodal velocities (vr, vz) of the soil's field.
  /// `body_inverse_mass` is 2π/M for a free body (its velocity moves with the
  /// impulses), 0 for a prescribed one.
  /// `warm_start`: begin from each particle's impulses of the last warm-started solve (scaled by
  /// the ratio of the steps), and keep this solve's for the next one. Contact impulses change
  /// little from step to step, so most of the sweeps are saved; the answer is the same to the
  /// tolerance.
  ParticleContactOutcome solve(const Simulation& s, std::uint8_t soil_field, double* vr, double* vz,
                               double body_velocity, double body_inverse_mass, const ContactLaw& law, bool warm_start);
  std::size_t candidates() const { return candidates_.size(); }

 private:
  struct Candidate {
    std::size_t particle;
    double nr, nz;  ///< outward normal of the outline at the closest point
    double gap_m;
  };
  std::vector<Candidate> candidates_;
  /// A candidate's support: its nodes, S_ip and S_ip/m_i per free component, and Σ S_ip²/m_i
  /// over the nodes free in r and in z (its inverse mass in each direction).
  struct Support {
    std::size_t node[9];
    double weight[9], weight_over_mass_r[9], weight_over_mass_z[9];
    int count = 0;
    double inverse_mass_r = 0.0, inverse_mass_z = 0.0;
  };
  std::vector<Support> supports_;                         ///< per candidate, this solve
  std::vector<double> normal_impulse_, tangent_impulse_;  ///< per candidate, this solve
  /// One solve's velocities: the soil's nodal ones (written) and the body's.
  struct Exchange {
    double* vr;
    double* vz;
    double v_body;
    double body_inverse_mass;
    const ContactLaw& law;
    double dt;
  };
  void build_supports(const Simulation& s, const NodalField& soil);
  static void apply(Exchange& exchange, const Support& support, double jr, double jz);
  void start_from_last_impulses(Exchange& exchange, std::size_t particles);
  double update(Exchange& exchange, std::size_t candidate);
  void sweep(Exchange& exchange, ParticleContactOutcome& out, double tolerance);
  void keep_impulses(double dt);
  void tally(ParticleContactOutcome& out) const;
  /// Last warm-started solve's impulses per particle (normal, tangent) and its step.
  std::vector<double> last_normal_, last_tangent_;
  std::vector<std::size_t> last_particles_;  ///< the particles whose last_* entries are set
  std::vector<std::uint8_t> fixed_;          ///< the grid's ConstraintBits per node
  double last_dt_s_ = 0.0;
};

}  // namespace ffp::mpm
