#pragma once
/// A shear band in the MPM: the axial shear of a long thick hollow cylinder of sand
/// (docs/verification.md#localisation-with-a-fixed-width).
///
/// The annulus r_i ≤ r ≤ r_o, confined by an isotropic stress p0, has its inner wall dragged
/// axially (rough: the soil moves with it, and turns no grain: ω = 0) while the outer wall is
/// fixed (u = 0, ω = 0). The cylinder is long: nothing depends on z. The grid holds one cell
/// row of soil, and every node column moves axially as one (its nodes take the column's
/// mass-weighted mean velocity, and its rotational-mass-weighted mean micro-spin): the long
/// cylinder's kinematics. The row's free z-faces then carry nothing of their own, since the
/// nodal forces of σ_zz over a column sum to zero (a column's shape functions sum to one in z).
/// Every node is held radially (u_r = 0, as in the long cylinder). Statics: r T(r) = const,
/// T the axial traction on a face of normal e_r, so the shear peaks at the inner wall
/// (τ ∝ 1/r) and softening starts there.
///
/// The wall's speed rises as a half cosine over `ramp_s`, then stays at `wall_speed_m_s`;
/// quasi-static by a slow drag and Cundall's local damping on the free nodes (the wall's
/// force and the outer wall's agree to the damping's and the inertia's share).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "models/math_constants.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

namespace ffp::mpm::testing {

struct ShearBandCase {
  MaterialLaw law;
  double density_kg_m3 = 1490.0;
  std::optional<MicropolarParameters> micropolar = std::nullopt;
  double inner_m = 0.5, outer_m = 0.55;  ///< r_i, r_o
  double confinement_Pa = 50e3;          ///< p0, the isotropic initial stress (compression)
  double wall_speed_m_s = 0.05;
  double ramp_s = 0.02;
  double end_displacement_m = 0.01;  ///< the inner wall's axial travel at the end
  /// When set, the run ends sooner: this far past the travel of the wall's largest force
  /// (a band compared at the same slip past the peak).
  std::optional<double> end_past_peak_m = std::nullopt;
  double local_damping = 0.3;
  Transfer transfer = Transfer::musl;
  int particles_per_cell = 2;  ///< across r (one particle per cell along z)
};

/// The walls' axial forces per radian and per metre of height (N/m): r T on each wall, which
/// statics makes equal.
struct ShearBandRecord {
  double displacement_m;  ///< the inner wall's travel
  double inner_force, outer_force;
};

struct ShearBandRun {
  std::vector<ShearBandRecord> history;  ///< one record per step
  std::vector<double> radius_m;          ///< the cells' centres, ascending
  std::vector<double> plastic_shear;     ///< |γ^p|, γ^p = 2 ε_rz − σ_rz/G, of each cell at the end
  std::vector<double> softening;         ///< the law's κ of each cell (0 for a law without it)
  long steps = 0;
};

namespace detail {

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
inline void tie_column(const Grid& grid, int i, const std::vector<double>& weight, double floor,
                       std::vector<double>& x) {
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
inline void share_column_forces(Simulation& s) {
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
inline void drive_column(const Grid& grid, int i, const NodalField& f, double floor, double value,
                         std::vector<double>& v) {
  for (int j = 0; j < grid.z.nodes(); ++j) {
    const std::size_t n = grid.node(i, j);
    if (f.mass[n] > floor) v[n] = value;
  }
}

/// After the grid update: the wall's velocities v^n = V(t), v^{n+1} = V(t + Δt) and its force
/// Σ_j [m_j (v^{n+1} − v^n)/Δt − f_j^int,z] (the force the wall puts on the soil; the damping is
/// no force of the wall's); the outer wall's Σ_j f_j^int,z (the soil's push, at rest); the free
/// columns tied.
inline void drag_after_integration(Simulation& s, WallDrag& d) {
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
inline void drag_after_remap(Simulation& s, const WallDrag& d) {
  NodalField& f = s.grid.fields[0];
  const Grid& g = s.grid;
  const int last = g.r.nodes() - 1;
  drive_column(g, 0, f, s.mass_floor_kg, d.speed(s.time_s + s.dt_s), f.velocity_z);
  for (int i = 1; i < last; ++i) tie_column(g, i, f.mass, s.mass_floor_kg, f.velocity_z);
  MicropolarFields& m = s.micropolar;
  if (m.active())
    for (int i = 1; i < last; ++i) tie_column(g, i, m.rotational_mass, m.rotational_mass_floor, m.spin);
}

}  // namespace detail

/// The cylinder of `c` on cells of `cell_m` (square), from rest to the end displacement.
inline ShearBandRun run_shear_band(const ShearBandCase& c, double cell_m) {
  const int cells = static_cast<int>(std::lround((c.outer_m - c.inner_m) / cell_m));
  const double h = (c.outer_m - c.inner_m) / cells;
  const int rows_above = static_cast<int>(std::ceil(c.end_displacement_m / h)) + 2;  // room for the travel
  ModelDescription m;
  m.r_nodes_m = nodes(c.inner_m, c.outer_m, cells);
  m.z_nodes_m = nodes(-h, (1 + rows_above) * h, rows_above + 2);
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
  Simulation s(m);

  for (std::size_t i = 0; i < s.grid.nodes(); ++i)
    s.grid.constraints.push_back({static_cast<std::uint32_t>(i), constrain_r});
  if (s.micropolar.active())
    for (int j = 0; j < s.grid.z.nodes(); ++j)
      s.micropolar.fixed_nodes.push_back(static_cast<std::uint32_t>(s.grid.node(0, j)));
  Voigt confined = Voigt::Zero();
  confined.head<3>().setConstant(-c.confinement_Pa);
  std::fill(s.particles.stress.begin(), s.particles.stress.end(), confined);

  auto drag = std::make_shared<detail::WallDrag>();
  drag->ramp_s = c.ramp_s;
  drag->speed_m_s = c.wall_speed_m_s;
  s.stages.insert_before(c.local_damping > 0.0 ? "apply_local_damping" : "integrate_grid",
                         {"share_column_forces", detail::share_column_forces});
  s.stages.insert_before("apply_boundary_conditions",
                         {"drag_inner_wall", [drag](Simulation& sim) { detail::drag_after_integration(sim, *drag); }});
  if (c.transfer != Transfer::usl)
    s.stages.insert_after(
        s.micropolar.active() ? "map_micro_spin_to_grid" : "map_velocities_to_grid",
        {"drag_inner_wall_remapped", [drag](Simulation& sim) { detail::drag_after_remap(sim, *drag); }});

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

  // Every particle keeps its radius (u_r = 0), and the two of a cell share its strain (each
  // particle's GIMP domain lies inside one cell, whose gradient it takes): the profile is one
  // value per cell, at the cell's centre.
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
  return run;
}

/// The largest inner-wall force of a run and the wall's travel there.
inline ShearBandRecord peak_of(const ShearBandRun& run) {
  return *std::ranges::max_element(run.history, {}, &ShearBandRecord::inner_force);
}

/// The inner-wall force at travel `displacement_m` (linear between steps).
inline double inner_force_at(const ShearBandRun& run, double displacement_m) {
  const auto& h = run.history;
  const auto after = std::ranges::lower_bound(h, displacement_m, {}, &ShearBandRecord::displacement_m);
  if (after == h.begin()) return after->inner_force;
  if (after == h.end()) return h.back().inner_force;
  const auto before = after - 1;
  const double w = (displacement_m - before->displacement_m) / (after->displacement_m - before->displacement_m);
  return before->inner_force + w * (after->inner_force - before->inner_force);
}

/// The width of the band a profile x(r) (ascending radii, the wall at r_wall) shows.
struct BandWidth {
  double half_maximum_m;  ///< the measure of {r : x(r) ≥ max x / 2}, x linear between samples
                          ///< and x(r_wall) = x of the first sample
  double moment_m;        ///< 2 ∫ (r − r_wall) x⁺ dr / ∫ x⁺ dr: a uniform band's width
};

inline BandWidth band_width(const std::vector<double>& r, const std::vector<double>& x, double r_wall) {
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

}  // namespace ffp::mpm::testing
