/// Free flight and free fall of an elastic block: nothing but inertia and gravity.
#include <catch2/catch.hpp>

#include <cmath>

#include "mpm/diagnostics.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

Simulation block(std::optional<double> gravity, double vz, ShapeFunction shape, Transfer transfer) {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.3, 15);
  m.z_nodes_m = testing::nodes(0.0, 2.0, 100);
  m.bodies.push_back(testing::elastic_body("block", 1e6, 0.3, 1000.0, BoxRegion{0.0, 0.2, 1.2, 1.4}, 0.0, vz));
  m.boundaries = {Fixity::roller, Fixity::free, Fixity::free, Fixity::free};
  m.gravity_m_s2 = gravity;
  m.solver.shape_function = shape;
  m.solver.transfer = transfer;
  return Simulation(m);
}

}  // namespace

TEST_CASE("free flight and free fall: mass exact, momentum to round-off, position on the trajectory",
          "[mpm][verification][free_fall]") {
  const double g = 9.81, v0 = 1.5;
  auto check = [&](std::optional<double> gravity, ShapeFunction shape, Transfer transfer) {
    Simulation s = block(gravity, v0, shape, transfer);
    const Diagnostics start = measure(s);
    const std::vector<double> mass = s.particles.mass;
    const double ga = gravity.value_or(0.0);
    // The scheme's own trajectory (symplectic Euler with the steps actually taken):
    // v ← v − gΔt, z ← z + Δt v.
    double v = v0, dz = 0.0, dt_max = 0.0;
    while (s.time_s < 0.2) {
      const double dt = s.dt_s;
      s.advance();
      v -= ga * dt;
      dz += dt * v;
      dt_max = std::max(dt_max, dt);
    }
    const double t = s.time_s;
    const Diagnostics end = measure(s);
    CHECK(s.particles.mass == mass);  // bit for bit: mass is never recomputed
    CHECK(end.mass_kg == start.mass_kg);
    // Momentum: p(t) = p(0) − M g t, to round-off (relative 1e-12 of |p|).
    const double expected_p = start.momentum_z_N_s - start.mass_kg * ga * t;
    CHECK(end.momentum_z_N_s == Approx(expected_p).epsilon(1e-12).margin(1e-12 * std::abs(start.momentum_z_N_s)));
    double worst_discrete = 0.0, worst_exact = 0.0, worst_r = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      worst_discrete = std::max(worst_discrete, std::abs(s.particles.z[p] - (s.particles.z0[p] + dz)));
      worst_exact = std::max(worst_exact, std::abs(s.particles.z[p] - (s.particles.z0[p] + v0 * t - 0.5 * ga * t * t)));
      worst_r = std::max(worst_r, std::abs(s.particles.r[p] - s.particles.r0[p]));
      CHECK(s.particles.vz[p] == Approx(v).epsilon(1e-12));
    }
    INFO("t = " << t << " s, " << s.step << " steps: |z − discrete| " << worst_discrete << " m, |z − z₀ − v₀t + gt²/2| "
                << worst_exact << " m, |Δr| " << worst_r << " m");
    CHECK(worst_discrete < 1e-12);
    CHECK(worst_r < 1e-12);
    // Symplectic Euler is first order: it differs from the parabola by ½ g t Δt at most.
    CHECK(worst_exact <= 0.5 * ga * t * dt_max + 1e-12);
  };
  SECTION("free flight, GIMP, MUSL") { check(std::nullopt, ShapeFunction::gimp, Transfer::musl); }
  SECTION("free fall, GIMP, MUSL") { check(g, ShapeFunction::gimp, Transfer::musl); }
  SECTION("free fall, linear, MUSL") { check(g, ShapeFunction::linear, Transfer::musl); }
  SECTION("free fall, GIMP, USL") { check(g, ShapeFunction::gimp, Transfer::usl); }
}
