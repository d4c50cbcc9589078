// One place turns a parameter set into a law and gives its at-rest K0.
#include <catch2/catch.hpp>

#include <cmath>
#include <span>
#include <vector>

#include "models/material_law.hpp"
#include "models/math_constants.hpp"

using namespace ffp;

TEST_CASE("at-rest K0: Jaky 1 − sin φ'_p is 0.384 for 38° (the paper's Table 1: 0.39) and an elastic body ν/(1 − ν)",
          "[models][k0]") {
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

namespace {

std::vector<MaterialLaw> every_law() {
  const double degree = kDegree;
  const ElasticConstants sand{2.5e6, 0.33};
  StrainSofteningParameters softening;
  softening.elastic = sand;
  softening.friction_peak_rad = 60.0 * degree;
  softening.friction_residual_rad = 32.0 * degree;
  softening.dilatancy_peak_rad = 5.0 * degree;
  softening.softening_factor = 8.0;
  return {make_law(sand), make_law(MohrCoulombParameters{sand, 39.0 * degree, 0.0, 0.0}), make_law(softening)};
}

}  // namespace

TEST_CASE("one update for every law: a batch over contiguous states equals the points one by one", "[models]") {
  for (const MaterialLaw& law : every_law()) {
    CAPTURE(law.index());
    CHECK(initial_state(law).index() == law.index());
    CHECK(elastic_constants(law).youngs_modulus_Pa == 2.5e6);
    // Drained-like shear from 1.72 kPa: elastic for the elastic law, past yield for the others.
    Voigt start;
    start << -1720.0, -1720.0, -1720.0, 0.0, 0.0, 0.0;
    std::vector<Voigt> stress(5, start), one_by_one = stress;
    std::vector<Voigt> increment(5);
    for (int i = 0; i < 5; ++i) increment[i] << 2e-4 * i, -4e-4 * i, 2e-4 * i, 1e-4, 0.0, 0.0;
    MaterialStates states = initial_states(law, 7);
    update(law, stress, increment, states, 2, 1e-2);  // points 2..6 of the group
    for (int i = 0; i < 5; ++i) {
      MaterialState state = initial_state(law);
      update(law, one_by_one[i], increment[i], state, 1e-2);
      CHECK(stress[i] == one_by_one[i]);
      for (StateOutput o : state_outputs(law)) {
        std::vector<double> out(1);
        state_output(law, states, 2 + i, std::span<const Voigt>(&stress[i], 1), o, out);
        CHECK(out[0] == state_output(law, state, mean_pressure(one_by_one[i]), o));
      }
    }
  }
}

TEST_CASE("state outputs and the Mohr-Coulomb strength: a softening law reports its state and starts at its peak",
          "[models]") {
  const std::vector<MaterialLaw> laws = every_law();
  CHECK(state_outputs(laws[0]).empty());
  CHECK(state_outputs(laws[1]).empty());  // perfectly plastic: nothing changes
  CHECK(has_state_output(laws[2], StateOutput::plastic_deviatoric_strain));
  CHECK_FALSE(mohr_coulomb_strength(laws[0], initial_state(laws[0]), 1720.0).has_value());
  CHECK(mohr_coulomb_strength(laws[1], initial_state(laws[1]), 1720.0)->friction_angle_rad ==
        std::get<MohrCoulomb>(laws[1]).parameters().friction_angle_rad);
  const MaterialState virgin = initial_state(laws[2]);
  CHECK(mohr_coulomb_strength(laws[2], virgin, 1720.0)->friction_angle_rad == Approx(60.0 * kDegree));
  CHECK(state_output(laws[2], virgin, 1720.0, StateOutput::plastic_deviatoric_strain) == 0.0);
  CHECK(state_output(laws[2], virgin, 1720.0, StateOutput::friction_angle) == Approx(60.0 * kDegree));
}
