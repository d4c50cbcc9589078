/// The two compression waves of a saturated column under a load stepped onto its drained
/// top (Verruijt 2010, An Introduction to Soil Dynamics, ch. 6): the undrained wave at
/// c₁ = √((E_c + K_w/n)/ρ_sat) and the slow, damped wave of Biot, against the exact solution
/// of Verruijt's uncoupled case (models/consolidation_solutions.hpp, BiotColumn).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <vector>

#include "models/consolidation_solutions.hpp"
#include "mpm/simulation.hpp"
#include "saturated_column.hpp"
#include "verification/sampled_integral.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

constexpr double kLoad = 1e3;  ///< P (Pa): a strain of 1e-4, far from the finite-strain terms
/// The load rises along a half cosine over 1 ms (10 cm of the first wave, 5 cm of the second):
/// a step would ring at the grid's shortest waves by ±10 % of P behind each front.
constexpr double kRamp = 1e-3;
constexpr double kWindow = 2e-3;  ///< the mean behind the slow front: ten periods of its ringing

/// The test fluid K_w = n E_c with ρ_d = (2 − n) ρ_w makes (E_c + (1 − n)K)/ρ_d = K/ρ_w: the
/// in-phase motion is a mode, c₁ = 100 m/s undamped, and the slow wave c₂ = √(n E_c/ρ_d) =
/// 50 m/s has its own telegraph equation. k = 0.05 m/s: γ = 49 /s, so its front falls to
/// e^{−γx/c₂} = 0.82, 0.67, 0.56 at depths 0.2, 0.4, 0.6 m.
testing::SaturatedColumn verruijt_column(int cells) {
  testing::SaturatedColumn c;
  c.height_m = 1.5;  // the first wave's reflection reaches 0.6 m at 24 ms, twice the slow wave's arrival
  c.cells = cells;
  c.fluid_bulk_modulus_Pa = c.porosity * c.constrained_modulus_Pa;
  c.permeability_m_s = 0.05;
  return c;
}

BiotColumn exact_column(const testing::SaturatedColumn& c) {
  return BiotColumn{c.constrained_modulus_Pa, c.fluid_bulk_modulus_Pa, c.porosity,
                    c.dry_density_kg_m3,      c.fluid_density_kg_m3(), c.permeability_m_s,
                    kConductivityGravity_m_s2};
}

/// Per probe depth: the cell row's mean pore pressure and total vertical stress (compression
/// positive) at every step.
struct Histories {
  std::vector<double> time_s;
  std::vector<std::vector<double>> pressure, total;  ///< [probe][step]
  std::vector<double> depth_m;                       ///< the rows' centres
  double dt_s = 0.0;
  long steps = 0;
};

Histories run(const testing::SaturatedColumn& c, const std::vector<double>& depths, double end_s) {
  ModelDescription m = c.model();
  m.pressures.push_back(testing::top_pressure(m.r_nodes_m.back(), [](double t) {
    return t >= kRamp ? kLoad : kLoad * 0.5 * (1.0 - std::cos(kPi * t / kRamp));
  }));
  Simulation s(m);
  Histories h;
  std::vector<int> rows;
  for (const double x : depths) {
    const int row = s.grid.z.cell_of(c.height_m - x);
    rows.push_back(row);
    h.depth_m.push_back(c.height_m - (row + 0.5) * c.cell_m());
  }
  h.pressure.resize(depths.size());
  h.total.resize(depths.size());
  while (true) {  // the start first: the impulse integrals begin at t = 0
    const std::vector<double> p = testing::row_means(s, [&](std::size_t i) { return s.two_phase->pore_pressure[i]; });
    const std::vector<double> szz = testing::row_means(s, [&](std::size_t i) { return s.particles.stress[i][1]; });
    h.time_s.push_back(s.time_s);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto row = static_cast<std::size_t>(rows[k]);
      h.pressure[k].push_back(p[row]);
      h.total[k].push_back(p[row] - szz[row]);
    }
    if (s.time_s >= end_s) break;
    s.advance();
  }
  h.dt_s = s.dt_s;
  h.steps = s.step;
  return h;
}

struct Fronts {
  std::vector<double> depth_m;  ///< the probed rows' centres
  std::vector<double> fast_arrival_s, slow_arrival_s, slow_jump_Pa;
  double damping_1_s = 0.0;  ///< from the jumps' decay between the first and last depth
  double worst_Pa = 0.0;     ///< max |p − p_exact| over the run
};

/// The fronts' arrivals as impulse centroids: the first from the total stress, P(t − x/c₁)
/// exactly (the slow wave carries none), less the ramp's own centroid t_r/2; the second from
/// the pore pressure against the exact solution, t₂ = x/c₂ + ∫ (p − p_exact) dt / J over the
/// slow front's window, J = −P₂ e^{−γx/c₂} its exact jump. The slow front's measured jump is
/// the drop of p from δ before it to t_r + δ after it, less what the exact solution drops
/// besides the jump over the same interval (δ = 4 cells of travel).
Fronts measure(const Histories& h, const BiotColumn& exact, double cell_m) {
  Fronts f;
  f.depth_m = h.depth_m;
  const double c1 = exact.wave(0).speed_m_s, c2 = exact.wave(1).speed_m_s, gamma = exact.wave(1).damping_1_s;
  const double delta = 4 * cell_m / c2;
  for (std::size_t k = 0; k < h.depth_m.size(); ++k) {
    const double x = h.depth_m[k], t1 = x / c1, t2 = x / c2, mid = 0.5 * (t1 + t2) + 0.5 * kRamp;
    const auto& p = h.pressure[k];
    const auto exact_p = [&](double t) { return exact.pressure(kLoad, kRamp, x, t); };
    std::vector<double> reference(h.time_s.size());
    for (std::size_t j = 0; j < h.time_s.size(); ++j) reference[j] = exact_p(h.time_s[j]);
    f.fast_arrival_s.push_back(
        sampled_integral(h.time_s, 0.0, mid, [&](std::size_t j) { return 1.0 - h.total[k][j] / kLoad; }) - 0.5 * kRamp);
    const double jump = kLoad * exact.slow_wave_pressure_share() * std::exp(-gamma * t2);
    const double end = h.time_s.back();
    f.slow_arrival_s.push_back(
        t2 + sampled_integral(h.time_s, mid, end, [&](std::size_t j) { return p[j] - reference[j]; }) / jump);
    // ⟨p − p_exact⟩ over a window: the front's ringing averages out, the exact smooth part cancels.
    const auto mean_error = [&](double t0, double t1) {
      return sampled_integral(h.time_s, t0, t1, [&](std::size_t j) { return p[j] - reference[j]; }) / (t1 - t0);
    };
    const double after = t2 + kRamp + delta;
    f.slow_jump_Pa.push_back(jump + mean_error(mid, t2 - delta) - mean_error(after, after + kWindow));
    for (std::size_t j = 0; j < h.time_s.size(); ++j) f.worst_Pa = std::max(f.worst_Pa, std::abs(p[j] - reference[j]));
  }
  const double x0 = h.depth_m.front(), x1 = h.depth_m.back();
  f.damping_1_s = std::log(f.slow_jump_Pa.front() / f.slow_jump_Pa.back()) * c2 / (x1 - x0);
  return f;
}

}  // namespace

TEST_CASE(
    "Verruijt's saturated column: an undamped wave at c_1 and Biot's slow wave at c_2, its front decaying "
    "as exp(-gamma t)",
    "[mpm][verification][saturated][wave]") {
  const std::vector<double> depths = {0.2, 0.4, 0.6};
  std::ostringstream measured;
  std::vector<Fronts> runs;
  for (const int cells : {150, 300}) {
    const testing::SaturatedColumn c = verruijt_column(cells);
    const BiotColumn exact = exact_column(c);
    REQUIRE(std::abs(exact.uncoupling_mismatch()) < 1e-12);
    const Histories h = run(c, depths, depths.back() / exact.wave(1).speed_m_s + kRamp + kWindow + 1e-3);
    const Fronts f = measure(h, exact, c.cell_m());
    runs.push_back(f);
    measured << cells << " cells, " << h.steps << " steps of " << h.dt_s << " s:";
    for (std::size_t k = 0; k < depths.size(); ++k)
      measured << " x " << h.depth_m[k] << ": fast " << f.fast_arrival_s[k] * exact.wave(0).speed_m_s / h.depth_m[k] - 1
               << ", slow " << f.slow_arrival_s[k] * exact.wave(1).speed_m_s / h.depth_m[k] - 1 << ", jump "
               << f.slow_jump_Pa[k] / (kLoad * exact.slow_wave_pressure_share() *
                                       std::exp(-exact.wave(1).damping_1_s * h.depth_m[k] / exact.wave(1).speed_m_s)) -
                      1
               << ";";
    measured << " gamma " << f.damping_1_s << " /s (exact " << exact.wave(1).damping_1_s << "), worst "
             << f.worst_Pa / kLoad << " P\n";
  }
  INFO(measured.str());
  const testing::SaturatedColumn fine = verruijt_column(300);
  const BiotColumn exact = exact_column(fine);
  const double c1 = exact.wave(0).speed_m_s, c2 = exact.wave(1).speed_m_s;
  const Fronts& f = runs[1];
  const double span = f.depth_m.back() - f.depth_m.front();
  // The first wave: arrivals within 1 % of x/c₁, the bound of the dry and undrained waves
  // (measured ≤ 0.06 % at 150 cells, ≤ 0.02 % at 300), its speed between 0.2 and 0.6 m within
  // 0.5 % (measured 0.007 %). The dry skeleton's wave, √(E_c/ρ_d) = 79 m/s, would be 21 % slower.
  CHECK(span / (f.fast_arrival_s.back() - f.fast_arrival_s.front()) == Approx(c1).epsilon(5e-3));
  for (std::size_t k = 0; k < depths.size(); ++k) CHECK(f.fast_arrival_s[k] == Approx(f.depth_m[k] / c1).epsilon(1e-2));
  // The slow wave: arrivals within 1 % of x/c₂, the bound of the dry and undrained waves
  // (measured 0.2 % at 150 cells, 0.06 % at 300); its speed within 0.5 % (measured 0.08 %).
  for (std::size_t k = 0; k < depths.size(); ++k) CHECK(f.slow_arrival_s[k] == Approx(f.depth_m[k] / c2).epsilon(1e-2));
  CHECK(span / (f.slow_arrival_s.back() - f.slow_arrival_s.front()) == Approx(c2).epsilon(5e-3));
  // Its decay: the jumps' e^{−γx/c₂} between 0.2 and 0.6 m gives γ within 3 % at 300 cells
  // (measured 1.6 %; 7.5 % at 150, 0.4 % at 600 cells: second order, the front's numerical
  // dispersion); a drag wrong by a factor n would be off by 150 %, none at all by 100 %.
  CHECK(f.damping_1_s == Approx(exact.wave(1).damping_1_s).epsilon(0.03));
  CHECK(std::log2(std::abs(runs[0].damping_1_s / exact.wave(1).damping_1_s - 1) /
                  std::abs(runs[1].damping_1_s / exact.wave(1).damping_1_s - 1)) > 1.7);
}
