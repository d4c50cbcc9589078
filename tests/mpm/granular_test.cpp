/// Granular bodies that lose grain contact: below the disconnection density a
/// particle is stress-free and the CFL step takes its wave speed at that density.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/math_constants.hpp"
#include "models/mohr_coulomb.hpp"
#include "mpm/simulation.hpp"
#include "mpm/stages.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

constexpr double kDensity = 1500.0;
const MohrCoulombParameters kSand{ElasticConstants{2.5e6, 0.33}, 39.0 * kPi / 180.0, 0.0, 0.0};

ModelDescription sand_block(double disconnected_below_kg_m3) {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 5);
  m.z_nodes_m = testing::nodes(0.0, 0.1, 5);
  m.bodies.push_back(BodyDescription{"sand", MohrCoulomb(kSand), kDensity, BoxRegion{0.0, 0.1, 0.0, 0.1}, 2, 2, 0.0,
                                     0.0, std::nullopt, disconnected_below_kg_m3});
  return m;
}

}  // namespace

TEST_CASE("a sand particle below its disconnection density carries no stress and steps at that density",
          "[mpm][granular]") {
  Simulation s(sand_block(0.5 * kDensity));
  const Voigt compression = (Voigt() << -1e3, -1e3, -1e3, 0.0, 0.0, 0.0).finished();
  for (auto& sigma : s.particles.stress) sigma = compression;
  s.particles.volume[0] *= 3.0;  // a third of its density: the grains no longer touch
  s.particles.volume[1] *= 1.5;  // two thirds: still in contact
  update_stresses(s);            // zero strain increment: only the contact state can change σ
  CHECK(s.particles.stress[0].norm() == 0.0);
  CHECK((s.particles.stress[1] - compression).norm() <= 1e-12 * compression.norm());
  CHECK((s.particles.stress[2] - compression).norm() <= 1e-12 * compression.norm());

  // With every particle at rest and stress-free, Δt_CFL = h_min / c_p; the
  // disconnected particle counts at 750 kg/m³ (√2 c_p), not at 500 (√3 c_p).
  for (auto& sigma : s.particles.stress) sigma.setZero();
  const double M = kSand.elastic.constrained_modulus();
  CHECK(cfl_time_step_limit(s) == Approx(0.02 / std::sqrt(M / (0.5 * kDensity))).epsilon(1e-12));

  Simulation continuum(sand_block(0.0));  // the same block without the rule
  continuum.particles.volume[0] *= 3.0;
  CHECK(cfl_time_step_limit(continuum) == Approx(0.02 / std::sqrt(M / (kDensity / 3.0))).epsilon(1e-12));
}

TEST_CASE("a disconnection density at or above the body's density is refused", "[mpm][granular]") {
  CHECK_THROWS_AS(Simulation(sand_block(kDensity)), std::invalid_argument);
  CHECK_THROWS_AS(Simulation(sand_block(-1.0)), std::invalid_argument);
}

TEST_CASE("a disconnected sand particle's volume is held at its limit and it stays out of the strain-smoothing means",
          "[mpm][granular]") {
  const double limit = 0.5 * kDensity;
  Simulation s(sand_block(limit));
  const Voigt compression = (Voigt() << -1e3, -1e3, -1e3, 0.0, 0.0, 0.0).finished();
  for (auto& sigma : s.particles.stress) sigma = compression;
  s.particles.volume[0] *= 5.0;  // J = 5, e.g. pushed off the axis to the shaft
  update_stresses(s);
  // Held at m/ρ_limit: J = 2, however far it was stretched.
  CHECK(s.particles.volume[0] == Approx(s.particles.mass[0] / limit).epsilon(1e-15));
  CHECK(s.particles.stress[0].norm() == 0.0);

  // Its cell's mean stress is that of its connected neighbours (2 × 2 per cell):
  // the stress-free particle neither dilutes it nor takes it in the internal force.
  compute_shape_functions(s);
  smooth_mean_stress(s);
  const std::size_t cell = s.cell[0];
  std::size_t in_cell = 0;
  for (std::size_t p = 0; p < s.particles.size(); ++p) in_cell += s.cell[p] == cell;
  REQUIRE(in_cell == 4);
  CHECK(s.cell_mean_stress[cell] == Approx(-1e3).epsilon(1e-12));
}
