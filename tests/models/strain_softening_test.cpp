#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "models/bolton_dilatancy.hpp"
#include "models/friction_rate_law.hpp"
#include "models/math_constants.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"
#include "tensor_test_helpers.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {

/// The paper's sand (section 4.2, Table 1): E' = 2500 kPa, ν' = 0.33, φ'_p = 39°, φ'_c = 32°, ψ_p = 5°, η = 8.
StrainSofteningParameters paper_sand() {
  StrainSofteningParameters p;
  p.elastic = {2.5e6, 0.33};
  p.friction_peak_rad = 39 * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = 5 * kDegree;
  p.softening_factor = 8.0;
  return p;
}

/// A random SSMC law, the n-th of a sweep: φ'_p 1–70°, φ'_r below it, ψ_p 0 in one
/// law of four, c' 0 in one of two, η 1e-3–1e3 (log-uniform), ν' 0–0.49, Bolton in one
/// of five and the rate law in one of three.
StrainSofteningParameters random_sand(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  StrainSofteningParameters p = paper_sand();
  p.friction_peak_rad = (1.0 + 69.0 * uniform(rng)) * kDegree;
  p.friction_residual_rad = p.friction_peak_rad * uniform(rng);
  p.dilatancy_peak_rad = n % 4 == 0 ? 0.0 : p.friction_peak_rad * uniform(rng);
  p.cohesion_peak_Pa = n % 2 == 0 ? 0.0 : 5e3 * uniform(rng);
  p.cohesion_residual_Pa = p.cohesion_peak_Pa * uniform(rng);
  p.softening_factor = std::pow(10.0, -3.0 + 6.0 * uniform(rng));
  p.elastic.poisson_ratio = 0.49 * uniform(rng);
  if (n % 5 == 0) p.relative_density = uniform(rng);
  if (n % 3 == 0) p.rate.alpha_phi = 0.2 * uniform(rng);
  return p;
}

Voigt plastic_strain(const ElasticConstants& e, const Voigt& strain_increment, const Voigt& stress_increment) {
  Voigt elastic = deviator(stress_increment) / (2.0 * e.shear_modulus());
  for (int i = 0; i < 3; ++i) elastic[i] += trace(stress_increment) / (9.0 * e.bulk_modulus());
  return strain_increment - elastic;
}

}  // namespace

TEST_CASE("Bolton dilatancy index and peak dilatancy match table values, clamping included", "[bolton]") {
  // Values computed by hand from paper eq. 5, I_R = D_r (10 − ln p') − 1, and eq. 4, tan ψ = 0.3 I_R.
  struct Row {
    double relative_density, p_kPa, index, psi_deg;
  };
  const Row table[] = {
      {0.15, 1.72, 0.41865190, 7.15487},  // the paper's sand at σ3 = 1.72 kPa
      {0.00, 1.72, 0.0, 0.0},             // D_r = 0: I_R = −1 clamped to 0
      {0.15, 3.00, 0.33520817, 5.74470},
      {0.50, 100.0, 1.69741490, 26.99},  // 0.5(10 − 4.60517) − 1
      {1.00, 1.0, 4.0, 50.19443},        // 9 clamped to 4: tan ψ = 1.2
      {0.10, 1e9, 0.0, 0.0},             // huge p': negative, clamped to 0
      {0.15, 0.0, 4.0, 50.19443},        // no pressure: ln p' → −∞, clamped to 4
  };
  for (const Row& r : table) {
    CAPTURE(r.relative_density, r.p_kPa);
    CHECK(bolton_dilatancy_index(r.relative_density, r.p_kPa) == Approx(r.index).margin(1e-8));
    CHECK(bolton_peak_dilatancy_rad(r.relative_density, r.p_kPa) / kDegree == Approx(r.psi_deg).margin(1e-2));
  }
}

TEST_CASE("the rate law is monotone in ε̇ and inert below ε̇_ref", "[rate]") {
  FrictionRateLaw law;
  law.alpha_phi = 0.05;
  law.reference_strain_rate_per_s = 1e-3;
  law.max_friction_angle_rad = 60 * kDegree;
  const double peak = 39 * kDegree;
  CHECK(law.peak_friction_rad(peak, 0.0) == peak);
  CHECK(law.peak_friction_rad(peak, 1e-9) == peak);
  CHECK(law.peak_friction_rad(peak, 1e-3) == peak);
  // φ'_p(ε̇) = φ'_p,ref (1 + α log10(ε̇/ε̇_ref)): two decades up → ×1.1.
  CHECK(law.peak_friction_rad(peak, 1e-1) == Approx(peak * 1.1).epsilon(1e-14));
  double previous = 0.0;
  for (double rate = 1e-6; rate < 1e6; rate *= 1.7) {
    const double phi = law.peak_friction_rad(peak, rate);
    CHECK(phi >= previous);
    CHECK(phi <= 60 * kDegree);
    previous = phi;
  }
  CHECK(law.peak_friction_rad(peak, 1e30) == 60 * kDegree);  // capped
  law.alpha_phi = 0.0;
  CHECK(law.peak_friction_rad(peak, 1e6) == peak);  // α_φ = 0: rate independent
}

TEST_CASE("strain-rate smoothing is an N-increment exponential moving average", "[rate]") {
  FrictionRateLaw law;
  law.smoothing_increments = 1;
  CHECK(law.smoothed_rate(5.0, 2.0) == 2.0);
  law.smoothing_increments = 3;  // weight 2/(N+1) = 1/2
  CHECK(law.smoothed_rate(4.0, 2.0) == 3.0);
  double smoothed = 0.0;
  for (int n = 0; n < 200; ++n) smoothed = law.smoothed_rate(smoothed, 7.0);
  CHECK(smoothed == Approx(7.0).epsilon(1e-12));  // a steady rate is reproduced
}

TEST_CASE("SSMC strength decays as x_r + (x_p − x_r) exp(−η ε_d^p)", "[ssmc]") {
  StrainSofteningParameters p = paper_sand();
  p.cohesion_peak_Pa = 5e3;
  p.cohesion_residual_Pa = 1e3;
  const StrainSofteningMohrCoulomb law(p);
  StrainSofteningMohrCoulomb::State state;
  MohrCoulombParameters s = law.current_strength(state, 1.72e3);
  CHECK(s.friction_angle_rad == Approx(39 * kDegree).epsilon(1e-14));
  CHECK(s.dilatancy_angle_rad == Approx(5 * kDegree).epsilon(1e-13));
  CHECK(s.cohesion_Pa == Approx(5e3).epsilon(1e-14));
  state.plastic_deviatoric_strain = 1.0 / 8.0;
  s = law.current_strength(state, 1.72e3);
  CHECK(s.friction_angle_rad == Approx((32 + 7 * std::exp(-1.0)) * kDegree).epsilon(1e-13));
  CHECK(s.cohesion_Pa == Approx(1e3 + 4e3 * std::exp(-1.0)).epsilon(1e-13));
  CHECK(s.dilatancy_angle_rad == Approx(5 * std::exp(-1.0) * kDegree).epsilon(1e-12));
  state.plastic_deviatoric_strain = 10.0;
  s = law.current_strength(state, 1.72e3);
  CHECK(s.friction_angle_rad == Approx(32 * kDegree).epsilon(1e-14));
  CHECK(s.dilatancy_angle_rad == Approx(0.0).margin(1e-30));
}

TEST_CASE("Bolton's ψ_p is capped at the current friction angle", "[ssmc][bolton]") {
  StrainSofteningParameters p = paper_sand();
  p.relative_density = 1.0;  // I_R clamped to 4: ψ_p = 50.2° > φ
  const StrainSofteningMohrCoulomb law(p);
  StrainSofteningMohrCoulomb::State state;
  CHECK(law.current_strength(state, 1e3).dilatancy_angle_rad == Approx(39 * kDegree).epsilon(1e-12));
  // Early in softening ψ = 50.19° e^(−ηκ) still exceeds φ = 32° + 7° e^(−ηκ): capped.
  state.plastic_deviatoric_strain = 0.01;
  MohrCoulombParameters s = law.current_strength(state, 1e3);
  CHECK(s.dilatancy_angle_rad == Approx(s.friction_angle_rad).epsilon(1e-12));
  // Later it decays below φ and follows its own law.
  state.plastic_deviatoric_strain = 0.1;
  s = law.current_strength(state, 1e3);
  const double bolton_peak = std::atan(1.2);
  CHECK(s.dilatancy_angle_rad == Approx(bolton_peak * std::exp(-0.8)).epsilon(1e-12));
  CHECK(s.dilatancy_angle_rad < s.friction_angle_rad);
}

TEST_CASE("ψ never grows with softening, even where Bolton's ψ_p is below ψ_r", "[ssmc][bolton]") {
  StrainSofteningParameters p = paper_sand();
  p.relative_density = 0.15;
  p.dilatancy_residual_rad = 2 * kDegree;
  const StrainSofteningMohrCoulomb law(p);
  StrainSofteningMohrCoulomb::State state;
  // At 1.72 kPa I_R = 0.15(10 − ln 1.72) − 1 = 0.42: ψ_p = 7.2° > ψ_r, the usual decay to 2°.
  const double low_p_peak = bolton_peak_dilatancy_rad(0.15, 1.72);
  REQUIRE(low_p_peak > 2 * kDegree);
  CHECK(law.current_strength(state, 1.72e3).dilatancy_angle_rad == Approx(low_p_peak).epsilon(1e-12));
  // At 100 kPa I_R = 0.15(10 − ln 100) − 1 < 0 is clamped to 0: ψ_p = 0 < ψ_r, and ψ stays 0.
  REQUIRE(bolton_peak_dilatancy_rad(0.15, 100.0) == 0.0);
  for (double kappa : {0.0, 0.05, 0.2, 5.0}) {
    state.plastic_deviatoric_strain = kappa;
    CAPTURE(kappa);
    CHECK(law.current_strength(state, 100e3).dilatancy_angle_rad == Approx(0.0).margin(1e-15));
    CHECK(law.current_strength(state, 1.72e3).dilatancy_angle_rad <= low_p_peak * (1 + 1e-12));
  }
  state.plastic_deviatoric_strain = 5.0;
  CHECK(law.current_strength(state, 1.72e3).dilatancy_angle_rad == Approx(2 * kDegree).epsilon(1e-12));
}

TEST_CASE("SSMC with η = 0 is Mohr-Coulomb with the peak strength", "[ssmc]") {
  StrainSofteningParameters p = paper_sand();
  p.softening_factor = 0.0;
  const StrainSofteningMohrCoulomb ssmc(p);
  MohrCoulombParameters m;
  m.elastic = p.elastic;
  m.friction_angle_rad = p.friction_peak_rad;
  m.dilatancy_angle_rad = p.dilatancy_peak_rad;
  const MohrCoulomb mc(m);
  std::mt19937_64 rng(8);
  Voigt a = isotropic(-2e3), b = a;
  StrainSofteningMohrCoulomb::State state;
  for (int n = 0; n < 500; ++n) {
    const Voigt increment = random_voigt(rng, 3e-4) + isotropic(-1e-4);
    ssmc.update(a, increment, state, 0.0);
    mc.update(b, increment);
    // Same closed-form return on the same numbers: equal to rounding.
    REQUIRE(max_abs(a - b) <= 1e-12 * std::max(max_abs(b), 1.0));
  }
  CHECK(state.plastic_deviatoric_strain > 0.0);
}

TEST_CASE("SSMC hardening is implicit: Δκ is the plastic deviatoric strain of the increment", "[ssmc]") {
  for (double eta : {0.5, 8.0, 200.0}) {
    StrainSofteningParameters p = paper_sand();
    p.softening_factor = eta;
    p.relative_density = 0.15;
    const StrainSofteningMohrCoulomb law(p);
    std::mt19937_64 rng(9);
    Voigt stress = isotropic(-1.72e3);
    StrainSofteningMohrCoulomb::State state;
    int plastic = 0;
    for (int n = 0; n < 400; ++n) {
      // Isochoric axial compression with random disturbances: keeps yielding.
      Voigt increment = random_voigt(rng, 5e-4);
      increment[0] += 1.5e-3;
      increment[1] -= 3e-3;
      increment[2] += 1.5e-3;
      const Voigt start = stress;
      const double kappa_start = state.plastic_deviatoric_strain;
      const ReturnRegion region = law.update(stress, increment, state, 0.0);
      REQUIRE(stress.allFinite());
      const double dkappa = state.plastic_deviatoric_strain - kappa_start;
      CHECK(dkappa >= 0.0);
      const Voigt ep = plastic_strain(p.elastic, increment, stress - start);
      // Δκ is solved to 1e-12 relative; Δε − CΔσ cancels O(1e-3) strains to ~1e-16.
      CHECK(dkappa == Approx(deviatoric_strain(ep)).epsilon(1e-9).margin(1e-14));
      if (region != ReturnRegion::elastic) {
        ++plastic;
        const MohrCoulomb at_end(law.current_strength(state, -trace(start) / 3.0));
        const double scale = max_abs(start + p.elastic.stress_increment(increment));
        CHECK(std::abs(at_end.yield_function(stress)) <= 1e-10 * scale);
      }
    }
    CHECK(plastic > 100);
  }
}

TEST_CASE("SSMC's elastic screen never hides yielding: trials 1e-9 either side of the surface", "[ssmc]") {
  // The update skips the exact yield test where a bound on sin φ' says "inside";
  // at every κ, rate and cohesion a trial just outside must still yield and one
  // just inside must stay elastic. Principal stresses σ1 ≥ σ2 ≥ σ3 on the
  // surface: σ1 (1 + sin φ') = σ3 (1 − sin φ') + 2c' cos φ'.
  StrainSofteningParameters p = paper_sand();
  p.friction_peak_rad = 60 * kDegree;
  for (int variant = 0; variant < 3; ++variant) {
    if (variant == 1) {
      p.rate.alpha_phi = 0.1;
      p.rate.reference_strain_rate_per_s = 1.0;
    }
    if (variant == 2) {
      p.cohesion_peak_Pa = 2e3;
      p.cohesion_residual_Pa = 0.5e3;
    }
    const StrainSofteningMohrCoulomb law(p);
    for (double kappa : {0.0, 1e-6, 1e-3, 0.02, 0.1, 0.3, 0.5, 2.0}) {
      for (double rate : {0.0, 10.0, 1e4}) {
        StrainSofteningMohrCoulomb::State state{kappa, rate};
        const MohrCoulombParameters s = law.current_strength(state, 3e3);
        const double sin_phi = std::sin(s.friction_angle_rad);
        const double minor = -3e3;
        const double major =
            (minor * (1.0 - sin_phi) + 2.0 * s.cohesion_Pa * std::cos(s.friction_angle_rad)) / (1.0 + sin_phi);
        for (double side : {1.0, -1.0}) {
          CAPTURE(variant, kappa, rate, side);
          Voigt stress = Voigt::Zero();
          stress << major + side * 1e-9 * std::abs(minor), 0.5 * (major + minor), minor, 0, 0, 0;
          StrainSofteningMohrCoulomb::State point = state;
          const ReturnRegion region = law.update(stress, Voigt::Zero(), point, 0.0);
          if (side > 0.0) {
            CHECK(region != ReturnRegion::elastic);
          } else {
            CHECK(region == ReturnRegion::elastic);
          }
        }
      }
    }
  }
}

TEST_CASE("a faster strain rate raises SSMC strength only above ε̇_ref", "[ssmc][rate]") {
  StrainSofteningParameters p = paper_sand();
  p.rate.alpha_phi = 0.1;
  p.rate.reference_strain_rate_per_s = 1.0;
  const StrainSofteningMohrCoulomb law(p);
  auto peak_q = [&](double dt) {
    Voigt stress = isotropic(-1.72e3);
    StrainSofteningMohrCoulomb::State state;
    Voigt increment = Voigt::Zero();
    increment << 0.5e-4, -1e-4, 0.5e-4, 0, 0, 0;  // isochoric axial compression
    double peak = 0.0;
    for (int n = 0; n < 200; ++n) {
      law.update(stress, increment, state, dt);
      peak = std::max(peak, deviatoric_stress(stress));
    }
    return peak;
  };
  // ε̇ = 1e-4/dt: dt = 1 s and 1e-3 s lie below / at ε̇_ref; 1e-6 s is two decades above it.
  const double slow = peak_q(1.0), at_reference = peak_q(1e-4), fast = peak_q(1e-6), faster = peak_q(1e-8);
  CHECK(slow == at_reference);
  CHECK(fast > slow * 1.1);
  CHECK(faster > fast);
}

TEST_CASE("SSMC randomized sweep stays finite and admissible", "[ssmc][sweep]") {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  long violations = 0, not_finite = 0;
  for (int n = 0; n < 20000; ++n) {
    const StrainSofteningParameters p = random_sand(rng, n);
    const StrainSofteningMohrCoulomb law(p);
    StrainSofteningMohrCoulomb::State state;
    state.plastic_deviatoric_strain = n % 7 == 0 ? 0.0 : uniform(rng);
    Voigt stress = n % 6 == 0 ? Voigt(Voigt::Zero()) : Voigt(isotropic(-1e4 * uniform(rng)) + random_voigt(rng, 3e3));
    const Voigt increment = random_voigt(rng, 0.1 * uniform(rng));
    const Voigt start = stress;
    law.update(stress, increment, state, 1e-3);
    if (!stress.allFinite() || !std::isfinite(state.plastic_deviatoric_strain)) {
      ++not_finite;
      continue;
    }
    const MohrCoulomb at_end(law.current_strength(state, -trace(start) / 3.0));
    const double scale = std::max(max_abs(start + p.elastic.stress_increment(increment)), p.cohesion_peak_Pa);
    if (at_end.yield_function(stress) > 1e-10 * scale) ++violations;
  }
  CHECK(not_finite == 0);
  CHECK(violations == 0);
}

TEST_CASE("SSMC's batch update gives the point update's bits, returns interleaved or not", "[ssmc][batch]") {
  // The batch runs the returns of a block of points side by side (one evaluation of each
  // per round); every point must still take the same arithmetic as alone. Random laws
  // (η from 1e-3 to 1e3, so that some returns need the residual bound, the widening and
  // the Illinois steps), planar and general trials, elastic and plastic, in batches that
  // cross the blocks' boundaries.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  long compared = 0, plastic = 0;
  for (int law_index = 0; law_index < 60; ++law_index) {
    const StrainSofteningMohrCoulomb law(random_sand(rng, law_index));
    const std::size_t n = 1 + static_cast<std::size_t>(300 * uniform(rng));
    std::vector<Voigt> stress(n), increment(n);
    std::vector<StrainSofteningMohrCoulomb::State> state(n);
    for (std::size_t i = 0; i < n; ++i) {
      stress[i] = isotropic(-1e4 * uniform(rng)) + random_voigt(rng, 3e3);
      increment[i] = random_voigt(rng, std::pow(10.0, -6.0 + 5.0 * uniform(rng)));
      if (i % 3 != 0) {  // axisymmetric: θθ principal, as in the MPM
        stress[i][4] = stress[i][5] = 0.0;
        increment[i][4] = increment[i][5] = 0.0;
      }
      state[i] = {i % 7 == 0 ? 0.0 : uniform(rng), 100.0 * uniform(rng)};
    }
    std::vector<Voigt> one_by_one = stress;
    std::vector<StrainSofteningMohrCoulomb::State> one_by_one_state = state;
    for (std::size_t i = 0; i < n; ++i) {
      if (law.update(one_by_one[i], increment[i], one_by_one_state[i], 1e-4) != ReturnRegion::elastic) ++plastic;
    }
    law.update(std::span<Voigt>(stress), std::span<const Voigt>(increment),
               std::span<StrainSofteningMohrCoulomb::State>(state), 1e-4);
    for (std::size_t i = 0; i < n; ++i) {
      CAPTURE(law_index, i);
      REQUIRE(stress[i] == one_by_one[i]);  // exact: the same bits
      REQUIRE(state[i].plastic_deviatoric_strain == one_by_one_state[i].plastic_deviatoric_strain);
      REQUIRE(state[i].strain_rate_per_s == one_by_one_state[i].strain_rate_per_s);
      ++compared;
    }
  }
  CHECK(compared > 5000);
  CHECK(plastic > compared / 4);
}
