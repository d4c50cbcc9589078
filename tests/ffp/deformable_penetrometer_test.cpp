/// The deformable alternative (paper section 5.1, Fig. 7): a linear elastic
/// FFP in two-body contact with the soil. It must conserve momentum node by
/// node, agree with the rigid body where the paper says they agree, and stay
/// stable as stiff as steel at the time step its p-wave needs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/ffp_model.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

FfpDescription coarse(std::optional<double> modulus_Pa) {
  FfpDescription d;
  d.soil.law = MohrCoulomb(MohrCoulombParameters{ElasticConstants{2.5e6, 0.33}, 39.0 * kDegree, 0.0, 0.0});
  d.mesh.min_cell_m = 0.02;
  d.mesh.max_cell_m = 0.06;
  d.mesh.below_cell_m = 0.04;
  d.contact.friction = std::tan(20.0 * kDegree);
  if (modulus_Pa) d.deformable = DeformableFfp{*modulus_Pa, 0.0, 2, 2};  // paper Fig. 7: ν = 0
  return d;
}

struct Sample {
  double t, depth, velocity;
};

std::vector<Sample> history(FfpRun& run, double end_s, double every_s) {
  std::vector<Sample> out;
  Simulation& s = run.simulation();
  double next = every_s;
  while (s.time_s < end_s) {
    run.advance();
    if (s.time_s >= next) {
      out.push_back({s.time_s, run.penetration_m(), run.velocity_down_m_s()});
      next += every_s;
    }
  }
  return out;
}

/// Linear interpolation of a sampled quantity at t.
double at(const std::vector<Sample>& h, double t, double Sample::*q) {
  auto it = std::lower_bound(h.begin(), h.end(), t, [](const Sample& s, double x) { return s.t < x; });
  if (it == h.begin()) return (*it).*q;
  if (it == h.end()) return h.back().*q;
  const Sample &b = *it, &a = *(it - 1);
  return a.*q + (b.*q - a.*q) * (t - a.t) / (b.t - a.t);
}

}  // namespace

TEST_CASE("elastic FFP: the soil gains exactly the momentum the FFP's particles lose (weightless, 2 ms)",
          "[ffp][deformable][momentum]") {
  // Each node's correction conserves momentum (m_f Δv_f = −m_s Δv_s), and the
  // transfers conserve it too, so before any disturbance reaches the fixed
  // bottom (see the rigid case) the two bodies' momenta change by opposite amounts.
  FfpDescription d = coarse(20e6);
  d.gravity_m_s2 = 0.0;
  FfpRun run(d);
  Simulation& s = run.simulation();
  const double ffp0 = measure_body(s, 1).momentum_z_N_s;
  while (s.time_s < 0.002) run.advance();
  const double soil = measure_body(s, 0).momentum_z_N_s, ffp = measure_body(s, 1).momentum_z_N_s;
  INFO("FFP momentum change " << ffp - ffp0 << " N s, soil momentum " << soil << " N s, ∫R dt "
                              << run.state().impulse_N_s);
  REQUIRE(ffp - ffp0 > 0.1);  // a real exchange
  CHECK(soil == Approx(-(ffp - ffp0)).epsilon(1e-5));
  // The reported reaction is that exchange (exact: the FFP's own forces sum to zero).
  CHECK(run.state().impulse_N_s == Approx(ffp - ffp0).epsilon(1e-10));
}

TEST_CASE("rigid and elastic (20 MPa, nu = 0) FFPs agree in depth and velocity like the paper's Fig. 7 (2 cm)",
          "[ffp][deformable][fig7]") {
  // Both meet the soil on the same outline (detection 0). The elastic body
  // shortens by F L/(E A) ≈ 1100 N · 0.5 m / (20 MPa · 60 cm²) ≈ 5 mm at the peak
  // and its outline is placed at its centre of mass, so depths may differ by
  // that much: 5 mm; the velocities by the vibration the impact excites, whose
  // amplitude at the tip is about F/(ρ c A) ≈ 1100/(2440 · 90 · 0.006) ≈ 0.8 m/s
  // and less at the centre of mass: 0.3 m/s. Up to 0.08 s, the end of the
  // penetration (on this coarse mesh the elastic body later lifts off slowly,
  // see the report; at 1 cm it does not).
  FfpRun rigid(coarse(std::nullopt)), elastic(coarse(20e6));
  const auto a = history(rigid, 0.08, 0.001), b = history(elastic, 0.08, 0.001);
  double depth = 0.0, velocity = 0.0;
  for (const Sample& s : a) {
    depth = std::max(depth, std::abs(s.depth - at(b, s.t, &Sample::depth)));
    velocity = std::max(velocity, std::abs(s.velocity - at(b, s.t, &Sample::velocity)));
  }
  INFO("largest differences: depth " << depth << " m, velocity " << velocity << " m/s; at 0.08 s rigid "
                                     << a.back().depth << " m, elastic " << b.back().depth << " m");
  CHECK(depth < 0.005);
  CHECK(velocity < 0.3);
}

TEST_CASE("a steel FFP (200 GPa) is stable at the time step of its p-wave and follows the rigid one (2 cm, 4 ms)",
          "[ffp][deformable][steel]") {
  FfpDescription d = coarse(200e9);
  FfpRun steel(d);
  Simulation& s = steel.simulation();
  const double h = d.mesh.min_cell_m;
  // c_p = √(E/ρ) with ν = 0 and ρ = M/V ≈ 2440 kg/m³: ~9 km/s, so Δt ≈ C h / c_p ≈ 1e-6 s.
  const double c_p = std::sqrt(200e9 * s.particles.volume[s.groups[1].begin] / s.particles.mass[s.groups[1].begin]);
  CHECK(s.dt_s <= 0.5 * h / c_p * (1.0 + 1e-12));
  const auto a = history(steel, 0.004, 0.0005);
  FfpRun rigid(coarse(std::nullopt));
  const auto b = history(rigid, 0.004, 0.0005);
  const Diagnostics body = measure_body(s, 1);
  INFO("after " << s.step << " steps: steel depth " << a.back().depth << " m, rigid " << b.back().depth
                << " m; steel velocity " << a.back().velocity << " m/s, rigid " << b.back().velocity << " m/s");
  CHECK(s.step > 3000);
  CHECK(std::isfinite(body.kinetic_energy_J));
  // Stable: no energy from nowhere (the body only loses kinetic energy to the soil and gains m g Δz).
  CHECK(body.kinetic_energy_J + body.strain_energy_J < 0.5 * 7.71 * 5.6 * 5.6 + 7.71 * 9.81 * a.back().depth);
  // Agreement: 2 mm in depth (elastic shortening ~F L/(EA) is 5 µm here; the rest is the two contact
  // models' different sampling of the tip on a 2 cm mesh) and 2 % of the impact speed.
  CHECK(std::abs(a.back().depth - b.back().depth) < 0.002);
  CHECK(std::abs(a.back().velocity - b.back().velocity) < 0.02 * 5.6);
}
