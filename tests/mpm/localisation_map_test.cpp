#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "models/localisation.hpp"
#include "models/math_constants.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"
#include "mpm/localisation_map.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// Principal values s1 ≥ s3 in the r–z plane (s1 along (cos ω, sin ω)) and θθ = s2.
Voigt in_plane_stress(double s1, double s2, double s3, double omega) {
  const double c = std::cos(omega), s = std::sin(omega);
  Voigt v = Voigt::Zero();
  v << s1 * c * c + s3 * s * s, s1 * s * s + s3 * c * c, s2, (s1 - s3) * s * c, 0.0, 0.0;
  return v;
}

}  // namespace

TEST_CASE("the localisation map tests the face and edge particles of a non-associated sand, not the apex",
          "[mpm][localisation]") {
  const double phi = 39.0 * kDegree;
  const MohrCoulombParameters sand{ElasticConstants{2.5e6, 0.33}, phi, 0.0, 0.0};
  MaterialGroup group("sand", MohrCoulomb(sand), 1500.0);
  // Particle 0 belongs to another group; the sand holds particles 1–5.
  group.begin = 1;
  group.end = 6;
  group.states = initial_states(group.law, group.size());
  const double s3 = -10e3, s1 = s3 * (1.0 - std::sin(phi)) / (1.0 + std::sin(phi)), omega = 0.3;
  const std::vector<Voigt> stress = {
      in_plane_stress(s1, s3, s3, omega),                   // not the group's: ignored
      in_plane_stress(2.0 * s1, s1 + 0.5 * s3, s3, omega),  // σ1 more compressive: inside the surface
      in_plane_stress(s1, 0.5 * (s1 + s3), s3, omega),      // on a face, θθ intermediate: localised
      in_plane_stress(s1, s3, 0.5 * (s1 + s3), omega),      // on a face, θθ the major compression: elliptic
      in_plane_stress(s1, s1, s3, omega),                   // compression edge σ_a = σ_θθ: r_min −0.08
      Voigt::Zero(),                                        // apex (c' = 0)
  };
  const LocalisationMap map = map_localisation(group, stress);
  CHECK(map.on_face == 2);
  CHECK(map.on_edge == 1);
  CHECK(map.at_apex == 1);
  CHECK(map.localised_on_face == 1);
  CHECK(map.localised_on_edge == 1);
  CHECK(map.localised_fraction() == Approx(2.0 / 3.0));  // of the face and edge particles; the apex is not tested
  CHECK(map.localised == std::vector<double>{0.0, 0.0, 1.0, 0.0, 1.0, 0.0});
  CHECK(map.place == std::vector<YieldPlace>{YieldPlace::inside, YieldPlace::inside, YieldPlace::localised,
                                             YieldPlace::face, YieldPlace::localised, YieldPlace::apex});
  // The bands are the point diagnostic's: the face's, and the edge's corner.
  const MohrCoulombStrength strength = MohrCoulombStrength::of(phi, 0.0, 0.0);
  CHECK(map.band_angle_deg[2] ==
        Approx(find_localisation(sand.elastic, mohr_coulomb_flow(stress[2], strength).flow).band_normal_rad / kDegree));
  CHECK(
      map.band_angle_deg[4] ==
      Approx(find_localisation(sand.elastic, mohr_coulomb_flow(stress[4], strength).corner).band_normal_rad / kDegree));
  for (std::size_t i : {2, 4}) {
    CHECK(map.band_angle_deg[i] >= 0.0);
    CHECK(map.band_angle_deg[i] < 180.0);
  }
}

TEST_CASE("a linear elastic group never localises", "[mpm][localisation]") {
  MaterialGroup group("body", LinearElastic(ElasticConstants{2e11, 0.3}), 7800.0);
  group.begin = 0;
  group.end = 1;
  group.states = initial_states(group.law, 1);
  const std::vector<Voigt> stress = {Voigt::Constant(-1e6)};
  const LocalisationMap map = map_localisation(group, stress);
  CHECK(map.on_face + map.on_edge + map.at_apex + map.localised_count() == 0);
  CHECK(map.localised_fraction() == 0.0);
}

// θθ the major compression: the perfectly plastic face stays elliptic (H_crit ≈ −0.91 G,
// models/localisation tests); a sand softening fast enough there localises.
TEST_CASE("the localisation map takes a softening sand's hardening modulus", "[mpm][localisation]") {
  const ElasticConstants elastic{2.5e6, 0.33};
  const double phi = 39.0 * kDegree, s3 = -100e3, s1 = s3 * (1.0 - std::sin(phi)) / (1.0 + std::sin(phi));
  const std::vector<Voigt> stress = {in_plane_stress(s1, s3, 0.5 * (s1 + s3), 0.3)};
  auto map_of = [&](MaterialLaw law) {
    MaterialGroup group("sand", std::move(law), 1500.0);
    group.begin = 0;
    group.end = 1;
    group.states = initial_states(group.law, 1);
    return map_localisation(group, stress);
  };
  StrainSofteningParameters softening;
  softening.elastic = elastic;
  softening.friction_peak_rad = phi;
  softening.friction_residual_rad = 32.0 * kDegree;
  // κ = 0: H = (2/√3)(σ1 + σ3) cos φ' η (φ'_p − φ'_r) = −1.35e6 Pa at η = 100, below H_crit = −0.85e6 Pa.
  softening.softening_factor = 100.0;
  const LocalisationMap perfect = map_of(MohrCoulomb(MohrCoulombParameters{elastic, phi, 0.0, 0.0}));
  const LocalisationMap softened = map_of(StrainSofteningMohrCoulomb(softening));
  CHECK(perfect.on_face == 1);
  CHECK(perfect.localised_count() == 0);
  CHECK(softened.on_face == 1);
  CHECK(softened.localised_count() == 1);
  softening.softening_factor = 30.0;  // H = −0.40e6 Pa: above H_crit
  CHECK(map_of(StrainSofteningMohrCoulomb(softening)).localised_count() == 0);
}

TEST_CASE("the localised share counts only with 5 % of the sand yielding, at least one particle",
          "[mpm][localisation]") {
  CHECK(minimum_yielding_for_share(6086) == 305);       // the reference drop at 1 cm: 304.3 rounded up
  CHECK(minimum_yielding_for_share(6080) == 304);       // exactly 5 %
  CHECK(minimum_yielding_for_share(4 * 6086) == 1218);  // four times the particles at h/2: the same share
  CHECK(minimum_yielding_for_share(10) == 1);
  CHECK(minimum_yielding_for_share(0) == 1);  // no sand: no row counts, since none yields
}
