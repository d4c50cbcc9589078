/// The penetrometer outline: the BlueDrop's cone height, distances and normals
/// at the tip, the flank, the rounded edge and the body.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/penetrometer_geometry.hpp"

using ffp::kPi;
using ffp::mpm::PenetrometerGeometry;
using ffp::mpm::PenetrometerShape;

namespace {
PenetrometerShape blue_drop() { return PenetrometerShape{}; }  // 60° cone, R = 4.375 cm
constexpr double kTight = 1e-12;                               // pure geometry: round-off only
}  // namespace

TEST_CASE("the 60° cone of radius 4.375 cm is 7.58 cm high (paper: about 7.55 cm)", "[ffp][geometry]") {
  CHECK(blue_drop().cone_height_m() == Approx(0.04375 * std::sqrt(3.0)).epsilon(kTight));
}

TEST_CASE("a point on the axis below the tip is its distance away with a downward normal", "[ffp][geometry]") {
  const PenetrometerGeometry g(blue_drop());
  const auto q = g.query(0.0, -0.03, 0.0);
  CHECK(q.signed_distance_m == Approx(0.03).epsilon(kTight));
  CHECK(q.normal_r == Approx(0.0).margin(kTight));
  CHECK(q.normal_z == Approx(-1.0).epsilon(kTight));
}

TEST_CASE("a point off the cone flank has the flank's outward normal", "[ffp][geometry]") {
  const PenetrometerGeometry g(blue_drop());
  const double half = kPi / 6;
  // Foot point on the flank at 3 cm along it, pushed 5 mm outward.
  const double s = 0.03, offset = 0.005;
  const double r = s * std::sin(half) + offset * std::cos(half);
  const double z = s * std::cos(half) - offset * std::sin(half);
  const auto q = g.query(r, z + 0.2, 0.2);  // tip at z = 0.2 m: queries are relative to it
  CHECK(q.signed_distance_m == Approx(offset).epsilon(1e-9));
  CHECK(q.normal_r == Approx(std::cos(half)).epsilon(1e-9));
  CHECK(q.normal_z == Approx(-std::sin(half)).epsilon(1e-9));
  // The same distance inside is negative.
  const auto inside =
      g.query(s * std::sin(half) - offset * std::cos(half), s * std::cos(half) + offset * std::sin(half) + 0.2, 0.2);
  CHECK(inside.signed_distance_m == Approx(-offset).epsilon(1e-9));
}

TEST_CASE("beside the body the normal is radial", "[ffp][geometry]") {
  const PenetrometerGeometry g(blue_drop());
  const auto q = g.query(0.06, 0.3, 0.0);
  CHECK(q.signed_distance_m == Approx(0.06 - 0.04375).epsilon(1e-12));
  CHECK(q.normal_r == Approx(1.0));
  CHECK(q.normal_z == Approx(0.0).margin(kTight));
}

TEST_CASE("the rounded edge is a smooth arc between cone and body", "[ffp][geometry]") {
  const PenetrometerGeometry g(blue_drop());
  const auto& s = g.shape();
  // The outline radius is continuous and never exceeds the base radius.
  double previous = 0.0;
  for (int i = 1; i <= 2000; ++i) {
    const double h = i * 0.1 / 2000;
    const double r = g.radius_at(h);
    CHECK(r <= s.base_radius_m + 1e-15);
    CHECK(std::abs(r - previous) < 1e-3);  // no jumps larger than the step allows (slope tan 30°)
    previous = r;
  }
  // The fillet shaves volume off a sharp cone-cylinder: the volume lies between
  // the sharp body and the body without the fillet's corner region.
  PenetrometerShape sharp = s;
  sharp.edge_radius_m = 0.0;
  const double sharp_volume = kPi * s.base_radius_m * s.base_radius_m * (s.body_length_m + s.cone_height_m() / 3.0);
  CHECK(sharp.volume_m3() == Approx(sharp_volume).epsilon(1e-6));
  CHECK(s.volume_m3() < sharp_volume);
  CHECK(s.volume_m3() > 0.99 * sharp_volume);
}

TEST_CASE("inside and outside agree with the outline radius", "[ffp][geometry]") {
  const PenetrometerGeometry g(blue_drop());
  for (double h : {0.001, 0.02, 0.07, 0.075, 0.08, 0.3}) {
    const double r = g.radius_at(h);
    CHECK(g.contains(0.99 * r, h, 0.0));
    CHECK_FALSE(g.contains(1.01 * r + 1e-6, h, 0.0));
    CHECK(std::abs(g.query(r, h, 0.0).signed_distance_m) < 1e-9);
  }
}

TEST_CASE("a flat tip (apex 180°) is a disc: no cone, a downward normal below it, the body's full radius at once",
          "[ffp][geometry][punch]") {
  PenetrometerShape punch;
  punch.cone_apex_angle_rad = kPi;
  punch.base_radius_m = 0.05;
  punch.edge_radius_m = 0.0;
  punch.body_length_m = 0.1;
  CHECK(punch.flat_tip());
  CHECK(punch.cone_height_m() == 0.0);
  const PenetrometerGeometry g(punch);
  CHECK(g.radius_at(0.0) == Approx(0.05).epsilon(kTight));
  CHECK(g.radius_at(0.05) == Approx(0.05).epsilon(kTight));
  for (double r : {0.0, 0.02, 0.049}) {
    const auto q = g.query(r, -0.004, 0.0);
    CHECK(q.signed_distance_m == Approx(0.004).epsilon(kTight));
    CHECK(q.normal_r == Approx(0.0).margin(kTight));
    CHECK(q.normal_z == Approx(-1.0).epsilon(kTight));
  }
  CHECK(g.contains(0.03, 0.001, 0.0));
  CHECK_FALSE(g.contains(0.051, 0.001, 0.0));
  CHECK(punch.volume_m3() == Approx(kPi * 0.05 * 0.05 * 0.1).epsilon(1e-6));
}
