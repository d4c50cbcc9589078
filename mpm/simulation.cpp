#include "mpm/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mpm/generate_particles.hpp"
#include "mpm/stages.hpp"

namespace ffp::mpm {

Simulation::Simulation(const ModelDescription& model)
    : settings(model.solver), gravity_m_s2(model.gravity_m_s2), pressures(model.pressures) {
  grid.r = GridAxis(model.r_nodes_m);
  grid.z = GridAxis(model.z_nodes_m);
  if (grid.r.front() < 0.0) throw std::invalid_argument("radial node coordinates must be ≥ 0 (axisymmetry)");
  if (model.bodies.empty()) throw std::invalid_argument("a simulation needs at least one body");
  if (model.bodies.size() > 255) throw std::invalid_argument("at most 255 bodies");
  if (!(settings.courant > 0.0 && settings.courant <= 1.0)) throw std::invalid_argument("courant must be in (0, 1]");
  if (!(settings.flip_fraction >= 0.0 && settings.flip_fraction <= 1.0))
    throw std::invalid_argument("flip_fraction must be in [0, 1]");
  grid.fields.resize(1);  // single velocity field; contact adds one per body
  grid.fields[0].resize(grid.nodes());
  grid.constraints = constrained_nodes(model.boundaries, grid.r.nodes(), grid.z.nodes(), grid.has_axis());
  {
    // The axis is a wall at a hair's breadth off r = 0 (1/r_p must stay finite).
    const double inf = std::numeric_limits<double>::infinity();
    const BoundaryConditions& b = model.boundaries;
    walls.r_min = grid.has_axis() ? 1e-6 * grid.r.spacing(0) : (b.inner == Fixity::free ? -inf : grid.r.front());
    walls.r_max = b.outer == Fixity::free ? inf : grid.r.back();
    walls.z_min = b.bottom == Fixity::free ? -inf : grid.z.front();
    walls.z_max = b.top == Fixity::free ? inf : grid.z.back();
  }

  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const BodyDescription& d = model.bodies[b];
    if (d.initial_stress && !gravity_m_s2)
      throw std::invalid_argument("body " + d.name + ": a K0 initial stress needs gravity");
    const std::size_t begin = particles.size();
    append_body_particles(grid, d, static_cast<std::uint8_t>(b),
                          geostatic_unit_weight(d, model.fluid, gravity_m_s2.value_or(0.0)), particles,
                          model.seeding_zones);
    if (particles.size() == begin) throw std::invalid_argument("body " + d.name + " has no particle inside the grid");
    groups.emplace_back(d.name, d.law, d.density_kg_m3);
    if (!(d.disconnected_below_kg_m3 >= 0.0 && d.disconnected_below_kg_m3 < d.density_kg_m3))
      throw std::invalid_argument("body " + d.name + ": the disconnection density must be ≥ 0 and below the density");
    groups.back().disconnected_below_kg_m3 = d.disconnected_below_kg_m3;
    groups.back().begin = begin;
    groups.back().end = particles.size();
    groups.back().states = initial_states(d.law, groups.back().size());
    bodies.push_back({d.name, b, 0, begin, particles.size()});
  }

  if (std::ranges::any_of(
          std::array{model.boundaries.inner, model.boundaries.outer, model.boundaries.bottom, model.boundaries.top},
          [](Fixity f) { return f == Fixity::absorbing; })) {
    absorbing = absorbing_nodes(model.boundaries, grid.r.nodes(), grid.z.nodes(), model.absorbing_bottom_row);
    if (model.absorbing_bottom_row > 0)  // the margin's edge below the sand's base: fixed
      for (int i = 0; i < grid.r.nodes(); ++i)
        grid.constraints.push_back({static_cast<std::uint32_t>(i), constrain_r | constrain_z});
    const BodyDescription& first = model.bodies.front();
    const ElasticConstants& e = elastic_constants(first.law);
    beyond = {first.density_kg_m3, e.p_wave_speed(first.density_kg_m3),
              std::sqrt(e.shear_modulus() / first.density_kg_m3)};
    if (model.wave_source_m) {
      beyond.has_source = true;
      beyond.source_r_m = model.wave_source_m->first;
      beyond.source_z_m = model.wave_source_m->second;
    }
  }

  if (std::ranges::any_of(model.bodies, [](const BodyDescription& d) { return d.saturated.has_value(); }))
    two_phase = make_two_phase(model, grid, particles);

  const double lightest = *std::min_element(particles.mass.begin(), particles.mass.end());
  // Far below any real nodal mass, far above round-off: only truly empty nodes.
  mass_floor_kg = 1e-12 * lightest;
  bins.configure(grid.r.cells(), grid.z.cells());
  strain_increment.assign(particles.size(), Voigt::Zero());
  spin_dt.assign(particles.size(), 0.0);
  main_step_end = particles.size();
  micropolar = make_micropolar_fields(model, *this);
  stages = build_stages(*this);

  dt_limit_s = cfl_time_step_limit(*this);
  if (two_phase) dt_limit_s = std::min(dt_limit_s, two_phase_time_step_limit(*this));
  dt_s = settings.fixed_dt_s ? *settings.fixed_dt_s : settings.courant * dt_limit_s;
  dt_next_s = dt_s;
}

void Simulation::advance() {
  stages.run(*this);
  time_s += dt_s;
  ++step;
  dt_s = dt_next_s;
}

namespace {

/// A group's fastest signal: c_p + |v| bounded by √((M + |σ|)/ρ_min) + |v|_max (see below),
/// and its speed part alone; `bad` counts particles with a non-finite state.
struct SignalSpeed {
  double wave_and_speed = 0.0, speed = 0.0;
  long bad = 0;
};

/// A group's maxima in a pass of its own, each thread its own part's particles
/// (mpm/particle_bins.hpp).
SignalMaxima group_signal_maxima(const Simulation& s, const MaterialGroup& g) {
  const Particles& p = s.particles;
  double stiffest = 0.0, speed2 = 0.0, stress = 0.0;  // max 1/ρ, max |v|², max |σ|
  long bad = 0;
  const bool ready = s.bins.covers(p.size());
  const int parts = ready ? s.bins.parts() : 1;
  FFP_OMP(omp parallel reduction(max : stiffest, speed2, stress) reduction(+ : bad) \
              if (ready && g.size() >= kParallelMinimum))
  for (int part = team_member(); part < parts; part += team_size()) {
    const auto [from, to] = ready ? s.bins.particle_range(part) : std::pair<std::size_t, std::size_t>{0, p.size()};
    const std::size_t begin = std::max(from, g.begin), end = std::min(to, g.end);
    if (begin >= end) continue;
    const SignalMaxima m = signal_maxima(p, begin, end);
    stiffest = std::max(stiffest, m.stiffest);
    speed2 = std::max(speed2, m.speed2);
    stress = std::max(stress, m.stress);
    bad += m.bad;
  }
  return {stiffest, speed2, stress, bad};
}

/// `formed`: the maxima update_stresses formed (Simulation::stressed_signal), or null.
SignalSpeed signal_speed(const Simulation& s, std::size_t group, const SignalMaxima* formed) {
  const MaterialGroup& g = s.groups[group];
  // c_p + |v| ≤ √((M + |σ|)/ρ_min) + |v|_max: the per-group extremes bound every
  // particle's sum and need no square root per particle. |σ| (a bound on the largest
  // principal stress) is the geometric stiffness of the current stress: it matters only
  // where stresses approach the modulus (very soft bodies under gravity), and there
  // the elastic c_p alone let the step run unstable (measured: an E = 1 kPa block
  // collapsing under its own weight at Courant 1).
  const SignalMaxima m = formed ? *formed : group_signal_maxima(s, g);
  double stiffest = m.stiffest;
  // A disconnected particle is stress-free; it reconnects at the disconnection density.
  if (g.disconnected_below_kg_m3 > 0.0) stiffest = std::min(stiffest, 1.0 / g.disconnected_below_kg_m3);
  const double speed = std::max(std::sqrt(m.speed2), s.rigid_speed_m_s);
  // A micropolar group's rotation adds its own stiffnesses (docs/theory.md#micropolar-time-step);
  // a classical group's sum is left exactly as it was.
  const double modulus = g.constrained_modulus() + m.stress;
  const double micropolar = micropolar_wave_modulus(s, group);
  return {std::sqrt((micropolar > 0.0 ? modulus + micropolar : modulus) * stiffest) + speed, speed, m.bad};
}

[[noreturn]] void report_bad_particle(const Simulation& s) {
  const Particles& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!(p.volume[i] > 0.0) || !std::isfinite(p.volume[i]) || !std::isfinite(p.vr[i]) || !std::isfinite(p.vz[i]) ||
        !p.stress[i].allFinite())
      throw StepFailure("particle " + std::to_string(i) +
                        " has a non-finite velocity or stress, or a non-positive "
                        "volume at t = " +
                        std::to_string(s.time_s) + " s (unstable step?)");
  }
  throw StepFailure("a particle has a non-finite state at t = " + std::to_string(s.time_s) + " s");
}

}  // namespace

double cfl_time_step_limit(const Simulation& s) { return cfl_time_step_limit(s, {}); }

double cfl_time_step_limit(const Simulation& s, const std::vector<std::optional<SignalMaxima>>& formed) {
  double fastest = 0.0;
  for (std::size_t group = 0; group < s.groups.size(); ++group) {
    const bool known = group < formed.size() && formed[group];
    const SignalSpeed signal = signal_speed(s, group, known ? &*formed[group] : nullptr);
    if (signal.bad > 0) report_bad_particle(s);
    fastest = std::max(fastest, s.groups[group].begin < s.main_step_end ? signal.wave_and_speed : signal.speed);
  }
  return s.grid.min_spacing() / fastest;
}

double group_time_step_limit(const Simulation& s, const MaterialGroup& g) {
  const SignalSpeed signal = signal_speed(s, static_cast<std::size_t>(&g - s.groups.data()), nullptr);
  if (signal.bad > 0) report_bad_particle(s);
  return s.grid.min_spacing() / signal.wave_and_speed;
}

}  // namespace ffp::mpm
