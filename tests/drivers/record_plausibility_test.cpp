/// What can be a penetrometer's impact (drivers/record_plausibility.hpp): records no impact
/// produces are refused, unlikely ones flagged.
#include <catch2/catch.hpp>

#include <cmath>

#include "drivers/record_plausibility.hpp"

using namespace ffp;

namespace {

constexpr double g = 9.81;
constexpr double kDt = 2e-4;

/// A drop seen from its impact at t = 0 (v0 = 5.6 m/s given): `early` samples of free fall (−1 g),
/// then a constant net deceleration `pulse_g` for `pulse` samples, then `after_g` to the end.
struct Drop {
  std::vector<double> time_s, deceleration_g;
  RecordSettings settings;
  Drop(int early, int pulse, double pulse_g, int after, double after_g = 0.0) {
    for (int k = 0; k < early + pulse + after; ++k) {
      time_s.push_back(k * kDt);
      deceleration_g.push_back(k < early ? -1.0 : k < early + pulse ? pulse_g : after_g);
    }
    settings.impact_velocity_m_s = 5.6;
    settings.impact_time_s = 0.0;
  }
  InterpretedRecord interpret() const { return interpret_record(time_s, deceleration_g, settings); }
  std::vector<std::string> check() const { return check_impact_kinematics(interpret(), g, "deceleration_g"); }
};

/// 5.6 m/s stopped by 4 g: 5.6 / (4 g) = 0.1427 s = 713.6 samples; 714 samples end it within 0.01 m/s.
constexpr int kStop = 714;

}  // namespace

TEST_CASE("the largest credible sample is a full reversal of the fastest speed within one interval",
          "[record][plausibility]") {
  const Drop drop(0, kStop, 4.0, 36);  // 750 samples, 0.1498 s
  // By hand: V = 5.6 + 9.81 × 0.1498 = 7.06954 m/s; 2V/(g Δt) = 14.13908/(9.81 × 2e-4) = 7206.46 g.
  CHECK(largest_credible_deceleration_g(drop.time_s, drop.settings) == Approx(7206.46).epsilon(1e-6));
  RecordSettings from_release = drop.settings;
  from_release.impact_velocity_m_s.reset();  // V = g T only: 2 T / Δt = 1498 g
  CHECK(largest_credible_deceleration_g(drop.time_s, from_release) == Approx(1498.0).epsilon(1e-9));

  CHECK_NOTHROW(check_deceleration_bound(drop.time_s, drop.deceleration_g, "deceleration_g", drop.settings));
  auto absurd = drop.deceleration_g;
  absurd[100] = absurd[101] = 1e308;  // two samples whose trapezoid overflows to inf
  CHECK_THROWS_WITH(check_deceleration_bound(drop.time_s, absurd, "deceleration_g", drop.settings),
                    Catch::Contains("column 'deceleration_g'") && Catch::Contains("data row 101") &&
                        Catch::Contains("1e+308 g") && Catch::Contains("±7.21e+03 g"));
  absurd[100] = absurd[101] = -7300.0;  // just beyond, on the other side
  CHECK_THROWS_WITH(check_deceleration_bound(drop.time_s, absurd, "deceleration_g", drop.settings),
                    Catch::Contains("data row 101"));
  absurd[100] = absurd[101] = 7100.0;  // just within
  CHECK_NOTHROW(check_deceleration_bound(drop.time_s, absurd, "deceleration_g", drop.settings));
}

TEST_CASE("a drop that slows to rest raises no doubt", "[record][plausibility]") {
  const Drop drop(0, kStop, 4.0, 200);
  CHECK(drop.check().empty());
}

TEST_CASE("a pulse of the wrong sign is refused with the advice to negate the column", "[record][plausibility]") {
  const Drop drop(0, kStop, -4.0, 200);  // speeds up from 5.6 to 11.2 m/s
  CHECK_THROWS_WITH(drop.check(), Catch::Contains("deceleration_g looks like it has the wrong sign") &&
                                      Catch::Contains("never slows") && Catch::Contains("negate the column"));
  CHECK_THROWS_WITH(check_impact_kinematics(drop.interpret(), g, "acceleration_m_s2"),
                    Catch::Contains("acceleration_m_s2 looks like it has the wrong sign"));
}

TEST_CASE("a body that never slows after the impact time has no impact there", "[record][plausibility]") {
  const Drop free_fall(900, 0, 0.0, 0);  // free fall all along: never below −1 g, so no sign to blame
  CHECK_THROWS_WITH(free_fall.check(), Catch::Contains("never slows") && Catch::Contains("impact_time_s") &&
                                           !Catch::Contains("wrong sign"));
  // Slowing by 1 % of v0 (0.056 m/s) is enough: 4 samples at 10 g take 0.068 m/s off, then it falls on.
  const Drop barely(0, 4, 10.0, 300, -1.0);
  CHECK_NOTHROW(barely.check());
}

TEST_CASE("a body faster than free fall from the impact is refused", "[record][plausibility]") {
  // Slowed at first (10 samples at 4 g: −0.078 m/s), then pushed down at 1.5 g net, half a g beyond
  // gravity: it is 0.093 m/s below free fall at 2 ms and gains 0.5 g on it, so it passes free fall
  // by 5 % of v0 (0.28 m/s) after (0.28 + 0.093)/(0.5 g) = 0.076 s, 380 samples.
  const Drop pushed(0, 10, 4.0, 600, -1.5);
  CHECK_THROWS_WITH(pushed.check(),
                    Catch::Contains("faster than free fall") && Catch::Contains("sign or zero offset is wrong"));
  const Drop shorter(0, 10, 4.0, 300, -1.5);  // 0.06 s of it: 0.20 m/s beyond, within the allowance
  CHECK_NOTHROW(shorter.check());             // flagged as a rise above v0 instead
}

TEST_CASE("a rebound faster than the impact's energy allows is refused", "[record][plausibility]") {
  // Stopped at 0.143 s, 0.400 m deep; 4 g on for 0.1 s more throws it up at 3.9 m/s, within the
  // √(5.6² + 2 g 0.4) = 6.27 m/s its energy allows; 0.2 s more, 7.8 m/s, is beyond 1.05 × 6.27 m/s.
  const Drop bounce(0, kStop + 500, 4.0, 0);
  CHECK(bounce.check().empty());
  const Drop catapult(0, kStop + 1000, 4.0, 0);
  CHECK_THROWS_WITH(catapult.check(), Catch::Contains("rises at") && Catch::Contains("energy"));
}

TEST_CASE("an impact time set before the impact rises above the impact velocity: a warning", "[record][plausibility]") {
  // 349 intervals of free fall after the given impact time: 5.6 + 9.81 × 0.0698 = 6.285 m/s, 12 % above.
  const Drop early(350, 801, 4.0, 200);
  const auto warnings = early.check();
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("rises to 6.285 m/s") && Catch::Contains("12% above") &&
                              Catch::Contains("impact time too early"));
  const Drop slightly(200, 764, 4.0, 200);  // 0.04 s: 7 %, within the 10 % a cone can take
  CHECK(slightly.check().empty());
}

TEST_CASE("a record that ends while the body still moves down: a warning", "[record][plausibility]") {
  const Drop cut(0, kStop / 2, 4.0, 0);  // half the slowing: still at 2.8 m/s
  const auto warnings = cut.check();
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("still moving down at 2.8") && Catch::Contains("final_penetration_m"));
}

TEST_CASE("an impact velocity integrated from release that is not downward is refused", "[record][plausibility]") {
  Drop drop(0, kStop, 4.0, 200);
  InterpretedRecord r = drop.interpret();
  r.impact_velocity_m_s = -0.0017;  // a record that starts at the impact, integrated as if from release
  r.impact_velocity_integrated = true;
  CHECK_THROWS_WITH(check_impact_kinematics(r, g, "deceleration_g"),
                    Catch::Contains("integrated from rest") && Catch::Contains("impact_velocity_m_s"));
}
