/// The nodal contact law (Bardenhagen et al. 2000/2001) against Coulomb's law:
/// free separation, no interpenetration, stick inside the friction cone, slip
/// on it with the tangential impulse μ times the normal one.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/contact_law.hpp"

using ffp::kDegree;
using ffp::kPi;
using ffp::mpm::contact_velocity;
using ffp::mpm::ContactLaw;
using ffp::mpm::Vector2;

namespace {
constexpr double kExact = 1e-14;  // a handful of flops: round-off only
const double kMu = std::tan(20.0 * kDegree);
// The cone flank's outward normal (60° apex) and its tangent.
const Vector2 kNormal{std::cos(kPi / 6), -std::sin(kPi / 6)};
const Vector2 kTangent{std::sin(kPi / 6), std::cos(kPi / 6)};

Vector2 combine(double normal, double tangential, Vector2 base = {}) {
  return {base.r + normal * kNormal.r + tangential * kTangent.r, base.z + normal * kNormal.z + tangential * kTangent.z};
}
double normal_part(Vector2 v, Vector2 s) { return (v.r - s.r) * kNormal.r + (v.z - s.z) * kNormal.z; }
double tangential_part(Vector2 v, Vector2 s) { return (v.r - s.r) * kTangent.r + (v.z - s.z) * kTangent.z; }
}  // namespace

TEST_CASE("contact: a body moving away from the surface is left alone (free separation)", "[ffp][contact]") {
  const Vector2 surface{0.0, -5.6};
  const ContactLaw law{kMu, false, 1.0};
  for (double tangential : {-3.0, 0.0, 2.0}) {
    const Vector2 v = combine(0.7, tangential, surface);  // separating along +n
    const Vector2 after = contact_velocity(v, surface, kNormal, law);
    CHECK(after.r == v.r);
    CHECK(after.z == v.z);
  }
}

TEST_CASE("contact: an approaching body loses its normal relative velocity (no interpenetration)", "[ffp][contact]") {
  const Vector2 surface{0.0, -5.6};
  const Vector2 v = combine(-2.0, 5.0, surface);
  for (const ContactLaw& law : {ContactLaw{0.0, false, 1.0}, ContactLaw{kMu, false, 1.0}, ContactLaw{0.0, true, 1.0}}) {
    const Vector2 after = contact_velocity(v, surface, kNormal, law);
    CHECK(normal_part(after, surface) == Approx(0.0).margin(kExact));
  }
}

TEST_CASE("contact: frictionless sliding keeps the tangential velocity", "[ffp][contact]") {
  const Vector2 surface{0.1, -3.0};
  const Vector2 v = combine(-1.5, 2.5, surface);
  const Vector2 after = contact_velocity(v, surface, kNormal, ContactLaw{0.0, false, 1.0});
  CHECK(tangential_part(after, surface) == Approx(2.5).epsilon(kExact));
}

TEST_CASE("contact: inside the friction cone the body sticks (Coulomb)", "[ffp][contact]") {
  // |Δv_t| ≤ μ|Δv_n|: the friction impulse can cancel the slip entirely.
  const Vector2 surface{0.0, -5.6};
  const double normal = -2.0;
  for (double tangential : {0.0, 0.5 * kMu * 2.0, 0.999 * kMu * 2.0, -0.9 * kMu * 2.0}) {
    const Vector2 after =
        contact_velocity(combine(normal, tangential, surface), surface, kNormal, ContactLaw{kMu, false, 1.0});
    CHECK(after.r == Approx(surface.r).margin(kExact));
    CHECK(after.z == Approx(surface.z).epsilon(kExact));
  }
}

TEST_CASE("contact: on the cone it slips, the tangential impulse is mu times the normal one", "[ffp][contact]") {
  // Per unit mass: normal impulse |Δv·n|, tangential impulse μ|Δv·n|, slip in the same direction.
  const Vector2 surface{0.0, -5.6};
  const double normal = -2.0;
  for (double tangential : {1.01 * kMu * 2.0, 3.0, -4.0}) {
    const Vector2 v = combine(normal, tangential, surface);
    const Vector2 after = contact_velocity(v, surface, kNormal, ContactLaw{kMu, false, 1.0});
    const double slip = tangential_part(after, surface);
    CHECK(std::abs(slip) == Approx(std::abs(tangential) - kMu * std::abs(normal)).epsilon(1e-13));
    CHECK(slip * tangential > 0.0);  // friction never reverses the slip
    const double normal_impulse = normal_part(after, surface) - normal;
    const double tangential_impulse = std::abs(tangential_part(after, surface) - tangential);
    CHECK(tangential_impulse == Approx(kMu * normal_impulse).epsilon(1e-13));
  }
}

TEST_CASE("contact: the fully rough limit takes the surface's velocity", "[ffp][contact]") {
  const Vector2 surface{0.2, -5.6};
  const Vector2 after = contact_velocity(combine(-0.1, 50.0, surface), surface, kNormal, ContactLaw{0.0, true, 1.0});
  CHECK(after.r == Approx(surface.r).epsilon(kExact));
  CHECK(after.z == Approx(surface.z).epsilon(kExact));
}

TEST_CASE("contact: the 2001 velocity scaling caps a correction's strain per step and leaves small ones whole",
          "[ffp][contact]") {
  const Vector2 surface{0.0, -5.6};
  const Vector2 v = combine(-2.0, 3.0, surface);
  const ContactLaw capped{kMu, false, 0.75};
  const Vector2 full = contact_velocity(v, surface, kNormal, ContactLaw{kMu, false, 0.0});
  const double correction = std::hypot(full.r - v.r, full.z - v.z);
  // Below the cap (Δt/h such that |Δv|Δt/h = 0.06, the FFP's typical value): the whole correction.
  const Vector2 small = contact_velocity(v, surface, kNormal, capped, 0.06 / correction);
  CHECK(small.r == Approx(full.r).epsilon(kExact));
  CHECK(small.z == Approx(full.z).epsilon(kExact));
  // Twice the cap: half of the correction, so that its strain in the step is exactly the cap.
  const Vector2 large = contact_velocity(v, surface, kNormal, capped, 1.5 / correction);
  CHECK(large.r == Approx(v.r + 0.5 * (full.r - v.r)).epsilon(kExact));
  CHECK(large.z == Approx(v.z + 0.5 * (full.z - v.z)).epsilon(kExact));
  CHECK(std::hypot(large.r - v.r, large.z - v.z) * 1.5 / correction == Approx(0.75).epsilon(kExact));
}
