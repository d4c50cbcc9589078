#include <catch2/catch.hpp>

#include "models/micropolar.hpp"

using namespace ffp;

// The micro terms' friction limits |s| ≤ μ p, |m| ≤ ℓ μ p (models/micropolar.hpp): inside them
// nothing changes; beyond, the trial goes to the limit along its own direction; without
// pressure (a sand in tension or unloaded) the grains carry no moment.
TEST_CASE("micro stresses held at the sand's friction: unchanged inside, on the limit beyond, none without pressure",
          "[micropolar]") {
  const double mu = 0.8, length = 1e-3, pressure = 10e3;  // limits: |s| ≤ 8 kPa, |m| ≤ 8 N/m
  SECTION("inside both limits the trial is returned bit for bit") {
    const MicroStresses trial{-7.9e3, 3.0, -4.0, 5.0};  // |m| = 7.07 N/m
    const MicroStresses held = held_at_friction(trial, mu, length, pressure);
    CHECK(held.skew == trial.skew);
    CHECK(held.couple_r == trial.couple_r);
    CHECK(held.couple_z == trial.couple_z);
    CHECK(held.couple_hoop == trial.couple_hoop);
  }
  SECTION("beyond them each goes onto its limit, keeping its sign and direction") {
    const MicroStresses held = held_at_friction({-20e3, 6.0, -8.0, 0.0}, mu, length, pressure);  // |m| = 10 N/m
    CHECK(held.skew == Approx(-8e3).epsilon(1e-15));
    CHECK(held.couple_norm() == Approx(8.0).epsilon(1e-15));
    CHECK(held.couple_r == Approx(4.8).epsilon(1e-15));
    CHECK(held.couple_z == Approx(-6.4).epsilon(1e-15));
    CHECK(held.couple_hoop == 0.0);
  }
  SECTION("a sand in tension carries no skew or couple stress") {
    const MicroStresses held = held_at_friction({5e3, 1.0, 2.0, 3.0}, mu, length, -1e3);
    CHECK(held.skew == 0.0);
    CHECK(held.couple_norm() == 0.0);
  }
}
