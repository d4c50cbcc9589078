/// Geostatic column under gravity: σ'_v = γ·depth, σ'_h = K0·σ'_v.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// A column of sand-like material, graded vertical cells (finer near the
/// surface) so the check also covers non-uniform spacing.
ModelDescription column(ShapeFunction shape, std::optional<GeostaticStress> k0, MaterialLaw law) {
  ModelDescription m;
  m.r_nodes_m = {0.0, 0.03, 0.07, 0.12, 0.2};
  m.z_nodes_m = {0.0};
  double h = 0.06;
  while (m.z_nodes_m.back() < 1.0 - 1e-9) {
    m.z_nodes_m.push_back(std::min(1.0, m.z_nodes_m.back() + h));
    h = std::max(0.02, h * 0.9);
  }
  for (double z : {1.05, 1.1}) m.z_nodes_m.push_back(z);
  m.bodies.push_back(BodyDescription{"soil", std::move(law), 1500.0, BoxRegion{0, 0.2, 0, 1.0}, 2, 2, 0.0, 0.0, k0});
  m.gravity_m_s2 = 9.81;
  m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
  m.solver.shape_function = shape;
  return m;
}

}  // namespace

TEST_CASE("geostatic K0 column stays at sigma'_v = gamma z, sigma'_h = K0 sigma'_v for 10,000 steps",
          "[mpm][verification][geostatic]") {
  const double gamma = 1500.0 * 9.81, H = 1.0, k0 = 0.39;
  auto check = [&](ShapeFunction shape, MaterialLaw law) {
    Simulation s(column(shape, GeostaticStress{k0, H}, std::move(law)));
    for (int k = 0; k < 10000; ++k) s.advance();
    double worst_v = 0.0, worst_h = 0.0, worst_rz = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      const double sv = gamma * (H - s.particles.z0[p]);
      const Voigt& sig = s.particles.stress[p];
      worst_v = std::max(worst_v, std::abs(-sig[1] - sv));
      worst_h = std::max({worst_h, std::abs(-sig[0] - k0 * sv), std::abs(-sig[2] - k0 * sv)});
      worst_rz = std::max(worst_rz, std::abs(sig[3]));
    }
    INFO("after " << s.step << " steps (t = " << s.time_s << " s): max |Δσ_v|, |Δσ_h|, |σ_rz| = " << worst_v << ", "
                  << worst_h << ", " << worst_rz << " Pa against γH = " << gamma * H << " Pa");
    // 1 % of the stress, measured against the largest (γH) so
    // that near-surface particles with tiny stresses do not make the check vacuous.
    // Particles at quadrature-exact positions make the K0 state an exact discrete
    // equilibrium (the hoop term cancels σ_h's radial divergence node by node), so the
    // measured drift is round-off (~1e-14 γH) — a missing or wrong hoop or gravity
    // term shows at once.
    CHECK(worst_v < 0.01 * gamma * H);
    CHECK(worst_h < 0.01 * gamma * H);
    CHECK(worst_rz < 0.01 * gamma * H);
    CHECK(measure(s).max_speed_m_s < 1e-9);
  };
  const ElasticConstants e{20e6, 0.3};
  SECTION("GIMP, linear elastic") { check(ShapeFunction::gimp, LinearElastic(e)); }
  SECTION("linear, linear elastic") { check(ShapeFunction::linear, LinearElastic(e)); }
  SECTION("GIMP, Mohr-Coulomb (phi' = 39°, K0 inside the yield surface)") {
    check(ShapeFunction::gimp, MohrCoulomb(MohrCoulombParameters{e, 39.0 * kDegree, 0.0, 0.0}));
  }
}

TEST_CASE("gravity switched on a weightless elastic column settles to sigma_v = gamma z, sigma_h = nu/(1-nu) sigma_v",
          "[mpm][verification][geostatic]") {
  // The dynamic route to the same state: no initial stress, gravity from t = 0,
  // Cundall local damping to settle. Uniaxial strain gives σ_h = ν/(1−ν)·σ_v.
  const double gamma = 1500.0 * 9.81, H = 1.0, nu = 0.3;
  ModelDescription m = column(ShapeFunction::gimp, std::nullopt, LinearElastic(ElasticConstants{20e6, nu}));
  m.solver.local_damping = 0.1;
  Simulation s(m);
  while (s.time_s < 1.0) s.advance();
  // Constant-strain cells carry the stress of their centre: compare each cell's mean
  // particle stress with the exact value at the cell's mean particle depth. (Single
  // particles sit h/4 off it, which on the coarsest 6 cm cells is 1.5 % of γH.)
  const std::size_t cells = s.grid.cells();
  std::vector<double> count(cells), depth(cells), sv(cells), sh(cells);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    const std::size_t c = s.grid.cell(s.grid.r.cell_of(s.particles.r0[p]), s.grid.z.cell_of(s.particles.z0[p]));
    count[c] += 1;
    depth[c] += H - s.particles.z0[p];
    sv[c] -= s.particles.stress[p][1];
    sh[c] -= s.particles.stress[p][0];
  }
  double worst_v = 0.0, worst_h = 0.0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (count[c] == 0) continue;
    const double exact = gamma * depth[c] / count[c];
    worst_v = std::max(worst_v, std::abs(sv[c] / count[c] - exact));
    worst_h = std::max(worst_h, std::abs(sh[c] / count[c] - nu / (1 - nu) * exact));
  }
  INFO("max cell |Δσ_v| = " << worst_v << " Pa, max |Δσ_h| = " << worst_h << " Pa, γH = " << gamma * H << " Pa");
  // 1 % of γH as above.
  CHECK(worst_v < 0.01 * gamma * H);
  CHECK(worst_h < 0.01 * gamma * H);
}
