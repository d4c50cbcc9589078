#include <cmath>

#include <catch2/catch.hpp>

#include "drivers/integration_study.hpp"
#include "drivers/point_integrator.hpp"
#include "models/math_constants.hpp"

using namespace ffp;

namespace {

double n_phi(double phi_deg) {
  const double s = std::sin(phi_deg * kDegree);
  return (1 + s) / (1 - s);
}

/// The paper's sand, with E' scaled with confinement from 2500 kPa at 1.72 kPa
/// so that every σ3 fails at the same axial strain.
MohrCoulombParameters sand_mc(double phi_deg, double psi_deg = 5.0, double cell_kPa = 1.72) {
  MohrCoulombParameters p;
  p.elastic = {2.5e6 * cell_kPa / 1.72, 0.33};
  p.friction_angle_rad = phi_deg * kDegree;
  p.dilatancy_angle_rad = psi_deg * kDegree;
  return p;
}

StrainSofteningParameters sand_ssmc(double eta) {
  StrainSofteningParameters p;
  p.elastic = {2.5e6, 0.33};
  p.friction_peak_rad = 39 * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = 5 * kDegree;
  p.softening_factor = eta;
  return p;
}

/// Triaxial at constant cell pressure (kPa); axial strain > 0 compresses, < 0 extends.
PointConfig triaxial(const PointLaw& law, double cell_kPa, double axial_strain, int increments) {
  PointConfig c = drained_triaxial_config(law, 1e3 * cell_kPa, axial_strain, 1e-4, increments);
  if (axial_strain < 0) c.segments[0].target[1] = -axial_strain;  // extension: tension-positive axial strain
  return c;
}

double q_kPa(const PointRecord& r) { return 1e-3 * deviatoric_stress(r.stress); }

}  // namespace

TEST_CASE("elastic moduli are exact on the isotropic and oedometric paths", "[point][elastic]") {
  const ElasticConstants e{2.5e6, 0.33};
  SECTION("isotropic, stress controlled: K = Δp/Δε_v") {
    PointConfig c;
    c.law = LinearElastic(e);
    c.initial_state = initial_state(c.law);
    c.initial_stress << -1e3, -1e3, -1e3, 0, 0, 0;
    PathSegment s;
    s.control = {Control::stress, Control::stress, Control::stress, Control::strain, Control::strain, Control::strain};
    s.target << -101e3, -101e3, -101e3, 0, 0, 0;
    s.increments = 10;
    c.segments = {s};
    const PointHistory h = integrate_point(c);
    const PointRecord& end = h.records.back();
    // Newton stops at 1e-10 of the stress scale; the modulus inherits that accuracy.
    CHECK(100e3 / -trace(end.strain) == Approx(e.bulk_modulus()).epsilon(1e-9));
    CHECK(end.strain[0] == Approx(end.strain[1]).epsilon(1e-12));
  }
  SECTION("oedometric, strain controlled: M = Δσ_a/Δε_a and K0 = ν/(1 − ν)") {
    PointConfig c;
    c.law = LinearElastic(e);
    c.initial_state = initial_state(c.law);
    PathSegment s;
    s.control.fill(Control::strain);
    s.target << 0, -0.01, 0, 0, 0, 0;
    s.increments = 7;
    c.segments = {s};
    const PointHistory h = integrate_point(c);
    const PointRecord& end = h.records.back();
    CHECK(end.stress[1] / -0.01 == Approx(e.constrained_modulus()).epsilon(1e-13));
    CHECK(end.stress[0] / end.stress[1] == Approx(0.33 / 0.67).epsilon(1e-13));
  }
}

TEST_CASE("drained triaxial peak equals σ3(Nφ−1)", "[point][mc]") {
  for (double phi : {30.0, 39.0, 50.0, 60.0}) {
    for (double cell : {0.1, 1.72, 100.0}) {
      CAPTURE(phi, cell);
      const PointHistory h = integrate_point(triaxial(MohrCoulomb(sand_mc(phi, 5.0, cell)), cell, 0.05, 100));
      // Exact return; the lateral stresses are met to Newton's 1e-10 → q to ~1e-9.
      CHECK(q_kPa(h.records.back()) == Approx(cell * (n_phi(phi) - 1)).epsilon(1e-8));
      CHECK(h.max_newton_iterations <= 5);
    }
  }
}

TEST_CASE("drained triaxial extension peak equals σ3(1 − 1/Nφ)", "[point][mc]") {
  for (double phi : {30.0, 39.0, 50.0, 60.0}) {
    for (double cell : {0.1, 1.72, 100.0}) {
      CAPTURE(phi, cell);
      const PointHistory h = integrate_point(triaxial(MohrCoulomb(sand_mc(phi, 5.0, cell)), cell, -0.05, 100));
      CHECK(q_kPa(h.records.back()) == Approx(cell * (1 - 1 / n_phi(phi))).epsilon(1e-8));
      CHECK(h.records.back().region == ReturnRegion::edge_extension);
    }
  }
}

TEST_CASE("drained triaxial plastic flow: dε_v/dε_a = −2 sinψ/(1 − sinψ) at constant stress", "[point][mc]") {
  for (double psi : {0.0, 5.0, 20.0}) {
    const PointHistory h = integrate_point(triaxial(MohrCoulomb(sand_mc(39, psi)), 1.72, 0.05, 100));
    const PointRecord& a = h.records[h.records.size() - 2];
    const PointRecord& b = h.records.back();
    // At failure the stress no longer changes, so the strain increment is all plastic.
    const double ratio = trace(b.strain - a.strain) / (b.strain[1] - a.strain[1]);
    const double s = std::sin(psi * kDegree);
    CHECK(ratio == Approx(-2 * s / (1 - s)).margin(1e-8));
  }
}

TEST_CASE("SSMC strength tends to the residual q_res = σ3(N_φr − 1)", "[point][ssmc]") {
  // η ε_d^p reaches ~30 at ε_a = 4: exp(−30) leaves nothing of the peak.
  const PointHistory h = integrate_point(triaxial(StrainSofteningMohrCoulomb(sand_ssmc(8)), 1.72, 4.0, 4000));
  double peak = 0;
  for (const auto& r : h.records) peak = std::max(peak, q_kPa(r));
  // Softening starts with the first plastic strain: the peak stays just below the MC peak.
  CHECK(peak <= 1.72 * (n_phi(39) - 1) * (1 + 1e-9));
  CHECK(peak > 0.99 * 1.72 * (n_phi(39) - 1));
  CHECK(q_kPa(h.records.back()) == Approx(1.72 * (n_phi(32) - 1)).epsilon(1e-8));
}

TEST_CASE("SSMC: η → large drops abruptly to the residual, η → 0 stays at peak", "[point][ssmc]") {
  const double peak = 1.72 * (n_phi(39) - 1), residual = 1.72 * (n_phi(32) - 1);
  SECTION("η = 10^4: residual within 1 % axial strain") {
    const PointHistory h = integrate_point(triaxial(StrainSofteningMohrCoulomb(sand_ssmc(1e4)), 1.72, 0.01, 1000));
    CHECK(q_kPa(h.records.back()) == Approx(residual).epsilon(1e-6));
  }
  SECTION("η = 10^-6: still at peak after 20 % axial strain") {
    const PointHistory h = integrate_point(triaxial(StrainSofteningMohrCoulomb(sand_ssmc(1e-6)), 1.72, 0.2, 1000));
    // φ loses 7° × η ε_d^p ≈ 7° × 2e-7 at most.
    CHECK(q_kPa(h.records.back()) == Approx(peak).epsilon(1e-5));
  }
}

TEST_CASE("stress-controlled components follow their targets in simple shear", "[point]") {
  PointConfig c;
  c.law = MohrCoulomb(sand_mc(35, 5));
  c.initial_state = initial_state(c.law);
  c.initial_stress << -10e3, -10e3, -10e3, 0, 0, 0;
  PathSegment s;
  s.control = {Control::strain, Control::stress, Control::strain, Control::strain, Control::strain, Control::strain};
  s.target << 0, -10e3, 0, 0.05, 0, 0;
  s.increments = 200;
  c.segments = {s};
  const PointHistory h = integrate_point(c);
  // Newton's contract: |σ22 − target| ≤ 1e-10 of the step's stress scale.
  for (const auto& r : h.records) CHECK(std::abs(r.stress[1] + 10e3) <= 1e-10 * r.stress.cwiseAbs().maxCoeff() * 1.01);
  // Dilatant shear at constant normal stress expands the sample.
  CHECK(trace(h.records.back().strain) > 0.0);
  CHECK(h.records.back().region != ReturnRegion::elastic);
}

TEST_CASE("a stress target beyond the strength fails with the increment, state and a reproducer", "[point]") {
  PointConfig c;
  c.law = StrainSofteningMohrCoulomb(sand_ssmc(8));
  c.initial_state = initial_state(c.law);
  c.initial_stress << -1.72e3, -1.72e3, -1.72e3, 0, 0, 0;
  c.newton.max_iterations = 12;
  PathSegment s;
  s.control.fill(Control::stress);
  s.target << -1.72e3, -20e3, -1.72e3, 0, 0, 0;  // q = 18 kPa > peak 5.84 kPa
  s.increments = 100;
  c.segments = {s};
  PointIntegrationFailure failure("");
  bool failed = false;
  try {
    integrate_point(c);
  } catch (const PointIntegrationFailure& f) {
    failure = f;
    failed = true;
  }
  REQUIRE(failed);
  // The stress ratio σ_a/σ_r = Nφ(39°) = 4.40 is passed at q = 5.84 kPa, i.e. 1/3 of the way.
  CHECK(failure.step > 1);
  CHECK(failure.step <= 100 * 5.84 / 18.28 + 1);
  CHECK(failure.stress_start.allFinite());
  CHECK(std::string(failure.what()).find("increment " + std::to_string(failure.step)) != std::string::npos);
  // Repeating only that increment from the recorded start fails the same way.
  PointConfig again = c;
  again.initial_stress = failure.stress_start;
  again.initial_state = failure.state_start;
  PathSegment one;
  one.control = failure.control;
  one.target = failure.target_stress;
  one.increments = 1;
  again.segments = {one};
  CHECK_THROWS_AS(integrate_point(again), PointIntegrationFailure);
}

TEST_CASE("exact Mohr-Coulomb return: triaxial error does not depend on the increment count", "[point][study]") {
  TriaxialErrorStudy study;
  study.law = MohrCoulomb(sand_mc(39, 5));
  study.increments = {10};
  study.reference_increments = 1000;
  study.min_timing_s = 0.0;
  const TriaxialErrorResult r = run_triaxial_error_study(study);
  // Piecewise-linear exact solution; only the lateral-stress Newton tolerance remains.
  CHECK(r.rows[0].q_error <= 1e-8);
  CHECK(r.rows[0].volumetric_error <= 1e-8);
}

TEST_CASE("SSMC triaxial error shrinks about in proportion to the increment size", "[point][study]") {
  TriaxialErrorStudy study;
  study.law = StrainSofteningMohrCoulomb(sand_ssmc(8));
  study.increments = {20, 200};
  study.reference_increments = 20000;  // its own error, ~1/1000 of the 20-increment run's, hardly matters
  study.min_timing_s = 0.0;
  const TriaxialErrorResult r = run_triaxial_error_study(study);
  // Backward Euler in the hardening variable is first order: ×10 increments → ≈ ÷10 error.
  CHECK(r.rows[1].q_error < r.rows[0].q_error / 5);
  CHECK(r.rows[1].q_error > r.rows[0].q_error / 20);
  CHECK(r.rows[1].volumetric_error < r.rows[0].volumetric_error / 5);
}

TEST_CASE("iso-error map: one increment inside the elastic range is exact", "[point][study]") {
  IsoErrorMapStudy m;
  m.law = MohrCoulomb(sand_mc(39, 5));
  m.start = MapStart::edge;
  m.points_x = 3;
  m.points_y = 3;
  m.reference_substeps = 50;
  const IsoErrorMap map = run_iso_error_map(m);
  REQUIRE(map.error.size() == 9);
  CHECK(map.error[1 * 3 + 0] == 0.0);  // x = y = 0: no increment at all
  for (double e : map.error) CHECK(std::isfinite(e));
  CHECK(*std::max_element(map.error.begin(), map.error.end()) > 1e-6);  // large increments do err
}
