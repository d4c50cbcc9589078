#include "mpm/deformable_penetrometer.hpp"

#include "mpm/diagnostics.hpp"

namespace ffp::mpm {

DeformablePenetrometer::DeformablePenetrometer(const Simulation& s, const DeformablePenetrometerSettings& settings)
    : settings_(settings), geometry_(settings.shape), tip_z0_(settings.tip_z_m) {
  if (settings.body >= s.bodies.size()) throw std::invalid_argument("deformable penetrometer: no such body");
  if (settings.soil_field == settings.penetrometer_field)
    throw std::invalid_argument("deformable penetrometer: soil and penetrometer need separate nodal fields");
  const Diagnostics d = measure_body(s, settings.body);
  mass_kg_ = d.mass_kg;
  z_cm0_ = d.mass_z_kg_m / d.mass_kg;
  state_.velocity_m_s = d.momentum_z_N_s / d.mass_kg;
}

void DeformablePenetrometer::attach(Simulation& s) {
  s.stages.insert_before("update_particles",
                         {"apply_two_body_contact", [this](Simulation& sim) { apply_contact(sim); }});
  if (settings_.subcycle) {
    subcycle_ = std::make_unique<BodySubcycle>(s, settings_.body);
    s.stages.insert_before("apply_two_body_contact", {"predict_penetrometer_velocity", [this](Simulation& sim) {
                                                        subcycle_->predict_contact_velocity(sim);
                                                      }});
  }
  if (s.settings.transfer == Transfer::musl)  // the classic MUSL strains from a remapped field: correct it too
    s.stages.insert_before("compute_strain_increments", {"apply_two_body_contact_remapped",
                                                         [this](Simulation& sim) { apply_contact_remapped(sim); }});
  const char* last = s.stages.contains("update_time_step") ? "update_time_step" : "check_time_step";
  s.stages.insert_before(last, {"follow_deformable_penetrometer", [this](Simulation& sim) { follow(sim); }});
  if (subcycle_)
    s.stages.insert_before("follow_deformable_penetrometer",
                           {"subcycle_penetrometer", [this](Simulation& sim) { subcycle_->advance(sim, impulses_); }});
}

double DeformablePenetrometer::correct(Simulation& s, std::vector<double> NodalField::*vr,
                                       std::vector<double> NodalField::*vz, std::size_t* corrected,
                                       std::vector<NodalImpulse>* impulses) {
  NodalField& soil = s.grid.fields[settings_.soil_field];
  NodalField& body = s.grid.fields[settings_.penetrometer_field];
  std::vector<double>&svr = soil.*vr, &svz = soil.*vz, &bvr = body.*vr, &bvz = body.*vz;
  double impulse = 0.0;
  std::size_t count = 0;
  // Subcycled, the body's inertia in the contact is that of the mass its p-wave reaches
  // within the step (BodySubcycle::contact_mass_factor), and its field's velocities are its
  // substeps' start (p_i/m_i): only its share of the step's contact (`impulses`) may change
  // them, so the classic MUSL's second correction (of the remapped field, for the soil's
  // strains) leaves the body alone (before: it changed the body's momentum by ~1e-3 of
  // the contact impulse per step, unaccounted).
  const double factor = subcycle_ ? subcycle_->contact_mass_factor() : 1.0;
  const bool write_body = !subcycle_ || impulses != nullptr;
  for (const ContactNode& c : nodes_) {
    const std::size_t k = c.node;
    const double ms = soil.mass[k], mf = body.mass[k], mc = factor * mf;
    const Vector2 vs{svr[k], svz[k]}, vf{bvr[k], bvz[k]};
    const Vector2 cm{(ms * vs.r + mc * vf.r) / (ms + mc), (ms * vs.z + mc * vf.z) / (ms + mc)};
    const Vector2 after = contact_velocity(vs, cm, c.normal, settings_.contact, s.dt_s / s.grid.min_spacing());
    const double dr = after.r - vs.r, dz = after.z - vs.z;
    if (dr == 0.0 && dz == 0.0) continue;
    ++count;
    svr[k] = after.r;
    svz[k] = after.z;
    if (write_body) {
      bvr[k] = vf.r - ms / mf * dr;
      bvz[k] = vf.z - ms / mf * dz;
    }
    impulse += ms * dz;
    if (impulses != nullptr) impulses->push_back({k, -ms * dr, -ms * dz});
  }
  if (corrected != nullptr) *corrected = count;
  return impulse;
}

void DeformablePenetrometer::apply_contact(Simulation& s) {
  nodes_.clear();
  const NodalField& soil = s.grid.fields[settings_.soil_field];
  const NodalField& body = s.grid.fields[settings_.penetrometer_field];
  const double floor = s.mass_floor_kg;
  const double tip = tip_z_m();
  const double reach = settings_.detection_distance_m + 1e-9 * s.grid.min_spacing();  // nodes on the outline count
  for (int j = 0; j < s.grid.z.nodes(); ++j) {
    for (int i = 0; i < s.grid.r.nodes(); ++i) {
      const std::size_t k = s.grid.node(i, j);
      if (!(soil.mass[k] > floor && body.mass[k] > floor)) continue;
      double distance = 0.0;
      const Vector2 n = contact_normal(geometry_, s.grid.r.coordinate(i), s.grid.z.coordinate(j), tip, &distance);
      if (distance <= reach) nodes_.push_back({k, n});
    }
  }
  std::size_t corrected = 0;
  impulses_.clear();
  const double impulse = correct(s, &NodalField::velocity_new_r, &NodalField::velocity_new_z, &corrected,
                                 subcycle_ ? &impulses_ : nullptr);
  state_.reaction_N = -kTwoPi * impulse / s.dt_s;
  state_.impulse_N_s += state_.reaction_N * s.dt_s;
  state_.contact_nodes = corrected;
}

void DeformablePenetrometer::apply_contact_remapped(Simulation& s) {
  correct(s, &NodalField::velocity_r, &NodalField::velocity_z, nullptr, nullptr);
}

void DeformablePenetrometer::follow(const Simulation& s) {
  const Diagnostics d = measure_body(s, settings_.body);
  state_.displacement_m = d.mass_z_kg_m / d.mass_kg - z_cm0_;
  state_.velocity_m_s = d.momentum_z_N_s / d.mass_kg;
}

}  // namespace ffp::mpm
