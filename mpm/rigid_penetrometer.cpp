#include "mpm/rigid_penetrometer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/bracketed_root.hpp"
#include "models/math_constants.hpp"
#include "mpm/diagnostics.hpp"

namespace ffp::mpm {

RigidPenetrometer::RigidPenetrometer(const RigidPenetrometerSettings& settings)
    : settings_(settings), geometry_(settings.shape), tip_z0_(settings.tip_z_m), tip_z_(settings.tip_z_m) {
  if (settings.motion == RigidMotion::free && !(settings.mass_kg > 0.0))
    throw std::invalid_argument("a free rigid penetrometer needs a mass > 0");
  if (!(settings.detection_distance_m >= 0.0)) throw std::invalid_argument("detection distance must be ≥ 0");
  if (settings.surface == ContactSurface::particles && settings.motion == RigidMotion::free &&
      settings.force != RigidBodyForce::contact_impulse)
    throw std::invalid_argument("the particles' contact surface exchanges impulses: it needs contact_impulse");
  state_.velocity_m_s = settings.velocity_m_s;
  if (settings.water_density_kg_m3 > 0.0) {
    // V_below(h) = ∫_0^h π r(y)² dy by the midpoint rule on 2000 slices: within 1e-6 of the
    // whole volume (PenetrometerShape::volume_m3 takes 20 000), linear between the slices.
    const int n = 2000;
    volume_step_m_ = settings.shape.total_length_m() / n;
    volume_below_m3_.assign(n + 1, 0.0);
    for (int k = 0; k < n; ++k) {
      const double r = geometry_.radius_at((k + 0.5) * volume_step_m_);
      volume_below_m3_[k + 1] = volume_below_m3_[k] + kPi * r * r * volume_step_m_;
    }
  }
}

double RigidPenetrometer::buoyancy_N(double gravity_m_s2) const {
  if (volume_below_m3_.empty()) return 0.0;
  // Archimedes: the hydrostatic water pressure ρ_w g (z_wt − z) over the whole outline.
  const double height = std::clamp((settings_.water_surface_z_m - tip_z_) / volume_step_m_, 0.0,
                                   static_cast<double>(volume_below_m3_.size() - 1));
  const auto k = std::min(static_cast<std::size_t>(height), volume_below_m3_.size() - 2);
  const double t = height - static_cast<double>(k);
  const double volume = (1.0 - t) * volume_below_m3_[k] + t * volume_below_m3_[k + 1];
  return settings_.water_density_kg_m3 * gravity_m_s2 * volume;
}

void RigidPenetrometer::attach(Simulation& s) {
  if (s.two_phase && settings_.surface == ContactSurface::particles)
    throw std::invalid_argument("a saturated sand takes the contact on the nodes (the pore water's is nodal)");
  // After the fixities, so that the contact law sees v_r = 0 on the axis (and keeps it).
  s.stages.insert_before("update_particles", {"apply_rigid_contact", [this](Simulation& sim) { apply_contact(sim); }});
  // The classic MUSL strains from a remapped field: correct it too (with the particles' surface also
  // musl_remapped, which moves particles with it).
  if (s.settings.transfer == Transfer::musl ||
      (settings_.surface == ContactSurface::particles && s.settings.transfer == Transfer::musl_remapped))
    s.stages.insert_before("compute_strain_increments",
                           {"apply_rigid_contact_remapped", [this](Simulation& sim) { apply_contact_remapped(sim); }});
  const char* last = s.stages.contains("update_time_step") ? "update_time_step" : "check_time_step";
  s.stages.insert_before(last, {"move_rigid_penetrometer", [this](Simulation& sim) { move(sim); }});
  // After the body's move: particles (moved in update_particles or move_particles) and the
  // outline are then both at t + Δt.
  if (settings_.project_particles)
    s.stages.insert_after("move_rigid_penetrometer",
                          {"project_soil_particles", [this](Simulation& sim) { project_particles(sim); }});
}

void RigidPenetrometer::find_nodes(const Simulation& s) {
  nodes_.clear();
  soil_star_.clear();
  const NodalField& f = s.grid.fields[settings_.soil_field];
  const double reach =
      settings_.detection_distance_m + 1e-9 * s.grid.min_spacing();  // nodes exactly on the outline count
  const double r_max = settings_.shape.base_radius_m + reach;
  const double z_lo = tip_z_ - reach, z_hi = tip_z_ + settings_.shape.total_length_m() + reach;
  for (int i = 0; i < s.grid.r.nodes(); ++i) {
    const double r = s.grid.r.coordinate(i);
    if (r > r_max) break;
    for (int j = 0; j < s.grid.z.nodes(); ++j) {
      const double z = s.grid.z.coordinate(j);
      if (z < z_lo || z > z_hi) continue;
      const std::size_t k = s.grid.node(i, j);
      if (!(f.mass[k] > s.mass_floor_kg)) continue;
      double distance = 0.0;
      const Vector2 n = contact_normal(geometry_, r, z, tip_z_, &distance);
      if (distance > reach) continue;
      nodes_.push_back({k, n});
      soil_star_.push_back({f.velocity_new_r[k], f.velocity_new_z[k]});
    }
  }
  liquid_star_.clear();
  if (!s.two_phase) return;
  const NodalField& w = s.two_phase->liquid;
  for (const ContactNode& c : nodes_) liquid_star_.push_back({w.velocity_new_r[c.node], w.velocity_new_z[c.node]});
}

void RigidPenetrometer::exchange_with_liquid(const Simulation& s, double v, std::size_t c, SoilExchange& out) {
  const TwoPhase& t = *s.two_phase;
  const std::size_t k = nodes_[c].node;
  const Vector2 n = nodes_[c].normal, before = liquid_star_[c];
  if (!(t.liquid.mass[k] > s.mass_floor_kg)) {
    liquid_after_[c] = before;
    return;
  }
  // Impermeable and frictionless: the normal part of the solid's law, with its cap.
  const ContactLaw impermeable{0.0, false, settings_.contact.velocity_scaling};
  const Vector2 after = contact_velocity(before, {0.0, v}, n, impermeable, s.dt_s / s.grid.min_spacing());
  liquid_after_[c] = after;
  const double m = t.porous_mass[k];  // the pores' water: M̄_w = Σ S n ρ_w V
  const double dp_z = m * (after.z - before.z);
  out.impulse_z += dp_z;
  out.liquid_z += dp_z;
  if (n.z < 0.0) {
    out.cone += dp_z;
    out.cone_normal += m * ((after.r - before.r) * n.r + (after.z - before.z) * n.z) * n.z;
  } else if (n.z == 0.0) {
    out.shaft += dp_z;
  }
}

const RigidPenetrometer::SoilExchange& RigidPenetrometer::exchange_with_soil(const Simulation& s, double v) {
  const NodalField& f = s.grid.fields[settings_.soil_field];
  const double dt_over_h = s.dt_s / s.grid.min_spacing();
  SoilExchange out;
  soil_after_.resize(nodes_.size());
  for (std::size_t c = 0; c < nodes_.size(); ++c) {
    const std::size_t k = nodes_[c].node;
    const Vector2 n = nodes_[c].normal;
    const Vector2 before = soil_star_[c];
    const Vector2 after = contact_velocity(before, {0.0, v}, n, settings_.contact, dt_over_h);
    soil_after_[c] = after;
    const double dp_z = f.mass[k] * (after.z - before.z);
    out.impulse_z += dp_z;
    if (after.r != before.r || after.z != before.z) ++out.corrected;
    // The split of the same impulse: cone (n_z < 0) or shaft (n_z = 0), and the
    // cone's normal part (Δp·n) n_z, the rest of its z impulse being friction.
    if (n.z < 0.0) {
      out.cone += dp_z;
      out.cone_normal += f.mass[k] * ((after.r - before.r) * n.r + (after.z - before.z) * n.z) * n.z;
    } else if (n.z == 0.0) {
      out.shaft += dp_z;
    }
  }
  liquid_after_.resize(liquid_star_.size());
  for (std::size_t c = 0; c < liquid_star_.size(); ++c) exchange_with_liquid(s, v, c, out);
  exchange_ = out;
  return exchange_;
}

double RigidPenetrometer::correct_soil(Simulation& s, double v) {
  exchange_with_soil(s, v);
  NodalField& f = s.grid.fields[settings_.soil_field];
  for (std::size_t c = 0; c < nodes_.size(); ++c) {
    f.velocity_new_r[nodes_[c].node] = soil_after_[c].r;
    f.velocity_new_z[nodes_[c].node] = soil_after_[c].z;
  }
  if (s.two_phase) {
    NodalField& w = s.two_phase->liquid;
    for (std::size_t c = 0; c < liquid_after_.size(); ++c) {
      w.velocity_new_r[nodes_[c].node] = liquid_after_[c].r;
      w.velocity_new_z[nodes_[c].node] = liquid_after_[c].z;
    }
  }
  take_soil_impulse_split(exchange_.cone, exchange_.cone_normal, exchange_.shaft);
  state_.pore_water_impulse_N_s -= kTwoPi * exchange_.liquid_z;
  return exchange_.impulse_z;
}

void RigidPenetrometer::take_soil_impulse_split(double cone, double cone_normal, double shaft) {
  state_.cone_impulse_N_s -= kTwoPi * cone;
  state_.cone_normal_impulse_N_s -= kTwoPi * cone_normal;
  state_.shaft_impulse_N_s -= kTwoPi * shaft;
}

double RigidPenetrometer::solve_free_velocity(Simulation& s, double v_free) {
  const double M = settings_.mass_kg / kTwoPi;  // per radian, as the nodal masses
  auto residual = [&](double v) { return M * (v - v_free) + exchange_with_soil(s, v).impulse_z; };
  double f_free = residual(v_free);
  if (f_free == 0.0) return v_free;
  // Bracket: the root is within |F(v_free)|/M' of v_free unless the soil's
  // share of the slope is large; widen until the sign changes.
  double lo = v_free, hi = v_free, f_lo = f_free, f_hi = f_free;
  double step = 2.0 * std::abs(f_free) / M + 1e-12 * (1.0 + std::abs(v_free));
  for (int k = 0; k < 200 && (f_lo > 0.0) == (f_hi > 0.0); ++k, step *= 2.0) {
    if (f_free < 0.0) {
      lo = hi;
      f_lo = f_hi;
      hi = v_free + step;
      f_hi = residual(hi);
    } else {
      hi = lo;
      f_hi = f_lo;
      lo = v_free - step;
      f_lo = residual(lo);
    }
  }
  if ((f_lo > 0.0) == (f_hi > 0.0))
    throw StepFailure("rigid penetrometer: no bracket for the contact velocity at t = " + std::to_string(s.time_s) +
                      " s");
  // Exact on each linear piece of the residual, and never leaves the bracket.
  const auto width = [](double v) { return 1e-15 * (1.0 + std::abs(v)); };
  return illinois_root(residual, hi, f_hi, lo, f_lo, 0.0, width, 200).x;
}

void RigidPenetrometer::apply_particle_contact(Simulation& s) {
  // Candidates within a cell of the outline: a particle closes at most its gap per step, and no
  // particle moves a cell in one step (CFL).
  particle_contact_.collect(s, geometry_, tip_z_, settings_.soil_field, s.grid.min_spacing());
  NodalField& f = s.grid.fields[settings_.soil_field];
  const double dt = s.dt_s;
  const double M = settings_.mass_kg;
  double v_start = settings_.velocity_m_s, inverse_mass = 0.0;
  if (settings_.motion == RigidMotion::free) {
    const double g = s.gravity_m_s2.value_or(0.0);
    v_start = state_.velocity_m_s + dt * (-g + settings_.external_force_N / M);
    inverse_mass = kTwoPi / M;
  }
  const ParticleContactOutcome out =
      particle_contact_.solve(s, settings_.soil_field, f.velocity_new_r.data(), f.velocity_new_z.data(), v_start,
                              inverse_mass, settings_.contact, true);
  const double reaction = -kTwoPi * out.impulse_z / dt;
  // The body takes exactly the soil's impulse (out.body_velocity equals this to round-off).
  state_.velocity_m_s = settings_.motion == RigidMotion::free ? v_start + dt * reaction / M : v_start;
  state_.reaction_N = reaction;
  state_.impulse_N_s += reaction * dt;
  state_.contact_nodes = out.active;
  state_.contact_residual_m_s = out.residual_m_s;
  take_soil_impulse_split(out.cone_z, out.cone_normal_z, out.shaft_z);
}

void RigidPenetrometer::apply_contact(Simulation& s) {
  if (settings_.surface == ContactSurface::particles) {
    apply_particle_contact(s);
    return;
  }
  find_nodes(s);
  const double dt = s.dt_s;
  const double g = s.gravity_m_s2.value_or(0.0);
  const double v0 = state_.velocity_m_s;
  const double M = settings_.mass_kg;
  // The water's buoyancy (saturated sand; 0 otherwise) at the step's start, beside t of eq. 1.
  const double buoyancy = buoyancy_N(g);
  double v = v0;
  double reaction = 0.0;
  if (settings_.motion == RigidMotion::prescribed) {
    v = settings_.velocity_m_s;
    reaction = -kTwoPi * correct_soil(s, v) / dt;
  } else if (settings_.force == RigidBodyForce::contact_impulse) {
    const double v_free = v0 + dt * (-g + (settings_.external_force_N + buoyancy) / M);
    v = solve_free_velocity(s, v_free);
    reaction = -kTwoPi * correct_soil(s, v) / dt;  // per radian, exactly what the soil received
    v = v_free + dt * reaction / M;  // the same impulse taken from the body (v equals the root to round-off)
  } else {
    // Eq. 1 verbatim: f_soil^i is the soil's nodal internal force at the contact nodes.
    const NodalField& f = s.grid.fields[settings_.soil_field];
    double sum = 0.0;
    for (const ContactNode& c : nodes_) sum += f.internal_force_z[c.node];
    reaction = kTwoPi * sum;
    v = v0 + dt * (-g + (reaction + settings_.external_force_N + buoyancy) / M);  // eqs. 1 and 3
    correct_soil(s, v);
  }
  state_.velocity_m_s = v;
  state_.reaction_N = reaction;
  state_.impulse_N_s += reaction * dt;
  // The buoyancy is part of what the surroundings exert: in the reaction, as an accelerometer reads
  // it. Added apart and only where there is water: a dry run's impulse then rounds as it always did
  // (reaction · Δt shared with the body's update, not fused into the sum).
  if (buoyancy != 0.0) {
    state_.reaction_N += buoyancy;
    state_.impulse_N_s += buoyancy * dt;
  }
  state_.buoyancy_N = buoyancy;
  state_.buoyancy_impulse_N_s += buoyancy * dt;
  state_.contact_nodes = exchange_.corrected;
}

void RigidPenetrometer::apply_contact_remapped(Simulation& s) {
  NodalField& f = s.grid.fields[settings_.soil_field];
  if (settings_.surface == ContactSurface::particles) {  // the same constraints, the body's velocity given
    particle_contact_.solve(s, settings_.soil_field, f.velocity_r.data(), f.velocity_z.data(), state_.velocity_m_s, 0.0,
                            settings_.contact, false);
    return;
  }
  const Vector2 body{0.0, state_.velocity_m_s};
  const double dt_over_h = s.dt_s / s.grid.min_spacing();
  for (const ContactNode& c : nodes_) {
    const Vector2 after =
        contact_velocity({f.velocity_r[c.node], f.velocity_z[c.node]}, body, c.normal, settings_.contact, dt_over_h);
    f.velocity_r[c.node] = after.r;
    f.velocity_z[c.node] = after.z;
  }
  if (!s.two_phase) return;
  // The pore water's remapped velocities too (its strain rate reads them), impermeable and frictionless.
  NodalField& w = s.two_phase->liquid;
  const ContactLaw impermeable{0.0, false, settings_.contact.velocity_scaling};
  for (const ContactNode& c : nodes_) {
    if (!(w.mass[c.node] > s.mass_floor_kg)) continue;
    const Vector2 after =
        contact_velocity({w.velocity_r[c.node], w.velocity_z[c.node]}, body, c.normal, impermeable, dt_over_h);
    w.velocity_r[c.node] = after.r;
    w.velocity_z[c.node] = after.z;
  }
}

void RigidPenetrometer::move(Simulation& s) {
  tip_z_ += s.dt_s * state_.velocity_m_s;
  state_.displacement_m = tip_z_ - tip_z0_;
  s.rigid_speed_m_s = std::abs(state_.velocity_m_s);
}

void RigidPenetrometer::project_particles(Simulation& s) {
  // x ← x + |d|·n for a particle at signed distance d < 0: the closest point of the
  // outline (n is the outward normal there; inside the body the closest point is on
  // the flank, the fillet, the shaft or the top, never the apex, so n is well defined).
  // Positions only: see the header for why the velocity is left alone.
  Particles& P = s.particles;
  const double R = settings_.shape.base_radius_m, tip = tip_z_, top = tip_z_ + settings_.shape.total_length_m();
  std::size_t projected = 0;
  double deepest = 0.0;
  for (const Body& body : s.bodies) {
    if (body.field != settings_.soil_field) continue;
    for (std::size_t p = body.begin; p < body.end; ++p) {
      const double r = P.r[p], z = P.z[p];
      if (r >= R || z <= tip || z >= top) continue;  // outside the outline's bounding box (as soil_intrusion_m)
      if (!geometry_.inside(r, z, tip)) continue;    // a signed distance ≥ 0: not projected
      const SurfaceQuery q = geometry_.query(r, z, tip);
      if (!(q.signed_distance_m < 0.0)) continue;
      const double depth = -q.signed_distance_m;
      P.r[p] = r + depth * q.normal_r;
      P.z[p] = z + depth * q.normal_z;
      deepest = std::max(deepest, depth);
      ++projected;
    }
  }
  state_.projected_particles = projected;
  state_.projection_depth_m = deepest;
}

}  // namespace ffp::mpm
