/// Terzaghi's 1D consolidation of a saturated elastic column, drained at the top and
/// impermeable at the base, under a load Δσ held from t = 0 (no gravity): against the
/// series solution, at three resolutions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "models/consolidation_solutions.hpp"
#include "mpm/simulation.hpp"
#include "saturated_column.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

struct Errors {
  std::vector<double> pressure;    ///< per time factor: max over cell rows |p − p_exact|/p_0
  std::vector<double> settlement;  ///< per time factor: |w_top − w_exact|/w_∞ at the top particles
  double dt_s = 0.0, dry_dt_s = 0.0;
  long steps = 0;
};

const std::vector<double> kTimeFactors = {0.02, 0.05, 0.1, 0.2, 0.5, 1.0};

/// The column starts undrained under a load of 1 kPa (a strain of 5e-5: the finite-strain
/// terms of the MPM, of that order, stay below the errors measured; at 10 kPa they set a
/// floor of 3e-4 p_0): p = p_0 = share·Δσ, σ'_zz = −(1 − share)Δσ,
/// σ'_rr = σ'_θθ = ν/(1 − ν) σ'_zz (uniaxial strain), in equilibrium with the load except at
/// the drained top, where the excess starts to flow out at t = 0.
Errors consolidate(testing::SaturatedColumn c, const std::vector<double>& time_factors = kTimeFactors) {
  const double load = 1e3;
  ModelDescription m = c.model();
  const double width = m.r_nodes_m.back();
  m.pressures.push_back(testing::top_pressure(width, [load](double) { return load; }));
  Simulation s(m);
  const double p0 = c.undrained_share() * load, effective = -(1.0 - c.undrained_share()) * load;
  const double k0 = c.poisson_ratio / (1.0 - c.poisson_ratio);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    s.two_phase->set_pore_pressure(p, p0);
    s.particles.stress[p] << k0 * effective, effective, k0 * effective, 0.0, 0.0, 0.0;
  }
  const double H = c.height_m, cv = c.consolidation_coefficient_m2_s();
  const Terzaghi exact{p0, H, cv, c.constrained_modulus_Pa};
  Errors e;
  e.dt_s = s.dt_s;
  {
    ModelDescription dry = c.model();
    dry.bodies[0].saturated.reset();
    e.dry_dt_s = Simulation(dry).dt_s;
  }
  const double top_row_z = H - c.cell_m();
  for (const double T : time_factors) {
    while (s.time_s < T * H * H / cv) s.advance();
    const std::vector<double> p = testing::row_means(s, [&](std::size_t i) { return s.two_phase->pore_pressure[i]; });
    double worst = 0.0;
    for (int row = 0; row < s.grid.z.cells(); ++row) {
      const double centre = H - (row + 0.5) * c.cell_m();
      worst = std::max(worst, std::abs(p[static_cast<std::size_t>(row)] - exact.pressure(centre, s.time_s)) / p0);
    }
    e.pressure.push_back(worst);
    double w = 0.0, w_exact = 0.0, count = 0.0;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      if (s.particles.z0[i] < top_row_z) continue;
      const double weight = s.particles.r0[i];
      w += weight * (s.particles.z0[i] - s.particles.z[i]);
      w_exact += weight * exact.displacement(H - s.particles.z0[i], s.time_s);
      count += weight;
    }
    e.settlement.push_back(std::abs(w - w_exact) / count / (p0 * H / c.constrained_modulus_Pa));
  }
  e.steps = s.step;
  return e;
}

std::string listed(const std::vector<double>& x) {
  std::string out;
  for (const double v : x) out += (out.empty() ? "" : ", ") + std::to_string(v);
  return out;
}

}  // namespace

double order(double coarse, double fine) { return std::log2(coarse / fine); }

TEST_CASE(
    "Terzaghi consolidation: isochrones converge at second order to the series solution, settlement within "
    "5e-4",
    "[mpm][verification][saturated][consolidation]") {
  // A test fluid with K_w/n = E_c: the fluid takes half the load at first (p_0 = Δσ/2), and
  // c_v = k/(γ_w (1/E_c + n/K_w)) is half the incompressible one, so every term counts.
  testing::SaturatedColumn c;
  c.fluid_bulk_modulus_Pa = c.porosity * c.constrained_modulus_Pa;
  std::vector<Errors> runs;
  for (const int cells : {10, 20, 40}) {
    c.cells = cells;
    runs.push_back(consolidate(c));
  }
  std::string measured;
  for (const Errors& e : runs)
    measured += std::to_string(e.steps) + " steps, Δt " + std::to_string(e.dt_s) + " s (dry " +
                std::to_string(e.dry_dt_s) + " s): pressure errors " + listed(e.pressure) + "; settlement errors " +
                listed(e.settlement) + "\n";
  INFO(measured);
  // The cell rows' pressure (one per row: the smoothed pore pressure, a Q1–P0 pair) is
  // second order at the row centres while the isochrones are steep (T ≤ 0.1: measured
  // orders 1.9–2.3); later the errors reach the floor of a dynamic model against a
  // quasi-static theory (~1e-5 p_0). An order below 1.7 is a lost order.
  for (std::size_t t = 0; t < 3; ++t) {
    INFO("T = " << kTimeFactors[t]);
    CHECK(order(runs[0].pressure[t], runs[1].pressure[t]) > 1.7);
    CHECK(order(runs[1].pressure[t], runs[2].pressure[t]) > 1.7);
  }
  // At 40 cells the worst isochrone error is 9.3e-4 p_0 (T = 0.02, the steepest): 1.5e-3
  // leaves room for another machine's rounding and fails on any error of the 20-cell size.
  CHECK(*std::max_element(runs[2].pressure.begin(), runs[2].pressure.end()) < 1.5e-3);
  // Settlement: the top particles' displacement, area-weighted (the load's work-conjugate
  // mean; single particles differ by the O(h) radial quadrature of the particles against
  // the exact traction), against w(ζ, t) at their depth: measured ≤ 1.9e-4 of p_0 H/E_c from
  // 20 cells on, a floor that does not fall with h (dynamics and finite strain); 5e-4.
  for (std::size_t k = 1; k < runs.size(); ++k)
    CHECK(*std::max_element(runs[k].settlement.begin(), runs[k].settlement.end()) < 5e-4);
}

TEST_CASE("Terzaghi consolidation with water (K_w = 2.2 GPa): isochrones within 5e-3 of p_0 from T = 0.1 at 20 cells",
          "[mpm][verification][saturated][consolidation]") {
  // p_0 = 0.998 Δσ, c_v = k/(γ_w (1/E_c + n/K_w)) ≈ k E_c/γ_w = 1.02 m²/s; H = 0.5 m: T = 1 at 0.25 s,
  // with Δt set by the undrained wave c_1 = √((E_c + K_w/n)/ρ_sat) = 1.66 km/s. Terzaghi's theory
  // neglects the liquid's inertia, which relaxes to Darcy flow in τ = k/(n g) = 2.5e-4 s: at
  // T = 0.02 and 0.05 (t = 20 and 50 τ) the isochrones still differ from it by 8 % and 1 % of p_0
  // (measured), so the comparison starts at T = 0.1 (100 τ).
  testing::SaturatedColumn c;
  c.height_m = 0.5;
  c.permeability_m_s = 1e-3;
  const Errors e = consolidate(c, {0.1, 0.2, 0.5, 1.0});
  INFO(e.steps << " steps, Δt " << e.dt_s << " s (dry " << e.dry_dt_s << " s): pressure errors " << listed(e.pressure)
               << "; settlement errors " << listed(e.settlement));
  // Measured at T = 0.1, 0.2, 0.5, 1: 3.2e-3, 2.3e-3, 5.5e-4, 3.2e-4 of p_0; settlement 1.0e-3 at most.
  CHECK(*std::max_element(e.pressure.begin(), e.pressure.end()) < 5e-3);
  CHECK(*std::max_element(e.settlement.begin(), e.settlement.end()) < 2e-3);
}
