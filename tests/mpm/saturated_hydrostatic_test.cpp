/// A saturated column at rest under gravity: hydrostatic pore pressure p = γ_w z and
/// buoyant effective stress σ'_v = γ' z (γ' = γ_sat − γ_w), σ'_h = K0 σ'_v, z the depth;
/// neither phase moves.
#include <catch2/catch.hpp>

#include <cmath>

#include "mpm/simulation.hpp"
#include "saturated_column.hpp"

using namespace ffp;
using namespace ffp::mpm;

TEST_CASE("hydrostatic saturated column stays at p = gamma_w z, sigma'_v = gamma' z and at rest for 2,000 steps",
          "[mpm][verification][saturated]") {
  auto check = [](testing::SaturatedColumn c) {
    c.gravity_m_s2 = 9.81;
    Simulation s(c.model());
    REQUIRE(s.two_phase);
    const TwoPhase& t = *s.two_phase;
    const double g = 9.81, H = c.height_m, gamma_w = c.fluid_density_kg_m3() * g;
    const double gamma_buoyant = (c.saturated_density_kg_m3() - c.fluid_density_kg_m3()) * g;
    for (int k = 0; k < 2000; ++k) s.advance();
    double worst_p = 0.0, worst_v = 0.0, worst_h = 0.0, fastest = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      const double depth = H - s.particles.z0[p];
      const Voigt& sig = s.particles.stress[p];
      worst_p = std::max(worst_p, std::abs(t.pore_pressure[p] - gamma_w * depth));
      worst_v = std::max(worst_v, std::abs(-sig[1] - gamma_buoyant * depth));
      worst_h = std::max({worst_h, std::abs(-sig[0] - c.k0 * gamma_buoyant * depth),
                          std::abs(-sig[2] - c.k0 * gamma_buoyant * depth)});
      fastest = std::max(
          {fastest, std::hypot(s.particles.vr[p], s.particles.vz[p]), std::hypot(t.liquid_vr[p], t.liquid_vz[p])});
    }
    const double scale = c.saturated_density_kg_m3() * g * H;  // γ_sat H, the largest total stress
    INFO("after " << s.step << " steps (t = " << s.time_s << " s, Δt = " << s.dt_s << " s): max |Δp| " << worst_p
                  << " Pa, |Δσ'_v| " << worst_v << " Pa, |Δσ'_h| " << worst_h << " Pa against γ_sat H = " << scale
                  << " Pa; fastest phase " << fastest << " m/s");
    // Particles at the cells' quadrature points make this state an exact discrete
    // equilibrium of both phases (the liquid's Σ V p G balances M_w g node by node, the
    // mixture's total stress balances (M_s + M̄_w) g, and the hoop terms cancel the radial
    // divergence), so what is left is round-off: 1e-9 γ_sat H is a million times what
    // it gives and a millionth of what a missing buoyancy, hoop or weight term would.
    CHECK(worst_p < 1e-9 * scale);
    CHECK(worst_v < 1e-9 * scale);
    CHECK(worst_h < 1e-9 * scale);
    // A speed of 1e-9 m/s held over the run moves nothing measurable (< 1e-12 m).
    CHECK(fastest < 1e-9);
  };
  testing::SaturatedColumn column;
  SECTION("GIMP, impermeable base") { check(column); }
  SECTION("linear hats, impermeable base") {
    column.shape = ShapeFunction::linear;
    check(column);
  }
  SECTION("GIMP, drained base (the fluid beyond holds the base's hydrostatic pressure)") {
    column.bottom = Drainage::drained;
    check(column);
  }
}

TEST_CASE("a saturated body's initial excess pore pressure adds to the hydrostatic one at every particle",
          "[mpm][saturated]") {
  testing::SaturatedColumn c;
  c.gravity_m_s2 = 9.81;
  ModelDescription m = c.model();
  m.bodies[0].saturated->initial_excess_pressure_Pa = 1234.5;
  const Simulation s(m);
  const TwoPhase& t = *s.two_phase;
  const double gamma_w = c.fluid_density_kg_m3() * 9.81;
  double worst = 0.0;
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    worst = std::max(worst, std::abs(t.pore_pressure[p] - gamma_w * (c.height_m - s.particles.z[p]) - 1234.5));
    CHECK(t.excess_pressure(s.particles, p) == Approx(1234.5).epsilon(1e-12));
    CHECK(t.liquid_pressure[p] == t.pore_pressure[p]);  // no vapour at the start
  }
  CHECK(worst < 1e-9);
}
