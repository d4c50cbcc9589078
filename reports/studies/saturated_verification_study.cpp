/// Verification of the saturated (two-phase) sand against exact answers, run from scenes:
/// the hydrostatic K0 column, the undrained and drained 1D load, Terzaghi's consolidation at
/// three mesh levels, Verruijt's column with its two waves, and radial consolidation. The
/// exact answers are models/consolidation_solutions.hpp, the tests' own; every figure in the
/// text is computed here from the runs.
#include <algorithm>
#include <cmath>
#include <string>

#include "reports/plot.hpp"
#include "reports/studies/saturated_runs.hpp"
#include "reports/studies/saturated_sections.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

const std::vector<double> kTerzaghiCells_m = {0.1, 0.05, 0.025};
const std::vector<double> kTerzaghiTimeFactors = {0.02, 0.05, 0.1, 0.2, 0.5};
const std::vector<double> kRadialTimeFactors = {0.02, 0.05, 0.1, 0.2};

std::string probe_list(const std::string& prefix, const std::vector<std::pair<double, double>>& points) {
  std::string list = "[";
  for (std::size_t i = 0; i < points.size(); ++i)
    list += std::string(i ? "," : "") + "{\"name\":\"" + prefix + std::to_string(i) +
            "\",\"r_m\":" + fixed(points[i].first, 5) + ",\"z_m\":" + fixed(points[i].second, 5) + "}";
  return list + "]";
}

double order(double coarse, double fine) { return std::log2(coarse / fine); }

// ---- hydrostatic K0 column --------------------------------------------------------------------

void write_hydrostatic(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Hydrostatic K0 column");
  const auto run = read_saturated_run(results, kHydrostatic);
  if (!run) return md.paragraph(missing_run("hydrostatic column"));
  const SaturatedParameters& c = run->parameters;
  const double g = c.gravity_m_s2, gamma_w = c.fluid_density_kg_m3 * g;
  const double gamma_eff = (c.dry_density_kg_m3 - (1 - c.porosity) * c.fluid_density_kg_m3) * g;
  const double gamma_sat = (c.dry_density_kg_m3 + c.porosity * c.fluid_density_kg_m3) * g;
  const double k0 = c.k0.value_or(0.0);
  Series p{.title = "p (MPM)", .style = "points"}, sv{.title = "−σ'_v (MPM)", .style = "points"};
  Series sh{.title = "−σ'_h (MPM)", .style = "points"};
  Series p_exact{.title = "γ_w z", .style = "lines"}, sv_exact{.title = "γ' z", .style = "lines"};
  Series sh_exact{.title = "K0 γ' z", .style = "lines"};
  double worst = 0.0;
  const std::size_t last = run->time_s.size() - 1;
  for (const ProbeHistory& h : run->probes) {
    const double depth = c.top_m - h.z_m[last];
    worst = std::max({worst, std::abs(h.pore_pressure_Pa[last] - gamma_w * depth),
                      std::abs(h.stress_zz_Pa[last] + gamma_eff * depth),
                      std::abs(h.stress_rr_Pa[last] + k0 * gamma_eff * depth)});
    p.x.push_back(1e-3 * h.pore_pressure_Pa[last]);
    sv.x.push_back(-1e-3 * h.stress_zz_Pa[last]);
    sh.x.push_back(-1e-3 * h.stress_rr_Pa[last]);
    for (Series* s : {&p, &sv, &sh}) s->y.push_back(depth);
  }
  for (const double depth : {0.0, c.top_m}) {
    p_exact.x.push_back(1e-3 * gamma_w * depth);
    sv_exact.x.push_back(1e-3 * gamma_eff * depth);
    sh_exact.x.push_back(1e-3 * k0 * gamma_eff * depth);
    for (Series* s : {&p_exact, &sv_exact, &sh_exact}) s->y.push_back(depth);
  }
  md.paragraph("The column of `mpm_terzaghi_column.json` without its load (" + fixed(c.top_m, 2) +
               " m, water table at the surface, K0 = " + fixed(k0, 3) + ", ρ_d = " + fixed(c.dry_density_kg_m3, 0) +
               " kg/m³ so that γ' = " + fixed(gamma_eff / gamma_w, 2) + " γ_w), " + std::to_string(run->steps) +
               " steps: after them the probes' pore pressure, vertical and horizontal effective stress differ "
               "from γ_w z, γ' z and K0 γ' z by at most " +
               scientific(worst / (gamma_sat * c.top_m)) + " of γ_sat H (" + scientific(worst) +
               " Pa). The well-balanced form makes the hydrostatic K0 state an exact discrete equilibrium.");
  const Plot plot{.title = "Hydrostatic K0 column",
                  .x_label = "stress (kPa)",
                  .y_label = "depth z (m)",
                  .series = {p_exact, sv_exact, sh_exact, p, sv, sh},
                  .reverse_y = true,
                  .key_position = "top right"};
  add_plot(out, plot, "saturated_hydrostatic.png",
           "Pore pressure and effective stresses against depth after the run, with the exact lines.");
}

// ---- undrained and drained 1D load -------------------------------------------------------------

struct LoadErrors {
  double pressure = 0.0, stress = 0.0;  ///< largest over the bottom half, in Δσ
  Series p{}, p_exact{}, s{}, s_exact{};
};

/// The pore pressure's and the skeleton's shares of the load at the end, against the exact
/// shares over the bottom half (where the drained top's influence has not arrived).
LoadErrors load_errors(const SaturatedRun& run, double expected_share, const std::string& label) {
  const SaturatedParameters& c = run.parameters;
  const std::size_t last = run.time_s.size() - 1;
  LoadErrors e{.p = {.title = "p/Δσ, " + label, .style = "points"},
               .p_exact = {.title = "", .style = "lines dashtype 2"},
               .s = {.title = "−σ'_zz/Δσ, " + label, .style = "points"},
               .s_exact = {.title = "", .style = "lines dashtype 2"}};
  for (const ProbeHistory& h : run.probes) {
    const double depth = c.top_m - h.z0_m;
    e.p.x.push_back(h.pore_pressure_Pa[last] / c.load_Pa);
    e.s.x.push_back(-h.stress_zz_Pa[last] / c.load_Pa);
    e.p.y.push_back(depth);
    e.s.y.push_back(depth);
    if (depth < 0.5 * c.top_m) continue;
    e.pressure = std::max(e.pressure, std::abs(h.pore_pressure_Pa[last] / c.load_Pa - expected_share));
    e.stress = std::max(e.stress, std::abs(-h.stress_zz_Pa[last] / c.load_Pa - (1 - expected_share)));
  }
  e.p_exact.x = {expected_share, expected_share};
  e.s_exact.x = {1 - expected_share, 1 - expected_share};
  e.p_exact.y = e.s_exact.y = {0.5 * c.top_m, c.top_m};
  return e;
}

void write_load(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Undrained and drained 1D load");
  const auto undrained = read_saturated_run(results, kUndrained), drained = read_saturated_run(results, kDrained);
  if (!undrained || !drained) return md.paragraph(missing_run("1D load"));
  const SaturatedParameters& c = undrained->parameters;
  const double share = c.undrained_share();
  const LoadErrors u = load_errors(*undrained, share, "k = " + scientific(c.permeability_m_s, 1) + " m/s");
  const LoadErrors d =
      load_errors(*drained, 0.0, "k = " + scientific(drained->parameters.permeability_m_s, 1) + " m/s");
  md.paragraph(
      "`mpm_saturated_load_column.json`: " + fixed(1e-3 * c.load_Pa, 0) + " kPa on the drained top of a " +
      fixed(c.top_m, 2) + " m column over a " + fixed(1e3 * c.ramp_s, 0) +
      " ms half cosine, with Cundall damping. Undrained (bottom half, beyond the drained top's reach): "
      "Δp = (K_w/n)/(E_c + K_w/n) Δσ = " +
      fixed(share, 3) + " Δσ with this test fluid; measured within " + scientific(u.pressure) + " Δσ (σ'_zz within " +
      scientific(u.stress) + " Δσ), " + std::to_string(undrained->steps) + " steps. Drained (c_v t/H² = " +
      fixed(drained->parameters.consolidation_coefficient_m2_s() * drained->time_s.back() / (c.top_m * c.top_m), 0) +
      "): p = 0 within " + scientific(d.pressure) + " Δσ, σ'_zz = −Δσ within " + scientific(d.stress) +
      " Δσ. What remains is the damped ringing.");
  const Plot plot{.title = "1D load: the pore fluid's and the skeleton's shares against depth",
                  .x_label = "share of the load",
                  .y_label = "depth (m)",
                  .series = {u.p, u.s, d.p, d.s, u.p_exact, u.s_exact, d.p_exact, d.s_exact},
                  .reverse_y = true,
                  .key_position = "bottom left"};
  add_plot(out, plot, "saturated_load.png",
           "The pore fluid's and the skeleton's shares of the load against depth at the end, undrained and "
           "drained, with the exact shares (dashed, over the bottom half, where the top's drainage has not "
           "arrived).");
}

// ---- Terzaghi ---------------------------------------------------------------------------------

struct TerzaghiLevel {
  std::vector<double> pressure_error{}, settlement_error{};  ///< per time factor, in p_0 and p_0 H/E_c
  std::vector<Series> isochrones{};                          ///< MPM, per time factor
  double cell_m = 0.0;
  long steps = 0;
  double wall_s = 0.0;
};

/// The probes' excess pore pressure against the series at their cell's centre (the one pressure
/// of a cell, Q1–P0), and the top probes' settlement, area-weighted, against w at their depth.
TerzaghiLevel terzaghi_level(const SaturatedRun& run, std::vector<Series>* exact_curves) {
  const SaturatedParameters& c = run.parameters;
  const double H = c.top_m, p0 = c.initial_excess_pressure_Pa, cv = c.consolidation_coefficient_m2_s();
  const Terzaghi exact{p0, H, cv, c.constrained_modulus_Pa};
  TerzaghiLevel level{.cell_m = c.cell_z_m, .steps = run.steps, .wall_s = run.wall_time_s};
  for (const double T : kTerzaghiTimeFactors) {
    const std::size_t row = nearest_row(run.time_s, T * H * H / cv);
    const double t = run.time_s[row];
    double worst = 0.0, w = 0.0, w_exact = 0.0, weight = 0.0;
    Series iso{.title = "T = " + fixed(T, 2) + ", h = " + fixed(100 * c.cell_z_m, 1) + " cm", .style = "points"};
    for (const ProbeHistory& h : run.probes) {
      if (h.name.starts_with("top")) {
        w += h.r0_m * (h.z0_m - h.z_m[row]);
        w_exact += h.r0_m * exact.displacement(H - h.z0_m, t);
        weight += h.r0_m;
        continue;
      }
      const double centre = H - (std::floor(h.z0_m / c.cell_z_m) + 0.5) * c.cell_z_m;
      worst = std::max(worst, std::abs(h.excess_pressure_Pa[row] - exact.pressure(centre, t)) / p0);
      iso.x.push_back(h.excess_pressure_Pa[row] / p0);
      iso.y.push_back(centre / H);
    }
    level.pressure_error.push_back(worst);
    level.settlement_error.push_back(std::abs(w - w_exact) / weight / (p0 * H / c.constrained_modulus_Pa));
    level.isochrones.push_back(iso);
    if (exact_curves) {
      Series curve{.title = "", .style = "lines"};
      for (int k = 0; k <= 100; ++k) {
        curve.x.push_back(exact.pressure(H * k / 100.0, t) / p0);
        curve.y.push_back(k / 100.0);
      }
      exact_curves->push_back(curve);
    }
  }
  return level;
}

void write_terzaghi(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Terzaghi's consolidation");
  std::vector<TerzaghiLevel> levels;
  std::vector<Series> exact_curves;
  for (std::size_t l = 0; l < kTerzaghiCells_m.size(); ++l) {
    const auto run = read_saturated_run(results, kTerzaghiCoarse + l);
    if (!run) return md.paragraph(missing_run("Terzaghi"));
    levels.push_back(terzaghi_level(*run, l == 0 ? &exact_curves : nullptr));
  }
  std::vector<std::vector<std::string>> rows;
  for (const TerzaghiLevel& l : levels) {
    std::vector<std::string> row = {fixed(100 * l.cell_m, 1) + " cm", std::to_string(l.steps), fixed(l.wall_s, 1)};
    for (const double e : l.pressure_error) row.push_back(scientific(e));
    row.push_back(scientific(*std::max_element(l.settlement_error.begin(), l.settlement_error.end())));
    rows.push_back(row);
  }
  for (std::size_t l = 1; l < levels.size(); ++l) {
    std::vector<std::string> row = {
        "order " + fixed(100 * levels[l - 1].cell_m, 1) + " → " + fixed(100 * levels[l].cell_m, 1) + " cm", "", ""};
    for (std::size_t t = 0; t < kTerzaghiTimeFactors.size(); ++t)
      row.push_back(fixed(order(levels[l - 1].pressure_error[t], levels[l].pressure_error[t]), 2));
    row.push_back("");
    rows.push_back(row);
  }
  md.paragraph(
      "`mpm_consolidation_column.json` at three mesh levels: the pore fluid starts at p_0 over an unloaded "
      "skeleton under an equal load (test fluid, K_w/n = E_c), drained at the top. Largest error of the probes' "
      "pressure against the series at their cell's centre, in p_0, at each T = c_v t/H², and of the top's "
      "area-weighted settlement against w(ζ, t) at its depth, in p_0 H/E_c (worst over T):");
  std::vector<std::string> header = {"cells", "steps", "wall time [s]"};
  for (const double T : kTerzaghiTimeFactors) header.push_back("T = " + fixed(T, 2));
  header.push_back("settlement");
  md.table(header, rows);
  md.paragraph(
      "While the isochrones are steep (T ≤ 0.1) the cell pressure converges at second order; later the "
      "errors near the floor of a dynamic model against a quasi-static theory.");
  Plot plot{.title = "Terzaghi: isochrones",
            .x_label = "excess pore pressure p / p_0",
            .y_label = "depth ζ/H",
            .series = {},
            .reverse_y = true,
            .key_position = "bottom left"};
  for (std::size_t t = 0; t < 4; ++t) plot.series.push_back(exact_curves[t]);
  plot.series.front().title = "series solution";
  for (std::size_t t = 0; t < 4; ++t) plot.series.push_back(levels.back().isochrones[t]);
  plot.series.push_back(levels.front().isochrones[1]);
  add_plot(out, plot, "saturated_terzaghi.png",
           "Isochrones at T = 0.02, 0.05, 0.1, 0.2 (2.5 cm cells) and T = 0.05 at 10 cm, against the series.");
}

}  // namespace

Study saturated_verification_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Saturated sand: verification";
  std::vector<std::pair<double, double>> rows;
  for (int j = 0; j < 20; ++j) rows.emplace_back(0.0125, 0.025 + 0.05 * j);
  study.runs.push_back(scene_run(scenes_dir, "mpm_terzaghi_column.json", "saturated: hydrostatic column",
                                 {"surface_pressures=[]", "end_time_s=0.02", "output.field_times_s=[]",
                                  "bodies.0.material.density_kg_m3=1700",  // γ' = 1.1 γ_w: the lines part
                                  "output.probes=" + probe_list("row", rows)}));
  study.runs.push_back(scene_run(scenes_dir, "mpm_saturated_load_column.json", "saturated: undrained 1D load"));
  study.runs.push_back(scene_run(scenes_dir, "mpm_saturated_load_column.json", "saturated: drained 1D load",
                                 {"bodies.0.permeability_m_s=0.1", "end_time_s=0.5"}));
  for (const double h : kTerzaghiCells_m) {
    // Square cells, two across as in the scene: probes at the finest rows' centres and on the
    // top row's four particles (for the area-weighted settlement).
    std::vector<std::pair<double, double>> centres, top;
    for (int j = 0; j < 40; ++j) centres.emplace_back(0.25 * h, 0.0125 + 0.025 * j);
    for (int i = 0; i < 4; ++i) top.emplace_back((0.25 + 0.5 * i) * h, 1.0);
    std::string probes = probe_list("row", centres);
    probes.back() = ',';
    probes += probe_list("top", top).substr(1);
    const std::string width = fixed(2 * h, 3);
    study.runs.push_back(scene_run(
        scenes_dir, "mpm_consolidation_column.json", "saturated: Terzaghi, " + fixed(100 * h, 1) + " cm",
        {"mesh.cell_z_m=" + fixed(h, 3), "mesh.cell_r_m=" + fixed(h, 3), "mesh.r_max_m=" + width,
         "bodies.0.region.r_max_m=" + width, "surface_pressures.0.r_max_m=" + width, "output.probes=" + probes}));
  }
  study.runs.push_back(scene_run(scenes_dir, "mpm_verruijt_column.json", "saturated: Verruijt, 1 cm"));
  study.runs.push_back(
      scene_run(scenes_dir, "mpm_verruijt_column.json", "saturated: Verruijt, 5 mm",
                {"mesh.cell_z_m=0.005", "mesh.cell_r_m=0.005", "mesh.r_max_m=0.01", "bodies.0.region.r_max_m=0.01",
                 "surface_pressures.0.r_max_m=0.01", "output.history_interval_s=1e-5"}));
  study.runs.push_back(
      scene_run(scenes_dir, "mpm_radial_consolidation.json", "saturated: radial, 5 cm",
                {"mesh.cell_r_m=0.05", "mesh.cell_z_m=0.05", "mesh.z_max_m=0.1", "bodies.0.region.z_max_m=0.1"}));
  study.runs.push_back(scene_run(scenes_dir, "mpm_radial_consolidation.json", "saturated: radial, 2.5 cm"));
  study.write = [](const StudyResults& results, StudyOutput& out) {
    out.document.paragraph(
        "The five exact checks of the saturated (two-phase) sand (docs/theory.md#saturated), each run from a "
        "scene of the `mpm` kind; the exact answers are those of the tests (`models/consolidation_solutions.hpp`). "
        "The " +
        std::to_string(results.size()) + " runs take " + fixed(results.total_wall_time_s(), 1) +
        " s together; every problem runs at its cheapest level that still shows its point (Terzaghi's order at "
        "10, 20 and 40 cells; the radial order at 10 and 20).");
    write_hydrostatic(results, out);
    write_load(results, out);
    write_terzaghi(results, out);
    write_saturated_waves(results, out);
    write_radial_consolidation(results, out);
  };
  return study;
}

}  // namespace ffp
