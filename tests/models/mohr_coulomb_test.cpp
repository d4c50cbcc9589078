#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <catch2/catch.hpp>

#include "models/elastic.hpp"
#include "models/math_constants.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/principal_stress.hpp"
#include "tensor_test_helpers.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {

MohrCoulombParameters sand(double phi_deg = 39.0, double psi_deg = 5.0, double cohesion_Pa = 0.0, double nu = 0.33,
                           double E_Pa = 2.5e6) {
  MohrCoulombParameters p;
  p.elastic = {E_Pa, nu};
  p.friction_angle_rad = phi_deg * kDegree;
  p.dilatancy_angle_rad = psi_deg * kDegree;
  p.cohesion_Pa = cohesion_Pa;
  return p;
}

/// Δε^p = Δε − C Δσ.
Voigt plastic_strain(const ElasticConstants& e, const Voigt& strain_increment, const Voigt& stress_increment) {
  Voigt elastic = deviator(stress_increment) / (2.0 * e.shear_modulus());
  for (int i = 0; i < 3; ++i) elastic[i] += trace(stress_increment) / (9.0 * e.bulk_modulus());
  return strain_increment - elastic;
}

/// Triaxial state (axial = component 22), compression positive inputs, tension positive result.
Voigt triaxial(double radial_kPa, double axial_kPa) {
  Voigt s = Voigt::Zero();
  s << -1e3 * radial_kPa, -1e3 * axial_kPa, -1e3 * radial_kPa, 0, 0, 0;
  return s;
}

double flow_factor_nphi(double phi_deg) {
  const double s = std::sin(phi_deg * kDegree);
  return (1 + s) / (1 - s);
}

}  // namespace

TEST_CASE("a trial inside the surface is elastic and exact", "[mc]") {
  const MohrCoulomb mc(sand());
  Voigt stress = triaxial(100.0, 150.0);
  Voigt increment = Voigt::Zero();
  increment[1] = -1e-6;
  const Voigt expected = stress + mc.parameters().elastic.stress_increment(increment);
  CHECK(mc.update(stress, increment) == ReturnRegion::elastic);
  CHECK(stress == expected);
}

TEST_CASE("plane return: plastic strain follows g with no flow along σ2", "[mc]") {
  const double psi = 10.0;
  const MohrCoulomb mc(sand(35.0, psi, 0.0, 0.3, 50e6));
  // Distinct principal stresses, sheared in the 1–2 plane past the surface.
  Voigt stress = Voigt::Zero();
  stress << -100e3, -250e3, -160e3, 0, 0, 0;
  REQUIRE(mc.yield_function(stress) < 0.0);
  Voigt increment = Voigt::Zero();
  increment << 2e-3, -4e-3, 0.0, 5e-4, 0, 0;
  const Voigt start = stress;
  REQUIRE(mc.update(stress, increment) == ReturnRegion::plane);
  const Voigt ep = plastic_strain(mc.parameters().elastic, increment, stress - start);
  const Eigen::Vector3d e = PrincipalStresses(ep).values();
  // g = (σ1 − σ3) + (σ1 + σ3) sin ψ: Δε^p = Δλ (1 + sin ψ, 0, −(1 − sin ψ)).
  // Tolerance: Δε^p is the difference of O(1e-3) strains, rounding ~1e-16 of them.
  const double sp = std::sin(psi * kDegree);
  CHECK(std::abs(e[1]) <= 1e-12);
  CHECK(e[0] / -e[2] == Approx((1 + sp) / (1 - sp)).epsilon(1e-9));
  CHECK(std::abs(mc.yield_function(stress)) <= 1e-10 * 250e3);
}

TEST_CASE("triaxial compression edge: dε_v^p/dε_1^p = −2 sinψ/(1 − sinψ)", "[mc]") {
  for (double psi : {0.0, 5.0, 15.0, 39.0}) {
    const MohrCoulomb mc(sand(39.0, psi));
    const double sigma3 = 1.72;
    Voigt stress = triaxial(sigma3, sigma3 * flow_factor_nphi(39.0));  // on the compression edge
    const Voigt start = stress;
    Voigt increment = Voigt::Zero();
    increment << 0.5e-3, -1e-3, 0.5e-3, 0, 0, 0;  // isochoric axial compression
    REQUIRE(mc.update(stress, increment) == ReturnRegion::edge_compression);
    const Voigt ep = plastic_strain(mc.parameters().elastic, increment, stress - start);
    const double sp = std::sin(psi * kDegree);
    // The ratio of O(1e-3) strains; 1e-9 relative leaves room for the cancellation in Δε − CΔσ.
    CHECK(trace(ep) / ep[1] == Approx(-2 * sp / (1 - sp)).margin(1e-9));
    CHECK(ep[0] == Approx(ep[2]).margin(1e-15));
    CHECK(std::abs(mc.yield_function(stress)) <= 1e-10 * 1e3 * sigma3 * flow_factor_nphi(39.0));
  }
}

TEST_CASE("triaxial extension edge: dε_v^p/dε_1^p = 2 sinψ/(1 + sinψ)", "[mc]") {
  const double psi = 8.0;
  const MohrCoulomb mc(sand(30.0, psi));
  const double radial = 50.0;
  Voigt stress = triaxial(radial, radial / flow_factor_nphi(30.0));  // on the extension edge
  const Voigt start = stress;
  Voigt increment = Voigt::Zero();
  increment << -0.5e-3, 1e-3, -0.5e-3, 0, 0, 0;  // isochoric axial extension
  REQUIRE(mc.update(stress, increment) == ReturnRegion::edge_extension);
  const Voigt ep = plastic_strain(mc.parameters().elastic, increment, stress - start);
  const double sp = std::sin(psi * kDegree);
  CHECK(trace(ep) / ep[1] == Approx(2 * sp / (1 + sp)).margin(1e-9));
  CHECK(std::abs(mc.yield_function(stress)) <= 1e-10 * 1e3 * radial);
}

TEST_CASE("tensile increments on c' = 0 sand return to zero stress", "[mc][apex]") {
  for (double psi : {0.0, 5.0}) {
    const MohrCoulomb mc(sand(39.0, psi));
    SECTION("isotropic extension from 100 kPa, ψ = " + std::to_string(psi)) {
      Voigt stress = isotropic(-100e3);
      const Voigt increment = isotropic(0.1);  // 10 %: far past the apex
      CHECK(mc.update(stress, increment) == ReturnRegion::apex);
      CHECK(stress == Voigt::Zero());
    }
    SECTION("uniaxial extension with shear from zero stress, ψ = " + std::to_string(psi)) {
      Voigt stress = Voigt::Zero();
      Voigt increment = Voigt::Zero();
      increment << 0.05, 0.0, 0.0, 0.02, 0.01, 0.0;
      CHECK(mc.update(stress, increment) == ReturnRegion::apex);
      CHECK(stress == Voigt::Zero());
    }
  }
  SECTION("with cohesion the apex is c cot φ") {
    const MohrCoulomb mc(sand(30.0, 0.0, 10e3));
    Voigt stress = isotropic(-10e3);
    CHECK(mc.update(stress, isotropic(0.1)) == ReturnRegion::apex);
    CHECK(max_abs(stress - isotropic(10e3 / std::tan(30 * kDegree))) <= 1e-9);
  }
}

TEST_CASE("Tresca (φ = 0) and φ = 70° return finite, consistent stresses", "[mc]") {
  for (double phi : {0.0, 70.0}) {
    const MohrCoulomb mc(sand(phi, 0.0, 20e3, 0.49));
    std::mt19937_64 rng(5);
    for (int n = 0; n < 2000; ++n) {
      Voigt stress = random_voigt(rng, 50e3);
      const Voigt increment = random_voigt(rng, 0.03);
      const Voigt trial = stress + mc.parameters().elastic.stress_increment(increment);
      mc.update(stress, increment);
      REQUIRE(stress.allFinite());
      CHECK(mc.yield_function(stress) <= 1e-10 * std::max(max_abs(trial), 20e3));
    }
  }
}

TEST_CASE("every plastic return is consistent: |f| ≤ 1e-10 of the stress scale", "[mc]") {
  // Plane, both edges and the apex must all be reached by this sample.
  std::array<int, 5> seen{};
  std::mt19937_64 rng(2020);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int n = 0; n < 20000; ++n) {
    const double phi = 5.0 + 60.0 * uniform(rng);
    const MohrCoulomb mc(sand(phi, phi * uniform(rng), n % 3 == 0 ? 0.0 : 30e3 * uniform(rng), 0.45 * uniform(rng)));
    Voigt stress = isotropic(-100e3 * uniform(rng)) + random_voigt(rng, 20e3);
    if (n % 2 == 0) stress[4] = stress[5] = 0.0;
    Voigt increment = random_voigt(rng, 0.01);
    if (n % 2 == 0) increment[4] = increment[5] = 0.0;
    const Voigt start = stress;
    const Voigt trial = stress + mc.parameters().elastic.stress_increment(increment);
    const ReturnRegion region = mc.update(stress, increment);
    ++seen[static_cast<int>(region)];
    const double scale = std::max(max_abs(trial), mc.parameters().cohesion_Pa);
    if (region != ReturnRegion::elastic) {
      CHECK(std::abs(mc.yield_function(stress)) <= 1e-10 * scale);
    }
    if (region == ReturnRegion::plane || region == ReturnRegion::edge_compression ||
        region == ReturnRegion::edge_extension) {
      // Flow rule on plane and edges: Δε^p = Σ Δλ_k (1 + sin ψ on the major, −(1 − sin ψ) on the minor
      // axis of plane k), so (1 − sin ψ) Σ(e_i > 0) + (1 + sin ψ) Σ(e_i < 0) = 0 with Δλ_k ≥ 0.
      const Eigen::Vector3d e =
          PrincipalStresses(plastic_strain(mc.parameters().elastic, increment, stress - start)).values();
      const double sp = std::sin(mc.parameters().dilatancy_angle_rad);
      double dilatant = 0.0, compactive = 0.0;
      for (int i = 0; i < 3; ++i) (e[i] > 0.0 ? dilatant : compactive) += e[i];
      // Δε^p = Δε − CΔσ cancels O(1e-2) strains: 1e-10 of them is ~1e6 ulps of room.
      CHECK(std::abs((1 - sp) * dilatant + (1 + sp) * compactive) <=
            1e-10 * max_abs(increment) + 1e-13 * e.cwiseAbs().maxCoeff());
      CHECK(e[0] > 0.0);
      CHECK(e[2] < 0.0);
    }
  }
  for (int region = 0; region < 5; ++region) CHECK(seen[region] > 50);
}

TEST_CASE("rotated increment and stress give the rotated result", "[mc]") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int n = 0; n < 5000; ++n) {
    const double phi = 10.0 + 55.0 * uniform(rng);
    const MohrCoulomb mc(sand(phi, phi * uniform(rng), n % 2 == 0 ? 0.0 : 10e3, 0.3));
    const Voigt stress = isotropic(-50e3) + random_voigt(rng, 20e3);
    const Voigt increment = random_voigt(rng, 0.02);
    Voigt plain = stress;
    mc.update(plain, increment);
    const Eigen::Matrix3d r = random_rotation(rng);
    Voigt turned = rotated(stress, r);
    mc.update(turned, rotated(increment, r));
    const Voigt trial = stress + mc.parameters().elastic.stress_increment(increment);
    // Both paths use the general eigen-solver on different matrices; its
    // eigenvectors are accurate to ~1e-13 of the stress scale here.
    CHECK(max_abs(turned - rotated(plain, r)) <= 1e-10 * std::max(max_abs(trial), 10e3));
  }
}

TEST_CASE("no NaN in a randomized sweep of 10^5 states × increments including the extreme cases", "[mc][sweep]") {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const std::array<double, 5> phis = {0.0, 1e-9, 30.0, 55.0, 70.0};
  const std::array<double, 4> nus = {0.0, 0.25, 0.45, 0.49};
  long failures = 0;
  long not_finite = 0;
  for (int n = 0; n < 100000; ++n) {
    const double phi = n % 7 == 0 ? 70.0 * uniform(rng) : phis[n % phis.size()];
    const double psi = (n / 5) % 3 == 0 ? 0.0 : ((n / 5) % 3 == 1 ? phi : phi * uniform(rng));
    const double cohesion = (n / 15) % 2 == 0 ? 0.0 : 1e4 * uniform(rng);
    const MohrCoulomb mc(sand(phi, psi, cohesion, nus[(n / 30) % nus.size()], 1e6 + 1e8 * uniform(rng)));
    Voigt stress;
    switch (n % 4) {
      case 0:
        stress = Voigt::Zero();
        break;  // zero stress
      case 1:
        stress = isotropic(-1e5 * uniform(rng));
        break;  // on the hydrostatic axis
      case 2:
        stress = isotropic(-1e5 * uniform(rng)) + random_voigt(rng, 3e4);
        break;
      default:
        stress = random_voigt(rng, 1e5);
        break;  // anything, tension too
    }
    if (n % 3 == 0) stress[4] = stress[5] = 0.0;
    Voigt increment = random_voigt(rng, 0.1 * uniform(rng));     // single increments up to ~10 %
    if (n % 11 == 0) increment = isotropic(0.1 * uniform(rng));  // pure tension
    if (n % 13 == 0) increment = isotropic(-0.1 * uniform(rng));
    if (n % 3 == 0) increment[4] = increment[5] = 0.0;
    const Voigt trial = stress + mc.parameters().elastic.stress_increment(increment);
    mc.update(stress, increment);
    if (!stress.allFinite()) {
      ++not_finite;
      continue;
    }
    const double scale = std::max(max_abs(trial), cohesion);
    if (mc.yield_function(stress) > 1e-10 * scale) ++failures;
  }
  CHECK(not_finite == 0);
  CHECK(failures == 0);
}

TEST_CASE("P-wave speed comes from the constrained modulus", "[mc][elastic]") {
  const MohrCoulomb mc(sand(39.0, 5.0, 0.0, 0.33, 2.5e6));
  const double nu = 0.33, E = 2.5e6;
  const double constrained = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  CHECK(mc.p_wave_speed(1490.0) == Approx(std::sqrt(constrained / 1490.0)).epsilon(1e-14));
}

TEST_CASE("the batch update gives the single-point update's bits in every region, planar and 3D", "[mc][batch]") {
  // The batch takes the elastic test in vector lanes (screen_elastic_trials, four points
  // at a time, the rest of a block of 64 one by one) and the returns where θθ is principal
  // (the MPM) four at a time in lanes too (return_planar_trials, the batch's last few on
  // ElasticTrial's scalar principal values): it must be the single-point update bit for
  // bit, for batches of every length about the lanes and the block.
  std::mt19937_64 rng(4321);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const MohrCoulomb mc(sand(39.0, 5.0, 0.0));
  const MohrCoulomb cohesive(sand(30.0, 10.0, 5e3));
  std::array<long, 5> regions{};  // elastic, plane, compression edge, extension edge, apex
  long different = 0;
  for (int n = 0; n < 6000; ++n) {
    const MohrCoulomb& law = n % 2 == 0 ? mc : cohesive;
    const std::size_t length = 1 + static_cast<std::size_t>(n) % 140;
    std::vector<Voigt> stress(length), increment(length);
    for (std::size_t k = 0; k < stress.size(); ++k) {
      const std::size_t m = static_cast<std::size_t>(n) + k;  // each lane of a batch its own kind of point
      stress[k] = m % 5 == 0 ? random_voigt(rng, 1e5) : isotropic(-1e5 * uniform(rng)) + random_voigt(rng, 3e4);
      increment[k] = random_voigt(rng, (m % 3 == 0 ? 1e-2 : 1e-4) * uniform(rng));
      if (m % 7 != 0) stress[k][4] = stress[k][5] = increment[k][4] = increment[k][5] = 0.0;  // θθ principal
    }
    std::vector<Voigt> single = stress;
    for (std::size_t k = 0; k < stress.size(); ++k)
      ++regions[static_cast<std::size_t>(law.update(single[k], increment[k]))];
    law.update(std::span<Voigt>(stress), std::span<const Voigt>(increment));
    for (std::size_t k = 0; k < stress.size(); ++k)
      for (int i = 0; i < 6; ++i)
        if (!(stress[k][i] == single[k][i] && std::signbit(stress[k][i]) == std::signbit(single[k][i]))) ++different;
  }
  CHECK(different == 0);
  for (const long count : regions) CHECK(count > 0);  // every region was exercised
}
