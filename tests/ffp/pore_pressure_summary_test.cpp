/// The shoulder pore pressure's summary figures (drivers/app/pore_pressure_summary.hpp) on
/// hand-made rows: the extremes, the rest, and the dissipation to 10 % or the reason it is absent.
#include <catch2/catch.hpp>

#include <vector>

#include "drivers/app/pore_pressure_summary.hpp"

using namespace ffp;

TEST_CASE("u2 figures: peak, minimum, rest at the first non-downward row, dissipation to 10 % of the excess",
          "[ffp][saturated][summary]") {
  // time, velocity (+ down), u2, excess
  const std::vector<ShoulderPressureRow> rows = {
      {0.00, 5.0, 10.0, 0.0},  {0.01, 3.0, 60.0, 50.0}, {0.02, 1.0, -30.0, -40.0}, {0.03, -0.1, 50.0, 40.0},
      {0.04, 0.0, 30.0, 20.0}, {0.05, 0.0, 14.0, 4.0},  {0.06, 0.0, 12.0, 2.0}};
  const ShoulderPressureFigures f = shoulder_pressure_figures(rows);
  CHECK(f.peak_kPa == 60.0);
  CHECK(f.time_of_peak_s == 0.01);
  CHECK(f.min_kPa == -30.0);
  CHECK(f.time_of_min_s == 0.02);
  REQUIRE(f.rest_time_s);
  CHECK(*f.rest_time_s == 0.03);
  CHECK(f.excess_at_rest_kPa == 40.0);
  REQUIRE(f.dissipation_time_s);
  CHECK(*f.dissipation_time_s == Approx(0.02));  // 4 kPa ≤ 10 % of 40 kPa first at 0.05 s
}

TEST_CASE("u2 figures: no dissipation time, with the reason, when the body never stops or the excess stays",
          "[ffp][saturated][summary]") {
  SECTION("still moving down at the end") {
    const std::vector<ShoulderPressureRow> rows = {{0.0, 5.0, 10.0, 0.0}, {0.01, 4.0, 20.0, 10.0}};
    const ShoulderPressureFigures f = shoulder_pressure_figures(rows);
    CHECK_FALSE(f.rest_time_s);
    CHECK_FALSE(f.dissipation_time_s);
    CHECK(f.dissipation_note.find("still moves down") != std::string::npos);
  }
  SECTION("the excess stays above 10 %") {
    const std::vector<ShoulderPressureRow> rows = {
        {0.0, 5.0, 10.0, 0.0}, {0.01, 0.0, 30.0, 20.0}, {0.02, 0.0, 20.0, 10.0}};
    const ShoulderPressureFigures f = shoulder_pressure_figures(rows);
    REQUIRE(f.rest_time_s);
    CHECK_FALSE(f.dissipation_time_s);
    CHECK(f.dissipation_note.find("50 %") != std::string::npos);
  }
}
