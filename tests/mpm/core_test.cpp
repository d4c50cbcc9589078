/// Unit checks of the MPM core pieces: grid axis, shape functions, stage list,
/// Jaumann rotation, time step.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/diagnostics.hpp"
#include "mpm/grid_axis.hpp"
#include "mpm/shape_functions.hpp"
#include "mpm/simulation.hpp"
#include "mpm/stages.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

TEST_CASE("grid axis finds the cell of a coordinate on a graded, moving axis", "[mpm][grid]") {
  GridAxis axis({0.0, 0.1, 0.15, 0.17, 0.3, 1.0});
  CHECK(axis.cell_of(0.0) == 0);
  CHECK(axis.cell_of(0.12) == 1);
  CHECK(axis.cell_of(0.16) == 2);
  CHECK(axis.cell_of(0.17) == 3);
  CHECK(axis.cell_of(1.0) == 4);
  CHECK(axis.cell_of(-1e-9) == -1);
  CHECK(axis.cell_of(1.0 + 1e-9) == -1);
  // A hint (the particle's previous cell) gives the same cell, right or wrong.
  for (const double x : {0.0, 0.1, 0.12, 0.16, 0.17, 0.5, 1.0, -1e-9, 1.0 + 1e-9})
    for (const int hint : {-1, 0, 1, 2, 3, 4, 5, 99}) CHECK(axis.cell_near(x, hint) == axis.cell_of(x));
  const std::vector<double> moved = {0.0, 0.05, 0.1, 0.5, 0.6, 1.0};
  axis.set_coordinates(moved);
  CHECK(axis.cell_of(0.16) == 2);
  CHECK(axis.min_spacing() == Approx(0.05));
  CHECK_THROWS_AS(GridAxis({0.0, 0.1, 0.1}), std::invalid_argument);
  // ∫ N_i over the whole axis is half the sum of the neighbouring cells.
  CHECK(axis.hat_integral(2, 0.0, 1.0) == Approx(0.5 * (0.05 + 0.4)));
}

TEST_CASE("shape functions: partition of unity, zero gradient sum, GIMP equals linear inside a cell", "[mpm][shape]") {
  const GridAxis axis({0.0, 0.1, 0.25, 0.3, 0.5, 0.55});
  for (double x = 0.0; x <= 0.55; x += 0.00731) {
    const int c = axis.cell_of(x);
    for (double half : {0.0, 0.01, 0.025, 0.2}) {
      const Weights1D w = half == 0.0 ? linear_weights(axis, x, c) : gimp_weights(axis, x, half, c);
      double sum = 0.0, gradient = 0.0, first_moment = 0.0;
      for (int k = 0; k < 3; ++k) {
        sum += w.w[k];
        gradient += w.g[k];
        if (w.w[k] != 0.0) first_moment += w.w[k] * axis.coordinate(w.base + k);
        CHECK(w.w[k] >= -1e-15);
      }
      CHECK(sum == Approx(1.0).epsilon(1e-14));
      CHECK(gradient == Approx(0.0).margin(1e-9));
      // Linear completeness: Σ S_i x_i = x (the domain average of x is x itself).
      CHECK(first_moment == Approx(x).margin(1e-14));
    }
  }
  // A GIMP domain inside one cell averages a linear hat: same as point evaluation.
  const Weights1D g = gimp_weights(axis, 0.16, 0.02, 1), l = linear_weights(axis, 0.16, 1);
  const int shift = l.base - g.base;
  for (int k = 0; k < 2; ++k) {
    CHECK(g.w[k + shift] == Approx(l.w[k]));
    CHECK(g.g[k + shift] == Approx(l.g[k]));
  }
  // Across a node the GIMP gradient is continuous (linear hats jump).
  const Weights1D left = gimp_weights(axis, 0.1 - 1e-9, 0.02, 0), right = gimp_weights(axis, 0.1 + 1e-9, 0.02, 1);
  for (int k = 0; k < 3; ++k) {
    const int node = left.base + k;
    const int j = node - right.base;
    if (j >= 0 && j < 3) CHECK(left.g[k] == Approx(right.g[j]).margin(1e-6));
  }
}

TEST_CASE("stage list: a model gets only the stages it needs and stages insert by name", "[mpm][stages]") {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 4);
  m.z_nodes_m = testing::nodes(0.0, 0.1, 4);
  m.bodies.push_back(testing::elastic_body("b", 1e6, 0.3, 1000.0, BoxRegion{0, 0.05, 0, 0.05}));
  m.solver.transfer = Transfer::usl;
  m.solver.strain_smoothing = StrainSmoothing::off;
  Simulation weightless(m);
  CHECK_FALSE(weightless.stages.contains("apply_gravity"));
  CHECK_FALSE(weightless.stages.contains("map_velocities_to_grid"));
  CHECK_FALSE(weightless.stages.contains("smooth_volumetric_strain"));
  CHECK_FALSE(weightless.stages.contains("apply_local_damping"));
  m.gravity_m_s2 = 9.81;
  m.solver.transfer = Transfer::musl;
  m.solver.strain_smoothing = StrainSmoothing::volumetric;
  Simulation heavy(m);
  CHECK(heavy.stages.contains("apply_gravity"));
  CHECK(heavy.stages.contains("map_velocities_to_grid"));
  CHECK(heavy.stages.contains("smooth_volumetric_strain"));
  CHECK(heavy.stages.contains("smooth_mean_stress"));

  int calls = 0;
  heavy.stages.insert_after("integrate_grid", {"count_calls", [&calls](Simulation&) { ++calls; }});
  const auto names = heavy.stages.names();
  const auto at = std::find(names.begin(), names.end(), "count_calls");
  REQUIRE(at != names.end());
  CHECK(*(at - 1) == "integrate_grid");
  heavy.advance();
  heavy.advance();
  CHECK(calls == 2);
  CHECK_THROWS_AS(heavy.stages.insert_before("no_such_stage", {"x", [](Simulation&) {}}), std::invalid_argument);
}

TEST_CASE("Jaumann rotation turns the stress with the material spin", "[mpm][stress]") {
  // Rigid spin Ω in the (r, z) plane: L_rz = −Ω, L_zr = Ω, W_rz = −Ω. Over one step the
  // stress must turn by Ω Δt: σ' = R σ Rᵀ to first order.
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 4);
  m.z_nodes_m = testing::nodes(0.0, 0.1, 4);
  m.bodies.push_back(testing::elastic_body("b", 1e6, 0.3, 1000.0, BoxRegion{0, 0.025, 0, 0.025}, 0, 0, 1));
  Simulation s(m);
  const double angle = 1e-4;  // Ω Δt
  s.strain_increment.assign(s.particles.size(), Voigt::Zero());
  s.spin_dt.assign(s.particles.size(), -angle);
  Voigt sigma = Voigt::Zero();
  sigma[0] = -100.0;  // σ_rr
  sigma[1] = -300.0;  // σ_zz
  s.particles.stress.assign(s.particles.size(), sigma);
  update_stresses(s);
  const Voigt& out = s.particles.stress[0];
  // With R = [[cos θ, −sin θ], [sin θ, cos θ]] (counter-clockwise in (r, z)):
  // (RσRᵀ)_rz = (σ_rr − σ_zz) sin θ cos θ, (RσRᵀ)_rr = σ_rr + O(θ²).
  CHECK(out[3] == Approx((sigma[0] - sigma[1]) * angle).epsilon(1e-6));
  CHECK(out[0] == Approx(sigma[0]).epsilon(1e-9));
  CHECK(out[2] == sigma[2]);
}

TEST_CASE("time step follows the CFL limit and a fixed step above it stops the run", "[mpm][time_step]") {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 10);
  m.z_nodes_m = testing::nodes(0.0, 0.2, 40);  // h_min = 5 mm
  m.bodies.push_back(testing::elastic_body("b", 1e7, 0.25, 2000.0, BoxRegion{0, 0.1, 0, 0.1}, 0.0, -2.0));
  m.solver.courant = 0.4;
  Simulation s(m);
  const double c = ElasticConstants{1e7, 0.25}.p_wave_speed(2000.0);
  CHECK(s.dt_limit_s == Approx(0.005 / (c + 2.0)).epsilon(1e-12));
  CHECK(s.dt_s == Approx(0.4 * s.dt_limit_s).epsilon(1e-12));
  m.solver.fixed_dt_s = 1.01 * s.dt_limit_s;
  Simulation fixed(m);
  CHECK_THROWS_AS(fixed.advance(), StepFailure);
}

TEST_CASE("the CFL maxima take each particle, in vector lanes or after them, and a non-finite one stops the run",
          "[mpm][time_step]") {
  // 3 × 1 cells of 3 × 3 particles: 27, so that the lanes of four take 24 and the last
  // three go one by one. One particle at a time is made the fastest, the most stressed
  // or non-finite; the limit must follow it wherever it sits.
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 10);
  m.z_nodes_m = testing::nodes(0.0, 0.2, 40);  // h_min = 5 mm
  m.bodies.push_back(testing::elastic_body("b", 1e7, 0.25, 2000.0, BoxRegion{0, 0.03, 0, 0.005}, 0.0, 0.0, 3));
  Simulation s(m);
  Particles& P = s.particles;
  REQUIRE(P.size() == 27);
  const double density = P.mass[0] / P.volume[0];
  const double M = ElasticConstants{1e7, 0.25}.constrained_modulus();
  const double c = std::sqrt(M / density);
  CHECK(cfl_time_step_limit(s) == Approx(0.005 / c).epsilon(1e-12));
  for (std::size_t p = 0; p < P.size(); ++p) {
    P.vz[p] = -3.0;
    CHECK(cfl_time_step_limit(s) == Approx(0.005 / (c + 3.0)).epsilon(1e-12));
    P.vz[p] = 0.0;
    P.stress[p][3] = -2e7;  // |σ_rz| in the Gershgorin bound
    CHECK(cfl_time_step_limit(s) == Approx(0.005 / std::sqrt((M + 2e7) / density)).epsilon(1e-12));
    P.stress[p][3] = 0.0;
    P.vr[p] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(cfl_time_step_limit(s), StepFailure);
    P.vr[p] = 0.0;
  }
}

TEST_CASE("the step's CFL maxima, formed by update_stresses as it stresses, are a pass of their own's",
          "[mpm][time_step]") {
  // 3,600 particles: seven and a bit batches of update_stresses. The fastest and the
  // most stressed particle sit in late batches; the time step the step took (from the
  // batches' maxima) must be the limit of a pass over the same end-of-step state.
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.3, 30);
  m.z_nodes_m = testing::nodes(0.0, 0.3, 30);
  m.bodies.push_back(testing::elastic_body("b", 1e7, 0.25, 2000.0, BoxRegion{0, 0.2, 0, 0.2}, 0.0, -2.0, 3));
  Simulation s(m);
  REQUIRE(s.particles.size() == 3600);
  const std::vector<Stage>& stages = s.stages.items();
  const auto stress = std::ranges::find(stages, "update_stresses", &Stage::name);
  REQUIRE((stress != stages.end() && (stress + 1)->name == "update_time_step"));  // the fused path
  for (const std::size_t fastest : {3000, 3599}) {
    s.particles.vr[fastest] = 40.0;
    s.particles.stress[fastest - 700][3] = -5e7;
    s.advance();
    CHECK(s.dt_limit_s == cfl_time_step_limit(s));
  }
}

TEST_CASE("transfers: each particle moves with the nodal field its strain comes from", "[mpm][transfer]") {
  // A falling elastic block hitting the fixed bottom: after the first contact
  // steps the grid-updated field v_i^{n+1} and the field remapped from the
  // updated particles differ, so moving with one and straining with the other
  // (the classic MUSL) is told apart from the consistent steps. USL: x moves by
  // Δt Σ S v_i^{n+1}; musl_remapped (the paper's code): by Δt Σ S ṽ_i, the
  // remapped field, which is also what the strain increments are taken from.
  for (const Transfer transfer : {Transfer::usl, Transfer::musl_remapped}) {
    ModelDescription m;
    m.r_nodes_m = testing::nodes(0.0, 0.2, 10);
    m.z_nodes_m = testing::nodes(0.0, 0.2, 10);
    m.bodies.push_back(testing::elastic_body("block", 1e6, 0.3, 2000.0, BoxRegion{0.0, 0.1, 0.0, 0.1}, 0.0, -1.0));
    m.gravity_m_s2 = 9.81;
    m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
    m.solver.transfer = transfer;
    Simulation s(m);
    for (int k = 0; k < 20; ++k) s.advance();
    const std::vector<double> r0 = s.particles.r, z0 = s.particles.z;
    const double dt = s.dt_s;
    s.advance();
    const NodalField& f = s.grid.fields[0];
    const std::vector<double>& vr = transfer == Transfer::usl ? f.velocity_new_r : f.velocity_r;
    const std::vector<double>& vz = transfer == Transfer::usl ? f.velocity_new_z : f.velocity_z;
    double worst = 0.0, largest = 0.0, remap_gap = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      const ShapeWeights& w = s.weights[p];  // from the step's start positions
      double ur = 0.0, uz = 0.0, gap = 0.0;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          const std::size_t i = s.grid.node(w.node_r + a, w.node_z + b);
          if (i >= f.size()) continue;
          const double N = w.wr[a] * w.wz[b];
          ur += N * dt * vr[i];
          uz += N * dt * vz[i];
          gap += N * dt * std::abs(f.velocity_new_z[i] - f.velocity_z[i]);
        }
      worst = std::max(worst, std::hypot(s.particles.r[p] - r0[p] - ur, s.particles.z[p] - z0[p] - uz));
      largest = std::max(largest, std::hypot(ur, uz));
      remap_gap = std::max(remap_gap, gap);
    }
    INFO((transfer == Transfer::usl ? "usl" : "musl_remapped")
         << ": largest step " << largest << " m, worst mismatch " << worst << " m, |v_new − ṽ|Δt up to " << remap_gap
         << " m");
    REQUIRE(largest > 0.0);
    CHECK(worst <= 1e-12 * largest);
    if (transfer == Transfer::musl_remapped) CHECK(remap_gap > 1e-6 * largest);  // the two fields do differ
  }
}

namespace {

/// An elastic block filling the grid's width, thrown outwards and down against the
/// walls (a roller axis and wall, a fixed base): stresses, shear included, and
/// velocities that vary from particle to particle after a few steps.
ModelDescription thrown_block(ShapeFunction shape, Transfer transfer) {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.2, 8);
  m.z_nodes_m = testing::nodes(0.0, 0.3, 12);
  m.bodies.push_back(testing::elastic_body("block", 1e6, 0.3, 2000.0, BoxRegion{0.0, 0.2, 0.0, 0.2}, 0.5, -1.0));
  m.gravity_m_s2 = 9.81;
  m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
  m.solver.shape_function = shape;
  m.solver.transfer = transfer;
  return m;
}

/// max |a − b| over max |b|: the largest of a nodal array sets the rounding scale
/// of sums of terms of both signs.
double relative_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return worst / scale;
}

}  // namespace

TEST_CASE("transfers: a support row per vector gives the node-by-node sums", "[mpm][transfer]") {
  // The kernel maps a support row as one vector (mpm/support_row.hpp), except for a
  // GIMP particle whose row ends at the grid's last node column, which goes node by
  // node. A block that fills the grid's width has particles of both kinds; its mapped
  // mass, momentum and internal forces, and its strain increments, must be the sums
  // S_ip m_p, S_ip m_p v_p, −V_p (σ_p·G_ip + σ_θθ S_ip/r_p e_r) and Δt sym(Σ v_i ⊗ G_ip)
  // formed node by node here, to rounding.
  for (const ShapeFunction shape : {ShapeFunction::gimp, ShapeFunction::linear}) {
    ModelDescription m = thrown_block(shape, Transfer::usl);
    m.solver.strain_smoothing = StrainSmoothing::off;
    Simulation s(m);
    // Thrown outwards and down against the walls: stresses, shear included, and
    // velocities that vary from particle to particle.
    for (int k = 0; k < 5; ++k) s.advance();
    double largest_shear = 0.0, largest_stress = 0.0;
    for (const Voigt& sig : s.particles.stress) {
      largest_shear = std::max(largest_shear, std::abs(sig[3]));
      largest_stress = std::max(largest_stress, sig.cwiseAbs().maxCoeff());
    }
    REQUIRE(largest_shear > 0.05 * largest_stress);
    // One more step, stage by stage: first up to the internal forces.
    const std::vector<Stage>& stages = s.stages.items();
    auto stage = stages.begin();
    auto run_through = [&](const std::string& last) {
      for (; stage != stages.end(); ++stage) {
        stage->run(s);
        if (stage->name == last) return ++stage, true;
      }
      return false;
    };
    REQUIRE(run_through("compute_internal_forces"));
    const NodalField& f = s.grid.fields[0];
    const int S = shape == ShapeFunction::gimp ? 3 : 2;
    std::vector<double> mass(f.size(), 0.0), momentum_z(f.size(), 0.0), force_r(f.size(), 0.0), force_z(f.size(), 0.0);
    const Particles& P = s.particles;
    long edge_particles = 0;
    double strain_gap = 0.0, strain_scale = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const ShapeWeights& w = s.weights[p];
      if (w.node_r + 3 >= s.grid.r.nodes()) ++edge_particles;
      const Voigt& sig = P.stress[p];
      for (int b = 0; b < S; ++b)
        for (int a = 0; a < S; ++a) {
          const std::size_t i = s.grid.node(w.node_r + a, w.node_z + b);
          const double N = w.wr[a] * w.wz[b], Gr = w.gr[a] * w.wz[b], Gz = w.wr[a] * w.gz[b];
          mass[i] += N * P.mass[p];
          momentum_z[i] += N * P.mass[p] * P.vz[p];
          force_r[i] -= P.volume[p] * (sig[0] * Gr + sig[3] * Gz + sig[2] * N * w.inverse_r);
          force_z[i] -= P.volume[p] * (sig[3] * Gr + sig[1] * Gz);
        }
    }
    // Then on to the strain increments (USL: from v_i^{n+1}, the step's start weights).
    REQUIRE(run_through("compute_strain_increments"));
    for (std::size_t p = 0; p < P.size(); ++p) {
      const ShapeWeights& w = s.weights[p];
      double L_rr = 0.0, L_zz = 0.0, L_tt = 0.0, L_rz = 0.0, L_zr = 0.0;
      for (int b = 0; b < S; ++b)
        for (int a = 0; a < S; ++a) {
          const std::size_t i = s.grid.node(w.node_r + a, w.node_z + b);
          const double N = w.wr[a] * w.wz[b], Gr = w.gr[a] * w.wz[b], Gz = w.wr[a] * w.gz[b];
          L_rr += f.velocity_new_r[i] * Gr;
          L_rz += f.velocity_new_r[i] * Gz;
          L_zr += f.velocity_new_z[i] * Gr;
          L_zz += f.velocity_new_z[i] * Gz;
          L_tt += f.velocity_new_r[i] * N * w.inverse_r;
        }
      const double dt = s.dt_s;
      const Voigt expected{dt * L_rr, dt * L_zz, dt * L_tt, 0.5 * dt * (L_rz + L_zr), 0.0, 0.0};
      strain_gap = std::max(strain_gap, (s.strain_increment[p] - expected).cwiseAbs().maxCoeff());
      strain_scale = std::max(strain_scale, expected.cwiseAbs().maxCoeff());
    }
    INFO(to_string(shape) << ": " << edge_particles << " particles at the last column");
    if (shape == ShapeFunction::gimp) CHECK(edge_particles > 0);  // both paths are taken
    CHECK(relative_gap(f.mass, mass) < 1e-13);
    CHECK(relative_gap(f.momentum_z, momentum_z) < 1e-13);
    CHECK(relative_gap(f.internal_force_r, force_r) < 1e-12);
    CHECK(relative_gap(f.internal_force_z, force_z) < 1e-12);
    REQUIRE(strain_scale > 0.0);
    CHECK(strain_gap < 1e-11 * strain_scale);
  }
}

TEST_CASE("transfers: the MUSL remap sums the updated particles' momentum node by node", "[mpm][transfer]") {
  // update_particles sums p_i = Σ_p S_ip m_p v_p^{n+1} as it updates each particle; for
  // linear hats a run of particles in one cell adds to its nodes in registers. Whatever
  // the path, p_i must be that sum, formed node by node here, to rounding.
  for (const ShapeFunction shape : {ShapeFunction::gimp, ShapeFunction::linear}) {
    Simulation s(thrown_block(shape, Transfer::musl));
    for (int k = 0; k < 5; ++k) s.advance();  // thrown against the walls: velocities vary by particle
    const std::vector<Stage>& stages = s.stages.items();
    auto stage = stages.begin();
    for (; stage != stages.end() && stage->name != "update_particles"; ++stage) stage->run(s);
    REQUIRE(stage != stages.end());
    stage->run(s);
    const NodalField& f = s.grid.fields[0];
    const Particles& P = s.particles;
    const int S = shape == ShapeFunction::gimp ? 3 : 2;
    std::vector<double> momentum_r(f.size(), 0.0), momentum_z(f.size(), 0.0);
    for (std::size_t p = 0; p < P.size(); ++p) {
      const ShapeWeights& w = s.weights[p];
      for (int b = 0; b < S; ++b)
        for (int a = 0; a < S; ++a) {
          const std::size_t i = s.grid.node(w.node_r + a, w.node_z + b);
          momentum_r[i] += w.wr[a] * w.wz[b] * P.mass[p] * P.vr[p];
          momentum_z[i] += w.wr[a] * w.wz[b] * P.mass[p] * P.vz[p];
        }
    }
    INFO(to_string(shape));
    CHECK(relative_gap(f.momentum_r, momentum_r) < 1e-13);
    CHECK(relative_gap(f.momentum_z, momentum_z) < 1e-13);
  }
}
