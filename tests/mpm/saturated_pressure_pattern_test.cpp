/// The pore pressure a particle carries is its cell's: a pattern of excess pressure inside a cell,
/// which the grid cannot see and no flow would even out, goes at the first step with strain
/// smoothing; without smoothing each particle keeps its own.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "mpm/simulation.hpp"
#include "saturated_column.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// The largest spread (max − min) of the particles' excess pore pressure within one cell.
double largest_spread_in_a_cell(const Simulation& s) {
  std::map<std::size_t, std::pair<double, double>> range;
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    const double e = s.two_phase->excess_pressure(s.particles, p);
    auto [it, fresh] = range.try_emplace(s.cell[p], e, e);
    it->second.first = std::min(it->second.first, e);
    it->second.second = std::max(it->second.second, e);
  }
  double spread = 0.0;
  for (const auto& [cell, r] : range) spread = std::max(spread, r.second - r.first);
  return spread;
}

}  // namespace

TEST_CASE("a pattern of excess pore pressure inside the cells goes at the first step with strain smoothing",
          "[mpm][saturated]") {
  testing::SaturatedColumn c;
  c.gravity_m_s2 = 9.81;
  ModelDescription m = c.model();
  const double pattern_Pa = 1000.0;  // ±1 kPa on alternate particles: two of each in every cell
  auto patterned = [&](StrainSmoothing smoothing) {
    m.solver.strain_smoothing = smoothing;
    Simulation s(m);
    TwoPhase& t = *s.two_phase;
    double mean = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      const double e = (p % 2 == 0 ? 1.0 : -1.0) * pattern_Pa;
      t.liquid_pressure[p] += e;
      t.pore_pressure[p] += e;
      mean += e;
    }
    REQUIRE(std::abs(mean) < 1e-9);  // the pattern adds nothing to any cell's mean
    s.advance();
    return s;
  };
  SECTION("strain smoothing: each particle takes its cell's mean") {
    const Simulation s = patterned(StrainSmoothing::volumetric);
    INFO("largest spread in a cell " << largest_spread_in_a_cell(s) << " Pa");
    // What one step's flow and storage can leave in a cell of a column at rest: round-off of the
    // hydrostatic ≈ 1e4 Pa, a hundred millionth of the pattern.
    CHECK(largest_spread_in_a_cell(s) < 1e-8 * pattern_Pa);
    double worst = 0.0;
    for (std::size_t p = 0; p < s.particles.size(); ++p)
      worst = std::max(worst, std::abs(s.two_phase->excess_pressure(s.particles, p)));
    CHECK(worst < 1e-6 * pattern_Pa);  // and the mean of ± is 0: the column is back at hydrostatic
  }
  SECTION("no smoothing: each particle keeps its own") {
    const Simulation s = patterned(StrainSmoothing::off);
    CHECK(largest_spread_in_a_cell(s) > 1.9 * pattern_Pa);
  }
}
