/// Elastic stability at the CFL limit (Courant 1) over the whole range of
/// stiffness the project meets: 1 kPa (a very loose sand) to 200 GPa (the steel
/// FFP), Poisson's ratio up to 0.49.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "mpm/diagnostics.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

struct Outcome {
  double initial_J, first_steps_J, highest_J, final_J;
  long steps;
};

/// A block thrown at a fixed base at 1 % of its wave speed, with a 0.1 % random
/// velocity field on top to excite the shortest waves the grid carries.
Outcome impact(double E, double nu, ShapeFunction shape, int steps) {
  const double rho = 2000.0;
  const double c = ElasticConstants{E, nu}.p_wave_speed(rho);
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.3, 15);
  m.z_nodes_m = testing::nodes(0.0, 0.3, 15);
  m.bodies.push_back(testing::elastic_body("block", E, nu, rho, BoxRegion{0, 0.2, 0, 0.2}, 0.0, -0.01 * c));
  m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
  m.solver.shape_function = shape;
  m.solver.courant = 1.0;
  Simulation s(m);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    s.particles.vr[p] += 1e-3 * c * u(random);
    s.particles.vz[p] += 1e-3 * c * u(random);
  }
  Outcome o{measure(s).total_energy_J(), 0.0, 0.0, 0.0, 0};
  for (int k = 0; k < steps; ++k) {
    s.advance();  // throws StepFailure on NaN
    const double e = measure(s).total_energy_J();
    if (k < 10) {
      o.first_steps_J = std::max(o.first_steps_J, e);
    } else {
      o.highest_J = std::max(o.highest_J, e);
    }
  }
  o.final_J = measure(s).total_energy_J();
  o.steps = s.step;
  return o;
}

}  // namespace

TEST_CASE("elastic block at the CFL limit: no NaN and energy bounded from E = 1 kPa to 200 GPa, nu up to 0.49",
          "[mpm][verification][stability]") {
  for (ShapeFunction shape : {ShapeFunction::gimp, ShapeFunction::linear}) {
    for (double E : {1e3, 2.5e6, 1e9, 2e11}) {
      for (double nu : {0.0, 0.33, 0.49}) {
        Outcome o{};
        REQUIRE_NOTHROW(o = impact(E, nu, shape, 1500));
        INFO((shape == ShapeFunction::gimp ? "GIMP" : "linear")
             << ", E = " << E << " Pa, ν = " << nu << ": energy / initial: first 10 steps ≤ "
             << o.first_steps_J / o.initial_J << ", later ≤ " << o.highest_J / o.initial_J << ", final "
             << o.final_J / o.initial_J);
        // In the impact step the cells at the wall strain at once while FLIP leaves the
        // particles their velocity for that step (the wall nodes' velocity is zero both
        // before and after), so the sampled sum jumps by about Courant × v₀Δt/h of the
        // kinetic energy — measured +9.6 % at Courant 1 on this grid, +3.5 % at 0.5 — and
        // then decays over some tens of steps. Instability would instead grow without
        // bound: after the impact steps the energy must never exceed what they reached,
        // and it must end below the initial energy.
        CHECK(std::isfinite(o.final_J));
        CHECK(o.first_steps_J < 1.15 * o.initial_J);
        CHECK(o.highest_J <= o.first_steps_J);
        CHECK(o.final_J < o.initial_J);
      }
    }
  }
}

TEST_CASE("very soft block (E = 1 kPa) collapsing under its own weight at Courant 1: no NaN, energy bounded",
          "[mpm][verification][stability]") {
  // ρgH = 3.9 kPa > E: strains far beyond 100 %. The geometric stiffness of the
  // stress enters the CFL estimate (mpm/simulation.cpp); without it this run went
  // unstable within 0.3 s.
  const double rho = 2000.0, g = 9.81;
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.6, 30);
  m.z_nodes_m = testing::nodes(0.0, 0.6, 30);
  m.bodies.push_back(testing::elastic_body("block", 1e3, 0.3, rho, BoxRegion{0, 0.2, 0, 0.2}));
  m.gravity_m_s2 = g;
  m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
  m.solver.courant = 1.0;
  Simulation s(m);
  const double released_bound = measure(s).gravity_energy_J;  // all of m g z, an upper bound of what can be released
  double highest_kinetic = 0.0;
  REQUIRE_NOTHROW([&] {
    while (s.time_s < 10.0) {  // the collapse, then about ten elastic periods of the heap
      s.advance();
      highest_kinetic = std::max(highest_kinetic, measure(s).kinetic_energy_J);
    }
  }());
  INFO("highest kinetic energy " << highest_kinetic << " J against m g z₀ = " << released_bound << " J; " << s.step
                                 << " steps, " << s.wall_clamps << " wall clamps");
  CHECK(highest_kinetic < released_bound);
}
