/// Two sections of the saturated-sand verification: Verruijt's column (the undrained wave and
/// Biot's slow wave against BiotColumn's exact solution) and radial consolidation (against
/// the Bessel series), each at two mesh levels.
#include <algorithm>
#include <cmath>

#include "reports/studies/saturated_runs.hpp"
#include "reports/studies/saturated_sections.hpp"
#include "reports/studies/study_helpers.hpp"
#include "verification/sampled_integral.hpp"

namespace ffp {

namespace {

constexpr double kMeanWindow_s = 2e-3;  ///< the mean behind the slow front: ten periods of its ringing

struct WaveLevel {
  double cell_m = 0.0, wall_s = 0.0;
  long steps = 0;
  std::vector<double> depth_m{}, fast_error{}, slow_error{}, jump_error{};  ///< relative, per probe
  double damping_1_s = 0.0, worst_Pa = 0.0;
  std::vector<Series> pressure{};  ///< p(t) per probe (kPa, ms)
};

/// The fronts as the test measures them (tests/mpm/biot_slow_wave_test.cpp): impulse centroids
/// of the total stress (the first wave's, P(t − x/c₁) exactly) and of p against the exact p (the
/// second's); the slow front's jump from the mean error before and behind it; γ from the jumps'
/// decay between the first and last probe. Each probe is compared at its cell's centre.
WaveLevel wave_level(const SaturatedRun& run) {
  const SaturatedParameters& c = run.parameters;
  const BiotColumn exact = c.biot();
  const double c1 = exact.wave(0).speed_m_s, c2 = exact.wave(1).speed_m_s, gamma = exact.wave(1).damping_1_s;
  const double P = c.load_Pa, ramp = c.ramp_s, delta = 4 * c.cell_z_m / c2;
  WaveLevel level{.cell_m = c.cell_z_m, .wall_s = run.wall_time_s, .steps = run.steps};
  std::vector<double> jumps;
  for (const ProbeHistory& h : run.probes) {
    const double x = c.top_m - (std::floor(h.z0_m / c.cell_z_m) + 0.5) * c.cell_z_m;
    const double t1 = x / c1, t2 = x / c2, mid = 0.5 * (t1 + t2) + 0.5 * ramp;
    std::vector<double> reference(run.time_s.size());
    for (std::size_t j = 0; j < run.time_s.size(); ++j) reference[j] = exact.pressure(P, ramp, x, run.time_s[j]);
    const auto& p = h.pore_pressure_Pa;
    const double fast =
        sampled_integral(run.time_s, 0.0, mid, [&](std::size_t j) { return 1.0 - (p[j] - h.stress_zz_Pa[j]) / P; }) -
        0.5 * ramp;
    const double jump = P * exact.slow_wave_pressure_share() * std::exp(-gamma * t2);
    const double slow = t2 + sampled_integral(run.time_s, mid, run.time_s.back(), [&](std::size_t j) {
                               return p[j] - reference[j];
                             }) / jump;
    const auto mean_error = [&](double a, double b) {
      return sampled_integral(run.time_s, a, b, [&](std::size_t j) { return p[j] - reference[j]; }) / (b - a);
    };
    const double after = t2 + ramp + delta;
    jumps.push_back(jump + mean_error(mid, t2 - delta) - mean_error(after, after + kMeanWindow_s));
    level.depth_m.push_back(x);
    level.fast_error.push_back(fast / t1 - 1);
    level.slow_error.push_back(slow / t2 - 1);
    level.jump_error.push_back(jumps.back() / jump - 1);
    Series s{.title = "x = " + fixed(100 * x, 2) + " cm (MPM)", .style = "lines"};
    Series e{.title = "exact", .style = "lines dashtype 2"};
    for (std::size_t j = 0; j < run.time_s.size(); ++j) {
      level.worst_Pa = std::max(level.worst_Pa, std::abs(p[j] - reference[j]));
      s.x.push_back(1e3 * run.time_s[j]);
      s.y.push_back(1e-3 * p[j]);
      e.x.push_back(1e3 * run.time_s[j]);
      e.y.push_back(1e-3 * reference[j]);
    }
    level.pressure.push_back(s);
    level.pressure.push_back(e);
  }
  level.damping_1_s = std::log(jumps.front() / jumps.back()) * c2 / (level.depth_m.back() - level.depth_m.front());
  return level;
}

std::string percents(const std::vector<double>& x) {
  std::string out;
  for (const double v : x) out += (out.empty() ? "" : " / ") + fixed(100 * v, 2);
  return out;
}

}  // namespace

void write_saturated_waves(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Verruijt's column: the undrained wave and Biot's slow wave");
  const auto coarse = read_saturated_run(results, kVerruijtCoarse), fine = read_saturated_run(results, kVerruijtFine);
  if (!coarse || !fine) return md.paragraph(missing_run("Verruijt column"));
  const SaturatedParameters& c = fine->parameters;
  const BiotColumn exact = c.biot();
  const BiotColumn::Wave first = exact.wave(0), second = exact.wave(1);
  const WaveLevel levels[2] = {wave_level(*coarse), wave_level(*fine)};
  md.paragraph(
      "`mpm_verruijt_column.json`: " + fixed(1e-3 * c.load_Pa, 0) + " kPa on the drained top of a " +
      fixed(c.top_m, 1) + " m column over a " + fixed(1e3 * c.ramp_s, 0) +
      " ms half cosine, k = " + fixed(c.permeability_m_s, 2) +
      " m/s. With the test fluid K_w = n E_c and ρ_d = (2 − n) ρ_w (Verruijt's condition (E_c + (1 − n)K)/ρ_d = "
      "K/ρ_w " +
      (std::abs(exact.uncoupling_mismatch()) < 1e-12 ? std::string("holds")
                                                     : "is off by " + scientific(exact.uncoupling_mismatch(), 2)) +
      ") the column's two waves uncouple: the undrained wave at c₁ = √((E_c + K_w/n)/ρ_sat) = " +
      fixed(first.speed_m_s, 1) + " m/s, undamped, carries the whole load, half of it in the pore fluid; Biot's slow " +
      "wave at c₂ = √(n E_c/ρ_d) = " + fixed(second.speed_m_s, 1) +
      " m/s passes the fluid's half to the skeleton, its front decaying as e^{−γx/c₂}, γ = " +
      fixed(second.damping_1_s, 2) + " /s, and behind it the telegraph equation's diffusion (c₂²/2γ = c_v = " +
      fixed(c.consolidation_coefficient_m2_s(), 2) + " m²/s).");
  std::vector<std::vector<std::string>> rows;
  for (const WaveLevel& l : levels)
    rows.push_back({fixed(1e3 * l.cell_m, 0) + " mm", std::to_string(l.steps), fixed(l.wall_s, 2),
                    percents(l.fast_error), percents(l.slow_error), percents(l.jump_error), fixed(l.damping_1_s, 2),
                    fixed(100 * (l.damping_1_s / second.damping_1_s - 1), 1), fixed(l.worst_Pa / c.load_Pa, 3)});
  md.table({"cells", "steps", "wall time [s]", "first arrival error [%]", "second arrival error [%]",
            "second front's jump error [%]", "γ [1/s]", "γ error [%]", "largest error of p / P"},
           rows);
  const double gamma_order = std::log2(std::abs(levels[0].damping_1_s / second.damping_1_s - 1) /
                                       std::abs(levels[1].damping_1_s / second.damping_1_s - 1));
  const auto speed = [](const WaveLevel& l, const std::vector<double>& error, double c) {
    const double t0 = l.depth_m.front() / c * (1 + error.front()), t1 = l.depth_m.back() / c * (1 + error.back());
    return (l.depth_m.back() - l.depth_m.front()) / (t1 - t0);
  };
  md.paragraph("Errors at the depths " + percents({levels[1].depth_m[0], levels[1].depth_m[1], levels[1].depth_m[2]}) +
               " cm. Between the first and last depth the first wave travels at " +
               fixed(speed(levels[1], levels[1].fast_error, first.speed_m_s), 2) + " m/s and the second at " +
               fixed(speed(levels[1], levels[1].slow_error, second.speed_m_s), 2) +
               " m/s (5 mm cells); the first wave's arrivals lead x/c₁ by half a cell at every level. The decay rate "
               "converges at order " +
               fixed(gamma_order, 2) +
               "; the largest pointwise error sits at the fronts, the explicit scheme's dispersion of a front "
               "a few cells wide.");
  Plot plot{.title = "Verruijt's column: pore pressure at three depths (5 mm cells)",
            .x_label = "time (ms)",
            .y_label = "pore pressure (kPa)",
            .series = levels[1].pressure,
            .key_position = "top right"};
  add_plot(out, plot, "saturated_verruijt.png",
           "Pore pressure against time at three depths with the exact solution: the first wave brings half the "
           "load into the fluid, the slow wave's front takes a decaying part of it away.");
}

void write_radial_consolidation(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Radial consolidation");
  const std::vector<double> factors = {0.02, 0.05, 0.1, 0.2};
  std::vector<std::vector<double>> errors;
  std::vector<std::vector<std::string>> rows;
  Plot plot{.title = "Radial consolidation: isochrones",
            .x_label = "r / R",
            .y_label = "p / p_0",
            .series = {},
            .key_position = "top right"};
  for (const std::size_t i : {std::size_t(kRadialCoarse), std::size_t(kRadialFine)}) {
    const auto run = read_saturated_run(results, i);
    if (!run) return md.paragraph(missing_run("radial consolidation"));
    const SaturatedParameters& c = run->parameters;
    const double R = c.radius_m, h = c.cell_r_m, p0 = c.initial_excess_pressure_Pa;
    // The rigid-skeleton limit: n/K_w ∂p/∂t = (k/γ_w) ∇²p, c = k K_w/(n γ_w).
    const RadialDiffusion exact{p0, R,
                                c.permeability_m_s * c.fluid_bulk_modulus_Pa /
                                    (c.porosity * c.fluid_density_kg_m3 * kConductivityGravity_m_s2)};
    std::vector<double> worst;
    for (const double T : factors) {
      const std::size_t row = nearest_row(run->time_s, T * R * R / exact.diffusivity_m2_s);
      const double t = run->time_s[row];
      double e = 0.0;
      Series iso{.title = "T = " + fixed(T, 2) + ", h = " + fixed(100 * h, 1) + " cm", .style = "points"};
      for (const ProbeHistory& probe : run->probes) {
        const double cell = std::floor(probe.r0_m / h);
        e = std::max(e, std::abs(probe.pore_pressure_Pa[row] - exact.cell_mean(cell * h, (cell + 1) * h, t)) / p0);
        iso.x.push_back(probe.r0_m / R);
        iso.y.push_back(probe.pore_pressure_Pa[row] / p0);
      }
      worst.push_back(e);
      if (i == kRadialFine || T == 0.05) plot.series.push_back(iso);
      if (i == kRadialFine) {
        Series curve{.title = T == factors.front() ? "Bessel series" : "", .style = "lines"};
        for (int k = 0; k <= 100; ++k) {
          curve.x.push_back(k / 100.0);
          curve.y.push_back(exact.pressure(R * k / 100.0, t) / p0);
        }
        plot.series.push_back(curve);
      }
    }
    std::vector<std::string> row = {fixed(R / h, 0), std::to_string(run->steps), fixed(run->wall_time_s, 1)};
    for (const double e : worst) row.push_back(scientific(e));
    rows.push_back(row);
    errors.push_back(worst);
  }
  std::vector<std::string> orders = {"order", "", ""};
  for (std::size_t t = 0; t < factors.size(); ++t) orders.push_back(fixed(std::log2(errors[0][t] / errors[1][t]), 2));
  rows.push_back(orders);
  md.paragraph(
      "`mpm_radial_consolidation.json`: a cylinder drained at its rim in plane strain, p = p_0 at t = 0 over a "
      "skeleton a thousand times stiffer than the fluid, so that p follows ∂p/∂t = c (∂²p/∂r² + ∂p/(r ∂r)), "
      "whose Bessel series needs the hoop terms of the liquid's force and strain. Largest error of the probes' "
      "pressure against the series' mean over their cell, in p_0, at T = c t/R²:");
  md.table({"radial cells", "steps", "wall time [s]", "T = 0.02", "T = 0.05", "T = 0.1", "T = 0.2"}, rows);
  md.paragraph(
      "Second order while the isochrones are steep; later the errors near what the series leaves out "
      "(the skeleton's compliance and the liquid's inertia).");
  add_plot(out, plot, "saturated_radial.png",
           "Isochrones of the 20-cell run at T = 0.02, 0.05, 0.1, 0.2 and of the 10-cell run at T = 0.05, against "
           "the Bessel series.");
}

}  // namespace ffp
