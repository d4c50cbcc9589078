/// Two elastic spheres meeting head-on on the axis (the axisymmetric form of
/// Sulsky, Zhou & Schreyer 1995's colliding disks), single velocity field.
/// data/scenes/mpm_colliding_spheres.json is the same run with its energy plot.
#include <catch2/catch.hpp>

#include <cmath>

#include "mpm/diagnostics.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

struct CollisionResult {
  double initial_J, final_J, lowest_J, momentum_error_N_s, body_momentum_N_s, lower_velocity_m_s;
};

CollisionResult collide(ShapeFunction shape) {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.3, 30);
  m.z_nodes_m = testing::nodes(0.0, 0.9, 90);
  m.bodies.push_back(testing::elastic_body("lower", 1e6, 0.3, 1000.0, SphereRegion{0.3, 0.1}, 0.0, 1.0));
  m.bodies.push_back(testing::elastic_body("upper", 1e6, 0.3, 1000.0, SphereRegion{0.6, 0.1}, 0.0, -1.0));
  m.boundaries = {Fixity::roller, Fixity::free, Fixity::free, Fixity::free};
  m.solver.shape_function = shape;
  Simulation s(m);
  CollisionResult r{};
  r.initial_J = r.lowest_J = measure(s).total_energy_J();
  r.body_momentum_N_s = std::abs(measure_body(s, 0).momentum_z_N_s);
  while (s.time_s < 0.2) {  // contact from 0.05 s to about 0.075 s
    s.advance();
    const Diagnostics d = measure(s);
    r.lowest_J = std::min(r.lowest_J, d.total_energy_J());
    r.momentum_error_N_s = std::max(r.momentum_error_N_s, std::abs(d.momentum_z_N_s));
  }
  r.final_J = measure(s).total_energy_J();
  const Diagnostics lower = measure_body(s, 0);
  r.lower_velocity_m_s = lower.momentum_z_N_s / lower.mass_kg;
  return r;
}

}  // namespace

TEST_CASE("colliding elastic spheres bounce apart and GIMP loses under 5% of the energy",
          "[mpm][verification][collision]") {
  const CollisionResult gimp = collide(ShapeFunction::gimp);
  const CollisionResult linear = collide(ShapeFunction::linear);
  INFO("GIMP: final/initial energy " << gimp.final_J / gimp.initial_J << ", lowest " << gimp.lowest_J / gimp.initial_J
                                     << "; linear: final " << linear.final_J / linear.initial_J << ", lowest "
                                     << linear.lowest_J / linear.initial_J);
  // Bound: < 5 % lost with GIMP, below what linear hats lose to cell-crossing noise (5.5 %)
  // and well above GIMP's measured 1.7 %.
  CHECK(gimp.final_J > 0.95 * gimp.initial_J);
  CHECK(gimp.final_J <= gimp.initial_J * 1.001);
  CHECK(linear.final_J < gimp.final_J);
  // Total momentum is zero by symmetry and stays so to round-off.
  CHECK(gimp.momentum_error_N_s < 1e-12 * gimp.body_momentum_N_s);
  // The spheres separate: the lower one moves down again at nearly its impact speed.
  CHECK(gimp.lower_velocity_m_s < -0.95);
}
