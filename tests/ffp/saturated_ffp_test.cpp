/// The penetrometer in a saturated sand (mpm/rigid_penetrometer.hpp, mpm/cone_pore_pressure.hpp):
/// a sand at rest under a resting body stays hydrostatic, the pore water does not flow into the
/// cone, the reaction holds the pore pressure, and u1/u2 average the particles docs/outputs.md
/// names. Coarse meshes (2 cm) keep each case to seconds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "coarse_ffp.hpp"
#include "models/math_constants.hpp"
#include "mpm/cone_pore_pressure.hpp"
#include "mpm/ffp_model.hpp"

using namespace ffp;
using namespace ffp::mpm;
using ffp::test::coarse_ffp;

namespace {

constexpr double kWaterDepth_m = 1.0;

/// The coarse reference sand saturated (n = 0.44, k = 1e-4 m/s) under 1 m of water.
FfpDescription saturated_ffp() {
  FfpDescription d = coarse_ffp();
  d.soil.saturated = SaturatedSoil{0.44, 1e-4, PermeabilityLaw::constant};
  d.soil.water_depth_m = kWaterDepth_m;
  return d;
}

/// The largest |p_e| of the saturated particles (Pa).
double largest_excess(const FfpRun& run) {
  const Simulation& s = run.simulation();
  double largest = 0.0;
  for (std::size_t p = 0; p < s.particles.size(); ++p)
    largest = std::max(largest, std::abs(s.two_phase->excess_pressure(s.particles, p)));
  return largest;
}

}  // namespace

TEST_CASE("saturated sand at rest under a resting penetrometer stays hydrostatic, the body carrying its buoyancy",
          "[ffp][saturated]") {
  FfpDescription d = saturated_ffp();
  d.prescribed = true;  // held still, its tip on the surface
  d.velocity_m_s = 0.0;
  FfpRun run(d);
  const double depth_pressure = 1000.0 * 9.81 * (kWaterDepth_m + d.soil.depth_m);  // p_h at the base
  REQUIRE(largest_excess(run) == 0.0);
  while (run.simulation().time_s < 0.01) run.advance();  // 40 undrained wave crossings of the chamber
  const double excess = largest_excess(run);
  INFO("largest |p_e| after 10 ms: " << excess << " Pa; p_h at the base " << depth_pressure << " Pa");
  // The K0 start is the continuum's equilibrium, not exactly the grid's (nor is the apex's touch
  // nothing): the nearly undrained water feels what settles as a small excess (measured 2e-5 of
  // p_h at the base). 1e-3 of it, 14 Pa, is far below any impact's hundreds of kPa; water pushed
  // through the cone or a wrong hydrostatic start would show at once.
  CHECK(excess < 1e-3 * depth_pressure);
  // Nothing pushes the body but the water: its reaction is the buoyancy ρ_w g V.
  const double buoyancy = 1000.0 * 9.81 * d.shape.volume_m3();
  CHECK(run.state().buoyancy_N == Approx(buoyancy).epsilon(1e-5));
  CHECK(std::abs(run.state().reaction_N - buoyancy) < 0.02 * buoyancy);
}

TEST_CASE("saturated sand: the cone is impermeable, the pore water's normal velocity never enters it",
          "[ffp][saturated]") {
  FfpDescription d = saturated_ffp();
  d.prescribed = true;  // pushed at 1 m/s, so the contact acts every step
  d.velocity_m_s = -1.0;
  FfpRun run(d);
  std::size_t held = 0;
  double worst = 0.0;
  for (int step = 0; step < 400; ++step) {
    run.advance();
    const Simulation& s = run.simulation();
    const NodalField& w = s.two_phase->liquid;
    for (const ContactNode& c : run.rigid()->nodes()) {
      if (!(w.mass[c.node] > s.mass_floor_kg)) continue;
      // (v_w − v_body)·n < 0 would be water flowing into the body.
      const double relative = w.velocity_new_r[c.node] * c.normal.r + (w.velocity_new_z[c.node] + 1.0) * c.normal.z;
      worst = std::min(worst, relative);
      held += std::abs(relative) < 1e-12;
    }
  }
  INFO("most negative (v_w − v_body)·n: " << worst << " m/s over " << held << " held node-steps");
  CHECK(worst > -1e-12);  // round-off of a 1 m/s velocity
  CHECK(held >= 400);     // the constraint acts: at least one node per step on average
}

TEST_CASE("saturated sand: a flat punch on an undrained layer carries the pore pressure over its area",
          "[ffp][saturated]") {
  // A weightless linear elastic layer (no hydrostatic part: the pore pressure is all excess) pushed by
  // a flat punch at 5 mm/s for 4 ms: c_v t/H² = 0.13 m²/s × 4 ms/(0.4 m)² = 0.003, undrained.
  FfpDescription d = saturated_ffp();
  d.gravity_m_s2 = 0.0;
  d.soil.law = LinearElastic(ElasticConstants{1e7, 0.3});
  d.shape.cone_apex_angle_rad = kPi;
  d.shape.edge_radius_m = 0.0;
  d.mesh.edge_offset_cells = 0.5;
  d.prescribed = true;
  d.velocity_m_s = -0.005;
  d.soil.water_depth_m = 0.0;
  FfpRun run(d);
  double impulse0 = 0.0, t0 = 0.0;
  while (run.simulation().time_s < 0.004) {
    if (impulse0 == 0.0 && run.simulation().time_s >= 0.003)
      impulse0 = run.state().impulse_N_s, t0 = run.simulation().time_s;
    run.advance();
  }
  const Simulation& s = run.simulation();
  const double reaction = (run.state().impulse_N_s - impulse0) / (s.time_s - t0);  // mean over the last ms
  // The total stress on the face, from the particles of the top cell under it: per radian the face
  // area ∫ r dr is Σ V_p/h over the cell's particles, so F = 2π Σ V_p (p_p − σ'_zz,p)/h.
  const double h = d.mesh.min_cell_m, R = d.shape.base_radius_m, tip = run.tip_z_m();
  double pore = 0.0, effective = 0.0;
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    if (s.particles.r[p] > R || s.particles.z[p] < tip - h || s.particles.z[p] > tip) continue;
    pore += kTwoPi * s.particles.volume[p] * s.two_phase->pore_pressure[p] / h;
    effective += kTwoPi * s.particles.volume[p] * -s.particles.stress[p][1] / h;
  }
  INFO("reaction " << reaction << " N; top cell under the face: pore pressure " << pore << " N, effective " << effective
                   << " N; the pore water's impulse " << run.state().pore_water_impulse_N_s << " N s");
  // Undrained (Skempton's B ≈ 1), the water takes the mean total stress: a third of σ_zz under a
  // uniaxial load, all of it under an isotropic one; under the face, with the sides held, between.
  CHECK(pore > 0.3 * (pore + effective));
  // The reaction is the total stress's, the water's included, within the top cell's sampling.
  CHECK(reaction == Approx(pore + effective).epsilon(0.15));
  CHECK(reaction > 1.5 * effective);  // the skeleton's part alone falls far short
  CHECK(run.state().pore_water_impulse_N_s > 0.0);
}

TEST_CASE("u1 and u2 average the saturated particles touching the cone's lower half and the shaft above it",
          "[ffp][saturated]") {
  FfpDescription d = saturated_ffp();
  d.prescribed = true;
  d.velocity_m_s = -2.0;
  FfpRun run(d);
  const double g_w = 1000.0 * 9.81, h = d.mesh.min_cell_m, H = d.shape.cone_height_m();
  SECTION("at the impact: u1 from the sand under the apex, u2 the water above the surface") {
    const ConePorePressure u = cone_pore_pressure(run);
    REQUIRE(u.u1.particles > 0);
    // Hydrostatic particles within a cell below the apex: between the surface's and a cell deeper.
    CHECK(u.u1.excess_Pa == 0.0);
    CHECK(u.u1.pressure_Pa > g_w * kWaterDepth_m);
    CHECK(u.u1.pressure_Pa < g_w * (kWaterDepth_m + h));
    CHECK(u.u2.particles == 0);
    CHECK(u.u2.pressure_Pa == Approx(g_w * (kWaterDepth_m - H - h)).epsilon(1e-12));
  }
  SECTION("the cone in the sand: each region's own particles, no others") {
    while (run.penetration_m() < H + 3.0 * h) run.advance();
    Simulation& s = run.simulation();
    TwoPhase& t = *s.two_phase;
    const double tip = run.tip_z_m();
    // Marked pressures: 1 kPa on the cone's lower half, 2 kPa beside the shaft's first two cells,
    // 1 MPa elsewhere; the means are exact only if no other particle enters them.
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      const double z = s.particles.z[p];
      const bool touching = run.geometry().query(s.particles.r[p], z, tip).signed_distance_m <= h;
      double marked = 1e6;
      if (touching && z <= tip + 0.5 * H) marked = 1e3;
      if (touching && z >= tip + H && z <= tip + H + 2.0 * h) marked = 2e3;
      t.set_pore_pressure(p, marked);
    }
    const ConePorePressure u = cone_pore_pressure(run);
    REQUIRE(u.u1.particles > 0);
    REQUIRE(u.u2.particles > 0);
    CHECK(u.u1.pressure_Pa == Approx(1e3).epsilon(1e-12));
    CHECK(u.u2.pressure_Pa == Approx(2e3).epsilon(1e-12));
  }
}
