#include "verification/shear_band_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "models/math_constants.hpp"
#include "mpm/simulation.hpp"

namespace ffp::verification {

using namespace ffp::mpm;

namespace {

/// n equal cells from a to b (n + 1 nodes).
std::vector<double> equal_nodes(double a, double b, int cells) {
  std::vector<double> x;
  for (int i = 0; i <= cells; ++i) x.push_back(a + (b - a) * i / cells);
  return x;
}

/// The drag's state, shared with its stages.
struct WallDrag {
  double ramp_s = 0.0, speed_m_s = 0.0;
  double displacement_m = 0.0;
  double inner_force = 0.0, outer_force = 0.0;  ///< per radian, the whole row

  double speed(double t) const {
    return t >= ramp_s ? speed_m_s : speed_m_s * 0.5 * (1.0 - std::cos(kPi * t / ramp_s));
  }
};

/// x_n ← Σ_j w_j x_j / Σ_j w_j over column i, on the column's nodes that have weight.
void tie_column(const Grid& grid, int i, const std::vector<double>& weight, double floor, std::vector<double>& x) {
  double w = 0.0, wx = 0.0;
  for (int j = 0; j < grid.z.nodes(); ++j) {
    const std::size_t n = grid.node(i, j);
    if (weight[n] > floor) {
      w += weight[n];
      wx += weight[n] * x[n];
    }
  }
  for (int j = 0; j < grid.z.nodes(); ++j) {
    const std::size_t n = grid.node(i, j);
    if (weight[n] > floor) x[n] = wx / w;
  }
}

/// Before the damping: each free column's axial force f_j^int,z + f_j^ext,z shared out in
/// proportion to its nodes' masses (and the couples in proportion to the rotational masses),
/// so that Cundall's damping, node by node, acts on the column's net force and not on the
/// ± p0 faces' forces that cancel over it.
void share_column_forces(Simulation& s) {
  NodalField& f = s.grid.fields[0];
  const Grid& g = s.grid;
  for (int i = 1; i + 1 < g.r.nodes(); ++i) {
    double mass = 0.0, force = 0.0;
    for (int j = 0; j < g.z.nodes(); ++j) {
      const std::size_t n = g.node(i, j);
      mass += f.mass[n];
      force += f.internal_force_z[n] + f.external_force_z[n];
    }
    for (int j = 0; j < g.z.nodes(); ++j) {
      const std::size_t n = g.node(i, j);
      f.internal_force_z[n] = mass > 0.0 ? force * f.mass[n] / mass : 0.0;
      f.external_force_z[n] = 0.0;
    }
  }
  MicropolarFields& m = s.micropolar;
  if (!m.active()) return;
  for (int i = 1; i + 1 < g.r.nodes(); ++i) {
    double inertia = 0.0, couple = 0.0;
    for (int j = 0; j < g.z.nodes(); ++j) {
      inertia += m.rotational_mass[g.node(i, j)];
      couple += m.couple_force[g.node(i, j)];
    }
    for (int j = 0; j < g.z.nodes(); ++j) {
      const std::size_t n = g.node(i, j);
      m.couple_force[n] = inertia > 0.0 ? couple * m.rotational_mass[n] / inertia : 0.0;
    }
  }
}

/// Column i's axial velocities ← `value` where it has mass.
void drive_column(const Grid& grid, int i, const NodalField& f, double floor, double value, std::vector<double>& v) {
  for (int j = 0; j < grid.z.nodes(); ++j) {
    const std::size_t n = grid.node(i, j);
    if (f.mass[n] > floor) v[n] = value;
  }
}

/// After the grid update: the wall's velocities v^n = V(t), v^{n+1} = V(t + Δt) and its force
/// Σ_j [m_j (v^{n+1} − v^n)/Δt − f_j^int,z] (the force the wall puts on the soil; the damping is
/// no force of the wall's); the outer wall's Σ_j f_j^int,z (the soil's push, at rest); the free
/// columns tied.
void drag_after_integration(Simulation& s, WallDrag& d) {
  NodalField& f = s.grid.fields[0];
  const Grid& g = s.grid;
  const int last = g.r.nodes() - 1;
  const double floor = s.mass_floor_kg, dt = s.dt_s, v0 = d.speed(s.time_s), v1 = d.speed(s.time_s + dt);
  d.inner_force = d.outer_force = 0.0;
  for (int j = 0; j < g.z.nodes(); ++j) {
    const std::size_t n = g.node(0, j), o = g.node(last, j);
    if (f.mass[n] > floor) d.inner_force += f.mass[n] * (v1 - v0) / dt - f.internal_force_z[n];
    if (f.mass[o] > floor) d.outer_force += f.internal_force_z[o];
  }
  drive_column(g, 0, f, floor, v0, f.velocity_z);
  drive_column(g, 0, f, floor, v1, f.velocity_new_z);
  for (int i = 1; i < last; ++i) {
    tie_column(g, i, f.mass, floor, f.velocity_z);
    tie_column(g, i, f.mass, floor, f.velocity_new_z);
  }
  MicropolarFields& m = s.micropolar;
  if (m.active()) {
    for (int i = 1; i < last; ++i) {
      tie_column(g, i, m.rotational_mass, m.rotational_mass_floor, m.spin);
      tie_column(g, i, m.rotational_mass, m.rotational_mass_floor, m.spin_new);
    }
  }
  d.displacement_m += dt * v1;
}

/// After MUSL's remap: the wall's remapped velocity V(t + Δt); the free columns tied.
void drag_after_remap(Simulation& s, const WallDrag& d) {
  NodalField& f = s.grid.fields[0];
  const Grid& g = s.grid;
  const int last = g.r.nodes() - 1;
  drive_column(g, 0, f, s.mass_floor_kg, d.speed(s.time_s + s.dt_s), f.velocity_z);
  for (int i = 1; i < last; ++i) tie_column(g, i, f.mass, s.mass_floor_kg, f.velocity_z);
  MicropolarFields& m = s.micropolar;
  if (m.active())
    for (int i = 1; i < last; ++i) tie_column(g, i, m.rotational_mass, m.rotational_mass_floor, m.spin);
}

/// The model: the annulus one cell row tall, room above it for the wall's travel.
ModelDescription cylinder_model(const ShearBandCase& c, int cells, double h) {
  const int rows_above = static_cast<int>(std::ceil(c.end_displacement_m / h)) + 2;  // room for the travel
  ModelDescription m;
  m.r_nodes_m = equal_nodes(c.inner_m, c.outer_m, cells);
  m.z_nodes_m = equal_nodes(-h, (1 + rows_above) * h, rows_above + 2);
  const BodyDescription body{.name = "sand",
                             .law = c.law,
                             .density_kg_m3 = c.density_kg_m3,
                             .region = BoxRegion{c.inner_m, c.outer_m, 0.0, h},
                             .particles_per_cell_r = c.particles_per_cell,
                             .particles_per_cell_z = 1,
                             .initial_stress = std::nullopt,
                             .micropolar = c.micropolar};
  m.bodies.push_back(body);
  m.boundaries = {Fixity::roller, Fixity::fixed, Fixity::free, Fixity::free};
  m.solver.local_damping = c.local_damping;
  m.solver.transfer = c.transfer;
  return m;
}

/// Every particle keeps its radius (u_r = 0), and the two of a cell share its strain (each
/// particle's GIMP domain lies inside one cell, whose gradient it takes): the profile is one
/// value per cell, at the cell's centre.
void record_profiles(const Simulation& s, const ShearBandCase& c, int cells, double h, ShearBandRun& run) {
  const Particles& P = s.particles;
  const MaterialGroup& group = s.groups.front();
  std::vector<double> kappa(P.size(), 0.0);
  if (has_state_output(group.law, StateOutput::plastic_deviatoric_strain))
    group.state_output(StateOutput::plastic_deviatoric_strain, P.stress, kappa);
  const double G = elastic_constants(group.law).shear_modulus();
  run.radius_m.resize(cells);
  run.plastic_shear.assign(cells, 0.0);
  run.softening.assign(cells, 0.0);
  std::vector<int> count(cells, 0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const auto cell = static_cast<std::size_t>(std::clamp(static_cast<int>((P.r0[p] - c.inner_m) / h), 0, cells - 1));
    run.plastic_shear[cell] += std::abs(2.0 * P.strain[p][3] - P.stress[p][3] / G);
    run.softening[cell] += kappa[p];
    ++count[cell];
  }
  for (int k = 0; k < cells; ++k) {
    run.radius_m[k] = c.inner_m + (k + 0.5) * h;
    run.plastic_shear[k] /= count[k];
    run.softening[k] /= count[k];
  }
}

}  // namespace

ShearBandRun run_shear_band(const ShearBandCase& c, double cell_m) {
  const int cells = static_cast<int>(std::lround((c.outer_m - c.inner_m) / cell_m));
  const double h = (c.outer_m - c.inner_m) / cells;
  Simulation s(cylinder_model(c, cells, h));

  for (std::size_t i = 0; i < s.grid.nodes(); ++i)
    s.grid.constraints.push_back({static_cast<std::uint32_t>(i), constrain_r});
  if (s.micropolar.active())
    for (int j = 0; j < s.grid.z.nodes(); ++j)
      s.micropolar.fixed_nodes.push_back(static_cast<std::uint32_t>(s.grid.node(0, j)));
  Voigt confined = Voigt::Zero();
  confined.head<3>().setConstant(-c.confinement_Pa);
  std::fill(s.particles.stress.begin(), s.particles.stress.end(), confined);

  auto drag = std::make_shared<WallDrag>();
  drag->ramp_s = c.ramp_s;
  drag->speed_m_s = c.wall_speed_m_s;
  s.stages.insert_before(c.local_damping > 0.0 ? "apply_local_damping" : "integrate_grid",
                         {"share_column_forces", share_column_forces});
  s.stages.insert_before("apply_boundary_conditions",
                         {"drag_inner_wall", [drag](Simulation& sim) { drag_after_integration(sim, *drag); }});
  if (c.transfer != Transfer::usl)
    s.stages.insert_after(s.micropolar.active() ? "map_micro_spin_to_grid" : "map_velocities_to_grid",
                          {"drag_inner_wall_remapped", [drag](Simulation& sim) { drag_after_remap(sim, *drag); }});

  ShearBandRun run;
  ShearBandRecord peak{0.0, 0.0, 0.0};
  auto past_peak = [&] {
    return c.end_past_peak_m && drag->displacement_m - peak.displacement_m >= *c.end_past_peak_m;
  };
  while (drag->displacement_m < c.end_displacement_m && !past_peak()) {
    s.advance();
    run.history.push_back({drag->displacement_m, drag->inner_force / h, drag->outer_force / h});
    if (run.history.back().inner_force > peak.inner_force) peak = run.history.back();
  }
  run.steps = s.step;
  record_profiles(s, c, cells, h, run);
  return run;
}

ShearBandRecord peak_of(const ShearBandRun& run) {
  return *std::ranges::max_element(run.history, {}, &ShearBandRecord::inner_force);
}

double inner_force_at(const ShearBandRun& run, double displacement_m) {
  const auto& h = run.history;
  const auto after = std::ranges::lower_bound(h, displacement_m, {}, &ShearBandRecord::displacement_m);
  if (after == h.begin()) return after->inner_force;
  if (after == h.end()) return h.back().inner_force;
  const auto before = after - 1;
  const double w = (displacement_m - before->displacement_m) / (after->displacement_m - before->displacement_m);
  return before->inner_force + w * (after->inner_force - before->inner_force);
}

BandWidth band_width(const std::vector<double>& r, const std::vector<double>& x, double r_wall) {
  const double half = 0.5 * *std::ranges::max_element(x);
  // The part of [a, b] where the linear x ≥ half.
  auto above = [half](double a, double xa, double b, double xb) {
    if (xa >= half && xb >= half) return b - a;
    if (xa < half && xb < half) return 0.0;
    const double cross = a + (half - xa) / (xb - xa) * (b - a);
    return xa >= half ? cross - a : b - cross;
  };
  BandWidth w{above(r_wall, x.front(), r.front(), x.front()), 0.0};
  double weight = 0.0, first_moment = 0.0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (k + 1 < r.size()) w.half_maximum_m += above(r[k], x[k], r[k + 1], x[k + 1]);
    const double positive = std::max(x[k], 0.0);
    weight += positive;
    first_moment += (r[k] - r_wall) * positive;
  }
  w.moment_m = 2.0 * first_moment / weight;
  return w;
}

StrainSofteningMohrCoulomb paper_softening_sand() {
  StrainSofteningParameters p;
  p.elastic = {2.5e6, 0.33};
  p.friction_peak_rad = 39.0 * kDegree;
  p.friction_residual_rad = 32.0 * kDegree;
  p.softening_factor = 8.0;
  return StrainSofteningMohrCoulomb(p);
}

ShearBandCase paper_sand_cylinder(MaterialLaw law, std::optional<MicropolarParameters> micropolar) {
  ShearBandCase c{std::move(law)};
  c.density_kg_m3 = 14.6e3 / 9.81;
  c.micropolar = micropolar;
  c.inner_m = 0.5;
  c.outer_m = 0.55;
  c.confinement_Pa = 50e3;
  c.wall_speed_m_s = 0.05;
  c.ramp_s = 0.02;
  c.end_displacement_m = 5e-3;
  return c;
}

MicropolarParameters cylinder_micropolar(double length_m) { return {length_m, 0.5, length_m * length_m}; }

}  // namespace ffp::verification
