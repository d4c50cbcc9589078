/// The reference drop into the same loose sand saturated, at two permeabilities that bracket a
/// BlueDrop's fine-to-medium sands, beside the dry drop: the body's motion, the pore pressure at
/// the cone (u1) and the shoulder (u2), the fields at the saturated runs' end, and what the
/// saturated-chamber findings of Yalcin, Zambrano-Cruzatty & Yerro (2023) say beside them.
/// The saturated runs need a step about 35 times shorter than the dry drop's (the undrained wave
/// or the drag), so this study runs outside the main job: `ffp report --only "Saturated drop"`.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/plot.hpp"
#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/saturated_sections.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

constexpr std::size_t kDry = 0, kMedium = 1, kFine = 2, kDeep = 3;

/// What sets how drained the sand is under the cone: c_v = k/(γ_w (1/E_c + n/K_w)) with the
/// skeleton's constrained modulus E_c, and V = v D/c_v (Randolph & Hope 2004) at the impact.
/// NaN where the run has none (the dry sand, a failed run).
struct DrainageFigures {
  double permeability_m_s = std::nan(""), consolidation_m2_s = std::nan(""), normalised_velocity = std::nan("");
};

DrainageFigures drainage_of(const StudyResults& results, std::size_t run) {
  const nlohmann::json s = results.summary(run);
  if (s.empty()) return {};
  const nlohmann::json& scene = s.at("scene");
  const double E = 1e3 * scene.at("material").at("E_kPa").get<double>();
  const double nu = scene.at("material").at("nu").get<double>();
  const double constrained_Pa = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double k = scene.at("soil").at("permeability_m_s").get<double>();
  const double n = scene.at("soil").at("porosity").get<double>();
  const double K_w = 1e3 * scene.at("fluid").at("bulk_modulus_kPa").get<double>();
  const double gamma_w = scene.at("fluid").at("density_kg_m3").get<double>() * scene.at("gravity_m_s2").get<double>();
  const double c_v = k / (gamma_w * (1 / constrained_Pa + n / K_w));
  const double diameter_m = 2 * scene.at("ffp").at("base_radius_m").get<double>();
  return {k, c_v, s.at("impact_velocity_m_s").get<double>() * diameter_m / c_v};
}

std::string run_label(const StudyResults& results, std::size_t run) {
  if (run == kDry) return "dry";
  const DrainageFigures d = drainage_of(results, run);
  char k[16];
  std::snprintf(k, sizeof k, "%.0e", d.permeability_m_s);
  return std::string("k = ") + k + " m/s, V = " + fixed(d.normalised_velocity, 0);
}

/// The hydrostatic pressure at the shoulder's depth, u2 − u2's excess, against time.
Series shoulder_hydrostatic(const CsvData& h) {
  Series hydrostatic{h.column("time_s"), h.column("u2_kPa"), "hydrostatic at the shoulder", "lines dashtype 2"};
  const auto& excess = h.column("u2_excess_kPa");
  for (std::size_t i = 0; i < hydrostatic.y.size(); ++i) hydrostatic.y[i] -= excess[i];
  return hydrostatic;
}

/// u1 and u2 of both saturated runs against time, with the shoulder's hydrostatic pressure.
void write_pore_pressure_figure(const StudyResults& results, StudyOutput& out) {
  Plot u2{"Pore pressure at the shoulder (u2)", "time (s)", "u2 (kPa)", {}, false, false, false, "top right"};
  Plot u1{"Pore pressure at the cone (u1)", "time (s)", "u1 (kPa)", {}, false, false, false, "top right"};
  for (const std::size_t run : {kMedium, kFine}) {
    const CsvData h = results.history(run);
    if (!h.has("u2_kPa")) continue;
    const std::string label = run_label(results, run);
    u2.series.push_back({h.column("time_s"), h.column("u2_kPa"), label});
    u1.series.push_back({h.column("time_s"), h.column("u1_kPa"), label});
    if (run == kMedium) u2.series.push_back(shoulder_hydrostatic(h));
  }
  if (u2.series.empty()) return out.document.paragraph(missing_run("saturated drop"));
  if (write_png_stack({u2, u1}, out.figures_dir / "saturated_drop_pore_pressure.png"))
    out.document.figure(out.figures_relative + "/saturated_drop_pore_pressure.png",
                        "Pore pressure at the shoulder (u2, the mean over the particles in contact just above the "
                        "cone–shaft junction) and at the cone (u1) against time, from the impact; the dashed line "
                        "is the hydrostatic pressure at the shoulder's depth under the water column.");
}

/// When the saturated runs end (the scene's end time).
double saturated_end_s(const StudyResults& results) {
  const nlohmann::json s = results.summary(kMedium);
  return s.empty() ? std::nan("") : s.at("scene").at("end_time_s").get<double>();
}

std::string in_cm(double m) { return fixed(100 * m, 1) + " cm"; }

/// The dry drop's history at the time a saturated run ended.
double dry_at(const StudyResults& results, const std::string& column, double time_s) {
  const CsvData h = results.history(kDry);
  if (!h.has(column)) return std::nan("");
  return h.column(column)[history_row_at(h, time_s)];
}

void write_table(const StudyResults& results, StudyOutput& out) {
  std::vector<std::vector<std::string>> rows;
  const double end_s = saturated_end_s(results);
  for (const std::size_t run : {kDry, kMedium, kFine}) {
    if (!results.ok(run)) {
      rows.push_back({run_label(results, run), "FAILED: " + results.outcome(run).error});
      continue;
    }
    const bool dry = run == kDry;
    const DrainageFigures d = dry ? DrainageFigures{} : drainage_of(results, run);
    const nlohmann::json s = results.summary(run);
    rows.push_back({run_label(results, run),
                    dry ? "–" : scientific(d.consolidation_m2_s) + " m²/s; " + fixed(d.normalised_velocity, 1),
                    scientific(figure(results, run, "dt_s")) + " s; " +
                        (dry ? std::string("CFL") : s.value("time_step_limited_by", std::string("?"))),
                    fixed(figure(results, run, "steps"), 0), fixed(figure(results, run, "wall_time_s"), 0) + " s",
                    dry ? in_cm(dry_at(results, "penetration_m", end_s)) + "; " +
                              fixed(dry_at(results, "velocity_m_s", end_s), 2) + " m/s"
                        : in_cm(figure(results, run, "final_penetration_m")) + "; " +
                              fixed(figure(results, run, "final_velocity_m_s"), 2) + " m/s",
                    fixed(figure(results, run, "peak_deceleration_2ms_g"), 1) + " g",
                    dry ? "–"
                        : fixed(figure(results, run, "u2_peak_kPa"), 0) + " / " +
                              fixed(figure(results, run, "u2_min_kPa"), 0) + " kPa",
                    dry ? "–"
                        : fixed(figure(results, run, "u1_max_kPa"), 0) + " / " +
                              fixed(figure(results, run, "u1_min_kPa"), 0) + " kPa",
                    in_cm(figure(results, run, "sheared_zone_radius_m")) + (dry ? " (at rest)" : " (at the end)")});
  }
  out.document.table(
      {"sand", "c_v; V at impact", "step at the start; its limit", "steps", "wall time",
       "penetration; velocity at " + fixed(1000 * end_s, 0) + " ms", "2 ms peak (over the run)", "u2 peak / min",
       "u1 max / min",
       "sheared zone's reach (ε_dev ≥ " + fixed(100 * figure(results, kDry, "sheared_zone_strain"), 0) + " %)"},
      rows);
}

/// The saturated-chamber findings beside these runs, each a match or a miss as it comes out.
void write_findings(const StudyResults& results, StudyOutput& out) {
  const double end_s = saturated_end_s(results);
  const double dry_depth = dry_at(results, "penetration_m", end_s);
  const double dry_rest = figure(results, kDry, "final_penetration_m");
  const double dry_reach = figure(results, kDry, "sheared_zone_radius_m");
  const double cell_m = figure(results, kDry, "min_cell_m");  // the reach's resolution
  std::vector<std::vector<std::string>> rows;
  for (const std::size_t run : {kMedium, kFine}) {
    if (!results.ok(run)) continue;
    const std::string label = run_label(results, run);
    const double depth = figure(results, run, "final_penetration_m");
    const double velocity = figure(results, run, "final_velocity_m_s");
    const bool deeper = depth > dry_depth;
    rows.push_back({"less penetration than dry (" + label + ")",
                    "at " + fixed(1000 * end_s, 0) + " ms " + in_cm(depth) + " against the dry " + in_cm(dry_depth) +
                        (velocity > 0.05 ? ", still moving at " + fixed(velocity, 2) + " m/s (the dry drop rests at " +
                                               in_cm(dry_rest) + ")"
                                         : ""),
                    deeper ? "miss" : "match so far (the run ends first)"});
    const CsvData h = results.history(run);
    double least_excess = 0.0;
    if (h.has("u2_excess_kPa"))
      for (const double e : h.column("u2_excess_kPa")) least_excess = std::min(least_excess, e);
    rows.push_back({"negative excess pore pressure in the loose sand (" + label + ")",
                    "u2 falls " + fixed(-least_excess, 0) + " kPa below hydrostatic (min u2 " +
                        fixed(figure(results, run, "u2_min_kPa"), 0) + " kPa); the sand has ψ = 0, so not by dilation",
                    least_excess < 0 ? "matches in sign, not in cause" : "miss"});
    const double reach = figure(results, run, "sheared_zone_radius_m");
    rows.push_back({"a local failure saturated, a general one dry (" + label + ")",
                    "sheared zone reaches r = " + in_cm(reach) + " by " + fixed(1000 * end_s, 0) + " ms, the dry one " +
                        in_cm(dry_reach) + " at rest",
                    reach < dry_reach - cell_m   ? "match"
                    : reach > dry_reach + cell_m ? "miss (wider saturated)"
                                                 : "miss (as wide as dry, within a cell)"});
  }
  out.document.table({"finding (Yalcin et al. 2023; Yalcin 2021)", "here", ""}, rows);
}

/// The deep chamber's run through the stop: u2 against time, and when its excess dissipates.
void write_stop_section(const StudyResults& results, StudyOutput& out) {
  Markdown& md = out.document;
  md.heading(3, "Through the stop");
  const nlohmann::json s = results.summary(kDeep);
  if (s.empty()) return md.paragraph(missing_run("deep chamber"));
  const CsvData h = results.history(kDeep);
  const double rest_s = s.value("rest_time_s", std::nan(""));
  const bool rested = s.contains("rest_time_s") && s["rest_time_s"].is_number();
  const bool dissipated = s.contains("u2_dissipation_time_s") && s["u2_dissipation_time_s"].is_number();
  md.paragraph(
      "The same saturated sand (k = 1e-4 m/s) in a chamber " +
      fixed(s.at("scene").at("soil").at("depth_m").get<double>(), 1) +
      " m deep, on 2 cm cells to keep it to minutes (" + fixed(figure(results, kDeep, "particles"), 0) +
      " particles, " + fixed(figure(results, kDeep, "steps"), 0) + " steps, " +
      fixed(figure(results, kDeep, "wall_time_s"), 0) +
      " s): a coarse mesh's answer, shown for the course of u2 through the stop rather than for its figures. " +
      (rested ? "The body comes to rest at " + fixed(1000 * rest_s, 0) + " ms, " +
                    in_cm(figure(results, kDeep, "final_penetration_m")) + " deep (its body is " +
                    in_cm(s.at("scene").at("ffp").at("body_length_m").get<double>()) + " long); u2's excess is " +
                    fixed(figure(results, kDeep, "u2_excess_at_rest_kPa"), 1) + " kPa then, and " +
                    (dissipated ? "falls to 10 % of it at " +
                                      fixed(1000 * figure(results, kDeep, "u2_dissipation_time_s"), 0) + " ms."
                                : s.value("u2_dissipation_note", std::string("does not dissipate in the run.")))
              : "The body has not come to rest by the end of the run."));
  Plot u2{"u2 through the stop (1.5 m chamber, 2 cm)", "time (s)", "u2 (kPa)", {}, false, false, false, "top right"};
  Plot v{"velocity", "time (s)", "velocity (m/s)", {}, false, false, false, "top right"};
  if (h.has("u2_kPa")) {
    u2.series.push_back({h.column("time_s"), h.column("u2_kPa"), "u2"});
    u2.series.push_back(shoulder_hydrostatic(h));
    v.series.push_back({h.column("time_s"), h.column("velocity_m_s"), "velocity"});
  }
  if (write_png_stack({u2, v}, out.figures_dir / "saturated_drop_stop.png"))
    md.figure(out.figures_relative + "/saturated_drop_stop.png",
              "u2 and the body's velocity against time in the 1.5 m chamber, 2 cm cells, k = 1e-4 m/s");
  // At rest the body is at its deepest: the fields there.
  const std::string end = fixed(s.at("scene").at("end_time_s").get<double>(), 3);
  include_run_figure(results, kDeep, "plots/excess_pore_pressure_t" + end + ".png", "saturated_drop_rest_excess.png",
                     "Excess pore pressure with the body at rest, 1.5 m chamber, 2 cm cells", out);
  include_run_figure(results, kDeep, "plots/deviatoric_strain_t" + end + ".png", "saturated_drop_rest_strain.png",
                     "Deviatoric strain with the body at rest, 1.5 m chamber, 2 cm cells", out);
}

}  // namespace

Study saturated_drop_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Saturated drop";
  study.outside_main_job = true;
  study.runs.push_back(reference_drop_run(scenes_dir, "ffp_reference (dry)"));
  study.runs.push_back(scene_run(scenes_dir, "ffp_saturated.json", "ffp_saturated (k = 1e-4 m/s)"));
  study.runs.push_back(
      scene_run(scenes_dir, "ffp_saturated.json", "ffp_saturated (k = 1e-5 m/s)", {"soil.permeability_m_s=1e-5"}));
  // To the stop and past it: the 1 cm chamber is too shallow for a body still moving at 4.7 m/s
  // at its end, so a chamber 1.5 m deep on 2 cm cells, to 0.4 s.
  study.runs.push_back(scene_run(scenes_dir, "ffp_saturated.json", "ffp_saturated (k = 1e-4 m/s, 1.5 m deep, 2 cm)",
                                 {"soil.depth_m=1.5", "mesh.min_cell_m=0.02", "end_time_s=0.4"}));
  study.runs[kMedium].expected_wall_s = 100.0;  // 23,181 steps of 6,086 particles
  study.runs[kFine].expected_wall_s = 200.0;    // 67,779 steps: the drag's bound
  study.runs[kDeep].expected_wall_s = 120.0;    // 96,000 steps of 5,661 particles
  study.write = [](const StudyResults& results, StudyOutput& out) {
    Markdown& md = out.document;
    md.paragraph(
        "The reference drop (BlueDrop 7.71 kg at 5.6 m/s, loose sand MC φ' = 39°, ψ = 0, 1 cm cells) into the "
        "same sand saturated (data/scenes/ffp_saturated.json: n = 0.44, water K_w = 2.2 GPa, 1 m of water above "
        "the bed, impermeable wall and base, drained surface), at k = 1e-4 m/s (a medium sand) and 1e-5 m/s (a "
        "fine one), beside the dry drop. V = v D/c_v at the impact says how drained the sand is under the cone "
        "(drained below about 0.03, undrained above about 30: Randolph & Hope 2004). The saturated runs end at "
        "the scene's end time, with the body still moving. This study runs outside the main job (`ffp report "
        "--only \"Saturated drop\"`): the two-phase step, no mass scaling of the water, is about 35 times the "
        "dry one's.");
    write_table(results, out);
    if (!results.ok(kDry) || !results.ok(kMedium)) return md.paragraph(missing_run("dry or saturated"));
    std::vector<LabelledRun> runs;
    for (const std::size_t run : {kDry, kMedium, kFine})
      if (results.ok(run)) runs.push_back({run, run_label(results, run)});
    ffp_depth_profiles_figure(results, runs, "The reference drop, dry and saturated", "saturated_drop_profiles.png",
                              out);
    write_pore_pressure_figure(results, out);
    const std::string end = fixed(saturated_end_s(results), 3);
    include_run_figure(results, kMedium, "plots/excess_pore_pressure_t" + end + ".png",
                       "saturated_drop_excess_pressure.png",
                       "Excess pore pressure at the end, k = 1e-4 m/s (suction blue, excess red)", out);
    include_run_figure(results, kMedium, "plots/deviatoric_strain_t" + end + ".png", "saturated_drop_strain.png",
                       "Deviatoric strain at the end, k = 1e-4 m/s", out);
    include_run_figure(results, kMedium, "plots/mean_stress_t0.040.png", "saturated_drop_effective_stress.png",
                       "Mean effective stress p' at 40 ms, k = 1e-4 m/s", out);
    include_run_figure(results, kDry, "plots/mean_stress_t0.040.png", "saturated_drop_dry_stress.png",
                       "Mean stress p' at 40 ms, dry", out);
    md.paragraph(
        "Why the saturated sand slows the body less here: the sand is Mohr–Coulomb with ψ = 0. Loaded faster than "
        "its pore water can leave (V ≫ 1), its volume barely changes, so the cone's compression goes into the "
        "pore pressure and the mean effective stress stays near the small geostatic one (the two maps of p' at "
        "40 ms); its frictional strength stays with it. Dry, the same compression raises p' under the cone and "
        "the strength with it. Sands that dilate (ψ > 0) would draw the pore pressure down as they shear and "
        "gain strength: the saturated-chamber runs the findings below come from had dilation dominate.");
    write_findings(results, out);
    write_stop_section(results, out);
  };
  return study;
}

}  // namespace ffp
