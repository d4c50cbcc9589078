/// Axisymmetric elastic statics: the hoop terms (σ_θθ·S/r in the force, v_r/r
/// in the strain rate) checked against closed-form solutions.
#include <catch2/catch.hpp>

#include <cmath>

#include "models/math_constants.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// A pressure ramped smoothly (half cosine) to p over `ramp`, then held.
std::function<double(double)> ramp(double p, double duration) {
  return [=](double t) { return t >= duration ? p : p * 0.5 * (1.0 - std::cos(kPi * t / duration)); };
}

/// Plane strain (rollers on top and bottom), quasi-static: the load is ramped over
/// many radial periods and Cundall damping removes what is left of the motion.
Simulation run_cylinder(ShapeFunction shape, double inner, double outer, int cells, Side loaded, double p) {
  const double h = (outer - inner) / cells;
  ModelDescription m;
  m.r_nodes_m = testing::nodes(inner, outer + (inner > 0 ? 4 * h : 0.0), cells + (inner > 0 ? 4 : 0));
  m.z_nodes_m = testing::nodes(0.0, 2 * h, 2);
  m.bodies.push_back(testing::elastic_body("cylinder", 10e6, 0.3, 2000.0, BoxRegion{inner, outer, 0, 2 * h}));
  m.boundaries = {inner > 0 ? Fixity::free : Fixity::roller, Fixity::free, Fixity::roller, Fixity::roller};
  m.pressures.push_back({loaded, 0.0, 2 * h, ramp(p, 0.05)});
  m.solver.shape_function = shape;
  m.solver.local_damping = 0.05;
  Simulation s(m);
  while (s.time_s < 0.1) s.advance();
  return s;
}

}  // namespace

TEST_CASE("thick-walled cylinder under internal pressure: radial and hoop stress within 2% of Lamé",
          "[mpm][verification][axisymmetric]") {
  // Lamé: σ_rr = A − B/r², σ_θθ = A + B/r², A = p a²/(b² − a²), B = p a² b²/(b² − a²);
  // plane strain σ_zz = ν(σ_rr + σ_θθ).
  const double a = 0.1, b = 0.3, p = 1e3, nu = 0.3;
  const double A = p * a * a / (b * b - a * a), B = p * a * a * b * b / (b * b - a * a);
  auto check = [&](ShapeFunction shape) {
    const Simulation s = run_cylinder(shape, a, b, 80, Side::inner, p);
    double rr = 0.0, tt = 0.0, zz = 0.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const double r = s.particles.r0[i];
      const Voigt& sig = s.particles.stress[i];
      rr = std::max(rr, std::abs(sig[0] - (A - B / (r * r))) / p);
      tt = std::max(tt, std::abs(sig[2] - (A + B / (r * r))) / p);
      zz = std::max(zz, std::abs(sig[1] - nu * 2 * A) / p);
    }
    INFO("max error over all particles, in units of p: σ_rr " << rr << ", σ_θθ " << tt << ", σ_zz " << zz);
    // 2 % of p (σ_θθ spans 0.25p–1.25p here): above the largest error measured with
    // 80 cells: linear 0.8–1.5 %, GIMP 1.0–1.7 %, largest in the loaded cell. The load
    // is small (p/E = 1e-4) because it acts on the fixed grid line r = a: once the
    // face moves a sizeable part of a cell off that line (p/E = 1e-3 moves it 6 % of
    // a cell) the face cell's stress is off by about as much.
    CHECK(rr < 0.02);
    CHECK(tt < 0.02);
    CHECK(zz < 0.02);
  };
  SECTION("linear") { check(ShapeFunction::linear); }
  SECTION("GIMP") { check(ShapeFunction::gimp); }
}

TEST_CASE("solid cylinder under uniform outer pressure: sigma_rr = sigma_tt = -p up to the axis",
          "[mpm][verification][axisymmetric]") {
  // Uniform radial compression of a solid cylinder in plane strain is homogeneous:
  // σ_rr = σ_θθ = −p, σ_zz = −2νp, for any mesh. It exercises the axis, where S/r
  // and v_r/r are largest.
  const double p = 1e3, nu = 0.3;
  auto check = [&](ShapeFunction shape) {
    const Simulation s = run_cylinder(shape, 0.0, 0.2, 40, Side::outer, p);
    double worst = 0.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const Voigt& sig = s.particles.stress[i];
      worst = std::max({worst, std::abs(sig[0] + p) / p, std::abs(sig[2] + p) / p, std::abs(sig[1] + 2 * nu * p) / p});
    }
    INFO("max error in units of p: " << worst);
    CHECK(worst < 0.01);  // measured 0.3 % (what the damping has not yet removed)
    CHECK(s.wall_clamps == 0);
  };
  SECTION("linear") { check(ShapeFunction::linear); }
  SECTION("GIMP") { check(ShapeFunction::gimp); }
}
