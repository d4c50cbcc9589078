/// The `cpt` scene kind (paper section 6, Fig. 14a): the FFP model's solver
/// with the rigid penetrometer pushed at a prescribed constant velocity, for
/// the quasi-static reaction profile F_0(z).
///
/// Its keys are the ffp kind's (ffp_scene.cpp), with a push speed instead of a
/// mass, an impact velocity, a deformable body or a rigid-body force, and an
/// end_depth_m or end_time_s: `ffp keys cpt`.
/// The paper pushes at v_ref = 2 cm/s. A rate-independent sand's F_0 does not
/// depend on the push speed while inertia is negligible (ρ v² A ≪ F_0), so a
/// scene may push faster to keep the run short; it states the speed it uses
/// (and the ffp tests show F_0 unchanged between two speeds).
/// Writes history.csv (time_s, penetration_m, velocity_m_s, reaction_N, contact_nodes,
/// soil_kinetic_energy_J, dt_s, impulse_N_s, soil_intrusion_m; reaction_N is the mean over the
/// interval since the previous row), plots/reaction_profile.png, fields, and the summary
/// (final_reaction_N, peak_reaction_N, max/final_penetration_m, particles, dt_s, …).
#include "drivers/app/ffp_scene.hpp"
#include "drivers/app/kinds.hpp"

namespace ffp {

std::unique_ptr<Job> make_cpt_job(SceneReader& scene, const std::filesystem::path&) {
  std::string name = read_scene_name(scene, "cpt");
  return make_penetrometer_job(read_ffp_scene(scene, PenetrometerKind::cpt), std::move(name));
}

}  // namespace ffp
