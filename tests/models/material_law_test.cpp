// One place turns a parameter set into a law and gives its at-rest K0.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/material_law.hpp"
#include "models/math_constants.hpp"

using namespace ffp;

TEST_CASE("at-rest K0: Jaky 1 − sin φ'_p is 0.384 for 38° (the paper's Table 1: 0.39) and an elastic body ν/(1 − ν)", "[models][k0]") {
  const double degree = kDegree;
  const ElasticConstants sand{2.5e6, 0.33};
  CHECK(at_rest_k0(MohrCoulombParameters{sand, 38.0 * degree, 0.0, 0.0}) == Approx(0.3843).margin(5e-5));
  StrainSofteningParameters softening;
  softening.elastic = sand;
  softening.friction_peak_rad = 60.0 * degree;  // the peak, not the residual, sets K0
  softening.friction_residual_rad = 32.0 * degree;
  CHECK(at_rest_k0(softening) == Approx(1.0 - std::sin(60.0 * degree)));
  CHECK(at_rest_k0(sand) == Approx(0.33 / 0.67));
}

TEST_CASE("make_law keeps the alternative: elastic, Mohr-Coulomb, SSMC", "[models]") {
  const ElasticConstants e{1e6, 0.3};
  CHECK(std::holds_alternative<LinearElastic>(make_law(e)));
  CHECK(std::holds_alternative<MohrCoulomb>(make_law(MohrCoulombParameters{e, 0.5, 0.0, 0.0})));
  StrainSofteningParameters s;
  s.elastic = e;
  s.friction_peak_rad = 0.6;
  s.friction_residual_rad = 0.5;
  s.softening_factor = 8.0;
  CHECK(std::holds_alternative<StrainSofteningMohrCoulomb>(make_law(s)));
}
