/// Deterministic parallel results: particle→grid sums run in a fixed order
/// (mpm/particle_bins.hpp), so runs repeat bit for bit, whatever the thread count.
#include <catch2/catch.hpp>

#include <cstring>

#include "mpm/parallel.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

Simulation run(int threads) {
  set_thread_count(threads);
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.4, 40);
  m.z_nodes_m = testing::nodes(0.0, 0.5, 50);
  m.bodies.push_back(BodyDescription{"sand",
                                     MohrCoulomb(MohrCoulombParameters{ElasticConstants{2.5e6, 0.33}, 0.68, 0.0, 0.0}),
                                     1490.0, BoxRegion{0, 0.4, 0, 0.3}, 2, 2, 0.0, 0.0, GeostaticStress{0.39, 0.3}});
  m.bodies.push_back(testing::elastic_body("ball", 2e7, 0.3, 7800.0, SphereRegion{0.36, 0.05}, 0.0, -3.0));
  m.gravity_m_s2 = 9.81;
  Simulation s(m);
  for (int k = 0; k < 300; ++k) s.advance();
  return s;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("a run repeats bit for bit, with 1 or 2 threads", "[mpm][determinism]") {
  const int threads = thread_count();
  const Simulation a = run(2), b = run(2), c = run(1);
  set_thread_count(threads);
  for (const Simulation* other : {&b, &c}) {
    CHECK(same_bits(a.particles.r, other->particles.r));
    CHECK(same_bits(a.particles.z, other->particles.z));
    CHECK(same_bits(a.particles.vr, other->particles.vr));
    CHECK(same_bits(a.particles.vz, other->particles.vz));
    CHECK(same_bits(a.particles.volume, other->particles.volume));
    CHECK(std::memcmp(a.particles.stress.data(), other->particles.stress.data(),
                      a.particles.stress.size() * sizeof(Voigt)) == 0);
    CHECK(a.time_s == other->time_s);
  }
}
