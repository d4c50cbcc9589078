#include <catch2/catch.hpp>

#include "models/principal_stress.hpp"
#include "tensor_test_helpers.hpp"

using namespace ffp;
using namespace ffp::test;

// Rebuilding with unchanged values must give the tensor back to rounding:
// 1e-14 of its largest entry is a few ulps of the arithmetic involved.
constexpr double kRoundTrip = 1e-14;

TEST_CASE("principal stresses rebuild the tensor they came from", "[principal]") {
  std::mt19937_64 rng(7);
  for (int n = 0; n < 2000; ++n) {
    Voigt s = random_voigt(rng, 1e5);
    if (n % 2 == 0) s[4] = s[5] = 0.0;  // the axisymmetric fast path
    const PrincipalStresses p(s);
    CHECK(p.planar() == (n % 2 == 0));
    CHECK(p.values()[0] >= p.values()[1]);
    CHECK(p.values()[1] >= p.values()[2]);
    CHECK(p.values().sum() == Approx(trace(s)).margin(kRoundTrip * max_abs(s) * 3));
    CHECK(max_abs(p.with_values(p.values()) - s) <= kRoundTrip * 10 * max_abs(s));
  }
}

TEST_CASE("the in-plane fast path agrees with the general 3×3 solver", "[principal]") {
  std::mt19937_64 rng(11);
  for (int n = 0; n < 500; ++n) {
    Voigt s = random_voigt(rng, 1.0);
    s[4] = s[5] = 0.0;
    Voigt nearly = s;
    nearly[4] = 1e-300;  // forces the general path, changes nothing measurable
    const PrincipalStresses fast(s), general(nearly);
    CHECK((fast.values() - general.values()).cwiseAbs().maxCoeff() <= 1e-14 * 10);
    // New values on the same directions: both paths must agree on where they go.
    const Eigen::Vector3d changed(fast.values()[0] * 0.5, fast.values()[1] - 0.25, fast.values()[2] * 2.0);
    CHECK(max_abs(fast.with_values(changed) - general.with_values(changed)) <= 1e-12);
  }
}

TEST_CASE("coincident principal stresses are handled exactly", "[principal]") {
  // Hydrostatic: any basis is a basis of eigenvectors.
  const Voigt hydrostatic = isotropic(-3.0);
  for (Voigt s : {hydrostatic, Voigt(Voigt::Zero())}) {
    const PrincipalStresses p(s);
    CHECK(p.values()[0] == p.values()[2]);
    CHECK(max_abs(p.with_values(Eigen::Vector3d::Constant(1.5)) - isotropic(1.5)) <= 1e-15);
  }
  // A triaxial state rotated in 3D (two equal values, general path).
  std::mt19937_64 rng(3);
  Voigt triaxial = Voigt::Zero();
  triaxial << -1.0, -3.0, -1.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix3d r = random_rotation(rng);
  const Voigt s = rotated(triaxial, r);
  const PrincipalStresses p(s);
  CHECK(p.values()[0] == Approx(-1.0).margin(1e-14));
  CHECK(p.values()[1] == Approx(-1.0).margin(1e-14));
  CHECK(p.values()[2] == Approx(-3.0).margin(1e-14));
  // Keeping the pair equal (as edge and apex returns do) rebuilds the rotated target.
  triaxial << -0.5, -2.0, -0.5, 0.0, 0.0, 0.0;
  CHECK(max_abs(p.with_values(Eigen::Vector3d(-0.5, -0.5, -2.0)) - rotated(triaxial, r)) <= 1e-14);
}
