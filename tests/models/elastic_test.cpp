#include <catch2/catch.hpp>

#include "models/elastic.hpp"
#include "tensor_test_helpers.hpp"

using namespace ffp;
using namespace ffp::test;

TEST_CASE("elastic moduli are exact on isotropic and oedometric increments", "[elastic]") {
  const ElasticConstants e{2.5e6, 0.33};
  const LinearElastic law(e);
  SECTION("isotropic: Δp = K Δε_v") {
    Voigt stress = isotropic(-1.72e3);
    law.update(stress, isotropic(-1e-3));
    CHECK(-trace(stress) / 3.0 - 1.72e3 == Approx(e.bulk_modulus() * 3e-3).epsilon(1e-13));
    CHECK(e.bulk_modulus() == Approx(2.5e6 / (3 * (1 - 2 * 0.33))).epsilon(1e-15));
  }
  SECTION("oedometric: Δσ_a = M Δε_a, Δσ_r = λ Δε_a") {
    Voigt stress = Voigt::Zero();
    Voigt increment = Voigt::Zero();
    increment[1] = -1e-3;
    law.update(stress, increment);
    const double M = 2.5e6 * (1 - 0.33) / ((1 + 0.33) * (1 - 2 * 0.33));
    CHECK(stress[1] == Approx(-M * 1e-3).epsilon(1e-13));
    CHECK(stress[0] / stress[1] == Approx(0.33 / (1 - 0.33)).epsilon(1e-13));  // K0 = ν/(1 − ν)
  }
  SECTION("pure shear: Δσ_12 = 2G Δε_12") {
    Voigt stress = Voigt::Zero();
    Voigt increment = Voigt::Zero();
    increment[3] = 1e-3;
    law.update(stress, increment);
    CHECK(stress[3] == Approx(2 * e.shear_modulus() * 1e-3).epsilon(1e-14));
    CHECK(trace(stress) == 0.0);
  }
}
