#pragma once
/// The micropolar (Cosserat) option's state: a nodal micro-rotation field and, per particle,
/// the micro-rotation, its rate, the skew stress and the couple stresses (models/micropolar.hpp
/// for the law, docs/theory.md#micropolar for the equations). A model without a micropolar body
/// has none of it: `active()` is false, no stage of mpm/stage_micropolar.cpp is in its step, and
/// the time step is the classical one.
///
/// One nodal field serves every micropolar body (their micro-rotations meet where they touch).
/// Fixities of ω: zero on the axis (symmetry: a rotation about e_θ is not defined at r = 0) and on
/// a side fixed in both directions (a rough rigid wall turns no grain); free (no couple traction)
/// on free, roller and absorbing sides and at a penetrometer's contact nodes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "models/micropolar.hpp"
#include "mpm/model.hpp"
#include "mpm/stage_list.hpp"

namespace ffp::mpm {

class Simulation;

/// A micropolar material group's constants.
struct MicropolarGroup {
  std::size_t group = 0;                ///< its index in Simulation::groups
  double cosserat_shear_modulus = 0.0;  ///< G_c (Pa)
  double couple_modulus = 0.0;          ///< 2 G ℓ² (N)
  double micro_inertia_m2 = 0.0;        ///< j
  double length_m = 0.0;                ///< ℓ
  /// tan φ' of the law when the micro terms slip at its friction (MicropolarParameters::friction_limited;
  /// SSMC: the residual φ'_r, what flowing grains keep), else 0: elastic.
  double slip_friction = 0.0;

  /// What the micro terms add to M + |σ| in the CFL step's c² = (…)/ρ, on cells of h_min
  /// (docs/theory.md#micropolar-time-step): G_c + (3 G ℓ² + h² G_c)/j.
  double wave_modulus(double h_min_m) const {
    return cosserat_shear_modulus +
           (1.5 * couple_modulus + h_min_m * h_min_m * cosserat_shear_modulus) / micro_inertia_m2;
  }
};

struct MicropolarFields {
  std::vector<MicropolarGroup> groups;
  std::vector<int> group_of_body;  ///< per body: its entry in `groups`, or −1 (classical)

  // Nodes (one field for all micropolar bodies), per radian.
  std::vector<double> rotational_mass;     ///< Θ_i = Σ_p S_ip m_p j_p (kg m²)
  std::vector<double> angular_momentum;    ///< Σ_p S_ip m_p j_p ω̇_p
  std::vector<double> couple_force;        ///< internal couple (N m), damping included
  std::vector<double> spin;                ///< ω̇_i^n (MUSL and musl_remapped: the remapped ω̇_i^{n+1})
  std::vector<double> spin_new;            ///< ω̇_i^{n+1}
  std::vector<std::uint32_t> fixed_nodes;  ///< ω̇_i = 0
  double rotational_mass_floor = 0.0;      ///< nodes lighter than this are empty

  // Particles (every particle has a slot; only those of micropolar bodies change).
  std::vector<double> rotation;        ///< ω_p (rad)
  std::vector<double> rotation_rate;   ///< ω̇_p (rad/s)
  std::vector<double> macro_rotation;  ///< ω_M,p = Σ spin·Δt (rad), for the relative rotation ω_M − ω
  std::vector<double> skew_stress;     ///< s (Pa)
  std::vector<double> couple_r, couple_z, couple_hoop;  ///< m = 2 G ℓ² (κ_r, κ_z, κ_θ) (N/m)

  bool active() const { return !groups.empty(); }
  /// The particle's micropolar group, or nullptr.
  const MicropolarGroup* group_of(std::uint8_t body) const {
    const int k = group_of_body[body];
    return k < 0 ? nullptr : &groups[static_cast<std::size_t>(k)];
  }
};

/// The fields of `model`'s micropolar bodies, for `simulation` once its groups and particles
/// exist (none: inactive). Throws std::invalid_argument on a bad option (ℓ < 0, G_c < 0, j ≤ 0).
MicropolarFields make_micropolar_fields(const ModelDescription& model, const Simulation& simulation);

/// MicropolarGroup::wave_modulus of group `group` on the simulation's smallest cell (0 if classical).
double micropolar_wave_modulus(const Simulation& simulation, std::size_t group);

/// The micropolar stages, inserted into a classical step's list (mpm/stage_micropolar.cpp).
void insert_micropolar_stages(StageList& stages, Transfer transfer);

}  // namespace ffp::mpm
