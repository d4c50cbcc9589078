/// The drained triaxial element test (drivers/triaxial_test.hpp): strength,
/// the force–displacement work against closed forms, and the work balance.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "drivers/triaxial_test.hpp"
#include "models/math_constants.hpp"

using namespace ffp;

namespace {

double n_phi(double phi_deg) {
  const double s = std::sin(phi_deg * kDegree);
  return (1 + s) / (1 - s);
}

MohrCoulombParameters sand_mc(double phi_deg, double psi_deg, double E_Pa = 2.5e6) {
  MohrCoulombParameters p;
  p.elastic = {E_Pa, 0.33};
  p.friction_angle_rad = phi_deg * kDegree;
  p.dilatancy_angle_rad = psi_deg * kDegree;
  return p;
}

StrainSofteningParameters sand_ssmc(double eta, double psi_deg = 5.0) {
  StrainSofteningParameters p;
  p.elastic = {2.5e6, 0.33};
  p.friction_peak_rad = 39 * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = psi_deg * kDegree;
  p.softening_factor = eta;
  return p;
}

TriaxialTestConfig test_of(const PointLaw& law, double cell_kPa, double axial_strain_max, int increments) {
  TriaxialTestConfig c;
  c.law = law;
  c.cell_pressure_Pa = 1e3 * cell_kPa;
  c.axial_strain_max = axial_strain_max;
  c.increments = increments;
  return c;
}

}  // namespace

TEST_CASE("triaxial element test: Mohr-Coulomb peak equals σ3(Nφ−1), reached at ε_a = q_f/E", "[triaxial][mc]") {
  for (double cell : {1.72, 10.0, 100.0}) {
    for (double phi : {30.0, 39.0, 45.0}) {
      CAPTURE(cell, phi);
      const double E = 2.5e6 * cell / 1.72;  // same failure strain at every σ3
      const int increments = 1000;
      const TriaxialResult r = run_triaxial_test(test_of(MohrCoulomb(sand_mc(phi, 5.0, E)), cell, 0.05, increments));
      const double q_f = 1e3 * cell * (n_phi(phi) - 1);
      // The exact return puts q on the surface; Newton holds σ3 to 1e-10 of the stress.
      CHECK(r.peak_q_Pa == Approx(q_f).epsilon(1e-9));
      CHECK(r.residual_q_Pa == Approx(q_f).epsilon(1e-9));
      // Elastic until q_f/E: the first increment at or past it carries the peak.
      const double h = 0.05 / increments;
      CHECK(r.axial_strain_at_peak >= q_f / E - 1e-12);
      CHECK(r.axial_strain_at_peak <= q_f / E + h + 1e-12);
    }
  }
}

TEST_CASE(
    "force–displacement area of elastic–perfectly plastic MC equals the closed form less the trapezoid's deficit at "
    "the kink",
    "[triaxial][mc][work]") {
  // F(δ) is piecewise linear: slope E·A/H up to q_f·A at δ_y = H q_f/E, then flat.
  // W_exact = V [q_f²/(2E) + q_f (ε_max − q_f/E)]. The trapezoid on the increments
  // is exact on both straight parts; in the increment [a, a + h] holding the kink
  // at a + t it cuts the corner by V·E·t(h − t)/2 (≤ V·E h²/8).
  const double E = 2.5e6, cell = 1.72e3, eps_max = 0.1;
  for (int increments : {10, 37, 200, 1000}) {
    for (double psi : {0.0, 5.0}) {
      CAPTURE(increments, psi);
      TriaxialTestConfig c = test_of(MohrCoulomb(sand_mc(39, psi, E)), 1e-3 * cell, eps_max, increments);
      const TriaxialResult r = run_triaxial_test(c);
      const double V = c.specimen.volume_m3();
      const double q_f = cell * (n_phi(39) - 1);
      const double eps_y = q_f / E;
      const double exact = V * (q_f * q_f / (2 * E) + q_f * (eps_max - eps_y));
      const double h = eps_max / increments;
      const double t = eps_y - h * std::floor(eps_y / h);
      const double deficit = V * E * t * (h - t) / 2;
      // Only rounding and Newton's 1e-10 on σ3 remain.
      CHECK(r.dissipated_work_J_total == Approx(exact - deficit).epsilon(1e-9));
      CHECK(deficit <= V * E * h * h / 8 * (1 + 1e-12));
      // F and δ are q·A and ε_a·H of the same specimen.
      CHECK(r.axial_force_N.back() == Approx(q_f * c.specimen.area_m2()).epsilon(1e-9));
      CHECK(r.axial_displacement_m.back() == Approx(eps_max * 0.15).epsilon(1e-12));
      CHECK(c.specimen.area_m2() == Approx(kPi * 0.035 * 0.035).epsilon(1e-15));
    }
  }
}

TEST_CASE("piston work equals plastic work + stored elastic energy − cell pressure work", "[triaxial][work]") {
  // Per unit volume σ:dε = q dε_a + σ3 dε_v (compression positive) and
  // σ:dε = σ:dε^p + d(½ σ:C:σ): an identity of the mid-increment rule the
  // integrator and the trapezoid share, so it holds to rounding (1e-12 of W).
  SECTION("SSMC, dilating (ψ_p = 5°): the cell does negative work") {
    const TriaxialResult r = run_triaxial_test(test_of(StrainSofteningMohrCoulomb(sand_ssmc(8)), 1.72, 0.2, 2000));
    const double balance = r.plastic_work_J_total + r.elastic_energy_change_J - r.cell_work_J;
    CHECK(r.dissipated_work_J_total == Approx(balance).epsilon(1e-9));
    CHECK(r.cell_work_J < 0.0);
    CHECK(r.volumetric_strain.back() < 0.0);
    // Not a trivial identity: the piston work exceeds the law's dissipation by
    // the dilation against the cell (here ~3 %).
    CHECK(r.dissipated_work_J_total > 1.02 * r.plastic_work_J_total);
  }
  SECTION("MC without dilatancy: no volume change in plastic flow; W − W_p is the elastic part") {
    const TriaxialResult r = run_triaxial_test(test_of(MohrCoulomb(sand_mc(39, 0)), 1.72, 0.2, 500));
    CHECK(r.dissipated_work_J_total ==
          Approx(r.plastic_work_J_total + r.elastic_energy_change_J - r.cell_work_J).epsilon(1e-9));
    CHECK(r.elastic_energy_change_J > 0.0);
  }
  SECTION("linear elastic: no plastic work, W = ΔU − σ3 V ε_v exactly") {
    const TriaxialResult r = run_triaxial_test(test_of(LinearElastic({2.5e6, 0.33}), 1.72, 0.01, 50));
    CHECK(std::abs(r.plastic_work_J_total) <= 1e-12 * r.dissipated_work_J_total);
    CHECK(r.dissipated_work_J_total == Approx(r.elastic_energy_change_J - r.cell_work_J).epsilon(1e-9));
    // Drained elastic triaxial: W = V E ε²/2 for q = E ε_a.
    CHECK(r.dissipated_work_J_total == Approx(0.5 * 2.5e6 * 1e-4 * 0.15 * kPi * 0.035 * 0.035).epsilon(1e-9));
  }
}

TEST_CASE("SSMC element test: the peak tends to σ3(Nφp−1) from below as Δε_a → 0, then q softens to σ3(Nφr−1)",
          "[triaxial][ssmc]") {
  // The continuum peak is q_p at first yield (κ = 0). The increment that
  // crosses yield already softens over its plastic part, so the recorded peak
  // lies below q_p by O(η Δε_a): first order in the increment.
  const double q_p = 1.72e3 * (n_phi(39) - 1);
  const TriaxialResult coarse = run_triaxial_test(test_of(StrainSofteningMohrCoulomb(sand_ssmc(50)), 1.72, 0.3, 3000));
  const TriaxialResult fine = run_triaxial_test(test_of(StrainSofteningMohrCoulomb(sand_ssmc(50)), 1.72, 0.3, 30000));
  CHECK(coarse.peak_q_Pa <= q_p * (1 + 1e-12));
  CHECK(fine.peak_q_Pa <= q_p * (1 + 1e-12));
  CHECK(q_p - fine.peak_q_Pa < 0.2 * (q_p - coarse.peak_q_Pa));
  CHECK(fine.peak_q_Pa == Approx(q_p).epsilon(5e-4));
  const TriaxialResult& r = coarse;
  // exp(−50 κ) with κ of order ε_a = 0.3: the residual friction to ~1e-6.
  CHECK(r.residual_q_Pa == Approx(1.72e3 * (n_phi(32) - 1)).epsilon(1e-5));
  for (std::size_t i = 1; i < r.dissipated_work_J.size(); ++i)
    REQUIRE(r.dissipated_work_J[i] > r.dissipated_work_J[i - 1]);
}

TEST_CASE("area_under is the exact area of the polyline, cut by interpolation at the ends", "[triaxial][work]") {
  const std::vector<double> x = {0.0, 1.0, 3.0, 4.0};
  const std::vector<double> y = {0.0, 2.0, 2.0, -2.0};
  CHECK(area_under(x, y, 0.0, 4.0) == Approx(1.0 + 4.0 + 0.0).epsilon(1e-15));
  // [0.5, 3.5]: 0.5·(1 + 2)/2 + 4 + 0.5·(2 + 0)/2.
  CHECK(area_under(x, y, 0.5, 3.5) == Approx(0.75 + 4.0 + 0.5).epsilon(1e-15));
  CHECK(area_under(x, y, 2.0, 2.0) == 0.0);
  CHECK_THROWS_AS(area_under(x, y, -0.1, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(area_under(x, y, 0.0, 4.1), std::invalid_argument);
  CHECK(interpolate_linear(x, y, 3.25) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("triaxial element test rejects what is not a test", "[triaxial]") {
  TriaxialTestConfig c = test_of(MohrCoulomb(sand_mc(39, 5)), 1.72, 0.1, 10);
  c.cell_pressure_Pa = 0.0;
  CHECK_THROWS_AS(run_triaxial_test(c), std::invalid_argument);
  c = test_of(MohrCoulomb(sand_mc(39, 5)), 1.72, 0.1, 0);
  CHECK_THROWS_AS(run_triaxial_test(c), std::invalid_argument);
}
