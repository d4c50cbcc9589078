/// Mesh convergence of the reference FFP run: 2 ms peak deceleration, final
/// penetration and the 0–40 ms impulse against wall time, with the error against
/// a Richardson extrapolation of the three finest meshes (or the finest, if that
/// fails); the run's health per level; pure FLIP as a control, and the tip at four
/// phases between two node rows (the staircase of the non-conforming cone); the
/// levels' penetration at fixed times, to show where in the drop they part.
#include <algorithm>
#include <array>
#include <cmath>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

const std::vector<double> kReferenceCells_m = {0.02, 0.01, 0.005, 0.0025};
// The PIC share per second held fixed across the levels (the 1 cm mesh's rate): the scene's default,
// per_soil_step, takes its reference step from the mesh and so damps twice as much per second at each
// halving of h, a setting that would change with the level.
const std::string kPicPerSecond = "solver.pic_blend=per_second";
// The controls (pure FLIP; the tip between node rows) on the three coarser levels.
constexpr std::size_t kControlLevels = 3;
// The tip's phases between two node rows besides the level's own 0 (mesh.tip_offset_cells); 0.5 is
// "half a cell off", the farthest from a row. The four phases sample the staircase the moving mesh freezes.
constexpr std::array<double, 3> kTipPhases = {0.25, 0.5, 0.75};
constexpr std::size_t kRunsPerControlLevel = 1 + kTipPhases.size();  // pure FLIP and the phases
// Where half a cell off sits among a level's phases (0 first, then kTipPhases).
constexpr std::size_t kHalfCellPhase = 2;
static_assert(kTipPhases[kHalfCellPhase - 1] == 0.5);

double phase_mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double phase_spread(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

/// A level's expected wall time: particles grow as h⁻² and steps as h⁻¹; 1 cm takes about 5 s on one core.
double level_wall_s(double h) { return 5.0 * std::pow(0.01 / h, 3); }

/// A history column at time t (history.csv, linear between rows; NaN outside the run).
double value_at(const CsvData& h, const std::string& column, double t) {
  return h.has(column) && h.has("time_s") ? interpolate(h.column("time_s"), h.column(column), t) : std::nan("");
}

// Times at which the levels' penetrations are compared: the fast first half of the drop, where the
// cone is embedded and the peak comes, and the slow second half, where the sand bears the body.
constexpr std::array<double, 7> kCompareTimes_s = {0.01, 0.02, 0.03, 0.04, 0.06, 0.08, 0.15};

double last(const CsvData& h, const std::string& column) {
  return h.has(column) && !h.column(column).empty() ? h.column(column).back() : std::nan("");
}

}  // namespace

Study ffp_convergence_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Mesh convergence of the reference run: error against run time";
  for (double h : kReferenceCells_m) {
    study.runs.push_back(scene_run(scenes_dir, "ffp_reference.json", "min cell " + fixed(100 * h, 2) + " cm",
                                   {"mesh.min_cell_m=" + fixed(h, 4), kPicPerSecond}));
    study.runs.back().expected_wall_s = level_wall_s(h);
  }
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    const double h = kReferenceCells_m[l];
    const std::string mesh = "mesh.min_cell_m=" + fixed(h, 4);
    study.runs.push_back(scene_run(scenes_dir, "ffp_reference.json", "pure FLIP, " + fixed(100 * h, 2) + " cm",
                                   {mesh, "solver.flip_fraction=1", "output.field_times_s=[]"}));
    study.runs.back().expected_wall_s = level_wall_s(h);  // as the level's own run
    for (double phase : kTipPhases) {
      // The 0.5 phase keeps its label of earlier reports ("half a cell off").
      const std::string label = phase == 0.5 ? "tip half a cell off, " : "tip " + fixed(phase, 2) + " cell off, ";
      study.runs.push_back(
          scene_run(scenes_dir, "ffp_reference.json", label + fixed(100 * h, 2) + " cm",
                    {mesh, "mesh.tip_offset_cells=" + fixed(phase, 2), kPicPerSecond, "output.field_times_s=[]"}));
      study.runs.back().expected_wall_s = level_wall_s(h);
    }
  }
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    md.paragraph(
        "The reference scene with every mesh size following the minimum cell (2, 1, 0.5 and 0.25 cm), and the "
        "PIC share of the velocity update held at the 1 cm mesh's rate per second on every level (solver.pic_blend "
        "per_second; the scene's per_soil_step would double it at each halving). The "
        "reference value of each quantity is the Richardson extrapolation of the three finest meshes when they "
        "converge monotonically with an order between 0.3 and 4, otherwise the finest mesh's value. The "
        "quantities are taken over fixed physical windows: the peak of the 2 ms running mean of the "
        "deceleration, the final penetration at 0.15 s and the soil's impulse on the FFP over 0–40 ms. Steps "
        "that shrink at one Courant number are not yet convergence: at Courant 0.25 the same usl series of final "
        "penetrations does not shrink, musl's goes on drifting, and a run of the same scene at 0.125 cm, outside "
        "the report (27 minutes), continues the drift (docs/verification.md#mesh-convergence).");
    const std::size_t n = kReferenceCells_m.size();
    std::vector<double> peak(n), depth(n), wall(n), impulse(n);
    for (std::size_t i = 0; i < n; ++i) {
      peak[i] = figure(results, i, "peak_deceleration_2ms_g");
      depth[i] = figure(results, i, "final_penetration_m");
      wall[i] = figure(results, i, "wall_time_s");
      impulse[i] = value_at(results.history(i), "impulse_N_s", 0.04);
    }
    const Extrapolation peak_ref = richardson(peak[n - 3], peak[n - 2], peak[n - 1]);
    const Extrapolation depth_ref = richardson(depth[n - 3], depth[n - 2], depth[n - 1]);
    const Extrapolation impulse_ref = richardson(impulse[n - 3], impulse[n - 2], impulse[n - 1]);
    std::vector<std::vector<std::string>> rows;
    Series peak_error{{}, {}, "peak deceleration", "linespoints"},
        depth_error{{}, {}, "final penetration", "linespoints"};
    for (std::size_t i = 0; i < n; ++i) {
      const double e_peak = std::abs(peak[i] - peak_ref.value) / std::abs(peak_ref.value);
      const double e_depth = std::abs(depth[i] - depth_ref.value) / std::abs(depth_ref.value);
      const double e_impulse = std::abs(impulse[i] - impulse_ref.value) / std::abs(impulse_ref.value);
      rows.push_back({fixed(100 * kReferenceCells_m[i], 2), fixed(figure(results, i, "particles"), 0),
                      fixed(figure(results, i, "steps"), 0), fixed(wall[i], 1), fixed(peak[i], 2),
                      fixed(100 * e_peak, 1), fixed(100 * depth[i], 2), fixed(100 * e_depth, 1), fixed(impulse[i], 2),
                      fixed(100 * e_impulse, 1)});
      if (std::isfinite(wall[i]) && e_peak > 0) {
        peak_error.x.push_back(wall[i]);
        peak_error.y.push_back(e_peak);
      }
      if (std::isfinite(wall[i]) && e_depth > 0) {
        depth_error.x.push_back(wall[i]);
        depth_error.y.push_back(e_depth);
      }
    }
    md.table({"min cell [cm]", "particles", "steps", "wall time [s]", "2 ms peak [g]", "error [%]",
              "final penetration [cm]", "error [%]", "impulse 0–40 ms [N s]", "error [%]"},
             rows);
    // What each level's run did to the soil: the contact's intrusion (it should
    // shrink with h), the largest V/V0, the smallest step, and the soil's kinetic
    // energy at the end (a level whose Δt collapses or whose soil gains energy with
    // no work done on it is not a solution: flag it).
    std::vector<std::vector<std::string>> health;
    for (std::size_t i = 0; i < n; ++i) {
      const auto s = results.summary(i);
      if (s.empty()) continue;
      const double dt0 = figure(results, i, "dt_s"), dt_min = figure(results, i, "dt_min_s");
      const bool collapsed = std::isfinite(dt0) && std::isfinite(dt_min) && dt_min < 0.01 * dt0;
      health.push_back(
          {fixed(100 * kReferenceCells_m[i], 2), fixed(1000 * figure(results, i, "max_soil_intrusion_m"), 2),
           fixed(figure(results, i, "max_soil_intrusion_cells"), 2), fixed(figure(results, i, "max_volume_ratio"), 2),
           fixed(figure(results, i, "inflated_particles_max"), 0), scientific(dt_min),
           scientific(last(results.history(i), "soil_kinetic_energy_J")),
           collapsed ? "Δt collapsed (< 1 % of the first step): not used" : "ok"});
    }
    md.table({"min cell [cm]", "max intrusion [mm]", "[cells]", "max V/V0", "particles at V/V0 ≥ 2", "Δt_min [s]",
              "soil kinetic energy at 0.15 s [J]", "level"},
             health);
    // The controls: pure FLIP (no PIC share: a level whose soil then gains energy with no work
    // done on it has an unstable step) and the tip at four phases between two node rows.
    std::vector<std::vector<std::string>> controls, phases;
    std::vector<double> phase_depth(kControlLevels), phase_peak(kControlLevels);
    std::vector<double> depth_range(kControlLevels), peak_range(kControlLevels);
    // The figure: every phase as a point at its level's cell size, the phase means as a line.
    Series depth_phases{{}, {}, "final penetration, each phase", "points"},
        peak_phases{{}, {}, "2 ms peak, each phase", "points"};
    for (std::size_t l = 0; l < kControlLevels; ++l) {
      const std::size_t flip = n + kRunsPerControlLevel * l;
      const double ke = last(results.history(l), "soil_kinetic_energy_J");
      const double ke_flip = last(results.history(flip), "soil_kinetic_energy_J");
      controls.push_back({fixed(100 * kReferenceCells_m[l], 2), fixed(100 * depth[l], 2),
                          fixed(100 * figure(results, flip, "final_penetration_m"), 2), scientific(ke),
                          scientific(ke_flip)});
      // Phase 0 is the level's own run.
      std::vector<double> z{depth[l]}, g{peak[l]};
      for (std::size_t k = 0; k < kTipPhases.size(); ++k) {
        z.push_back(figure(results, flip + 1 + k, "final_penetration_m"));
        g.push_back(figure(results, flip + 1 + k, "peak_deceleration_2ms_g"));
      }
      for (std::size_t k = 0; k < z.size(); ++k) {
        depth_phases.x.push_back(100 * kReferenceCells_m[l]);
        depth_phases.y.push_back(100 * z[k]);
        peak_phases.x.push_back(100 * kReferenceCells_m[l]);
        peak_phases.y.push_back(g[k]);
      }
      phase_depth[l] = phase_mean(z);
      phase_peak[l] = phase_mean(g);
      depth_range[l] = phase_spread(z);
      peak_range[l] = phase_spread(g);
      std::vector<std::string> row{fixed(100 * kReferenceCells_m[l], 2)};
      for (double x : z) row.push_back(fixed(100 * x, 2));
      row.push_back(fixed(100 * phase_depth[l], 2));
      row.push_back(fixed(100 * depth_range[l] / phase_depth[l], 1));
      row.push_back(fixed(100 * (z[kHalfCellPhase] - z[0]) / z[0], 1));
      for (double x : g) row.push_back(fixed(x, 2));
      row.push_back(fixed(phase_peak[l], 2));
      row.push_back(fixed(100 * peak_range[l] / phase_peak[l], 1));
      phases.push_back(row);
    }
    md.table({"min cell [cm]", "final penetration [cm]", "pure FLIP [cm]", "soil KE at 0.15 s [J]", "pure FLIP [J]"},
             controls);
    md.paragraph(
        "The tip at four phases between two node rows (mesh.tip_offset_cells 0, 0.25, 0.5, 0.75; 0 is the "
        "level's run above). The moving mesh freezes the cone's staircase for the whole run, so each phase is "
        "one sample of it; the range over the phases (as % of their mean) is the scatter any one run carries, "
        "and the bias is the run half a cell off against the run on a row.");
    md.table({"min cell [cm]", "z_f at 0 [cm]", "0.25", "0.5", "0.75", "mean [cm]", "range [%]", "bias at 0.5 [%]",
              "2 ms peak at 0 [g]", "0.25", "0.5", "0.75", "mean [g]", "range [%]"},
             phases);
    {
      Series depth_mean{{}, {}, "mean of the phases", "linespoints"},
          peak_mean{{}, {}, "mean of the phases", "linespoints"};
      Series depth_row{{}, {}, "tip on a row, every level", "lines dashtype 2"},
          peak_row{{}, {}, "tip on a row, every level", "lines dashtype 2"};
      for (std::size_t l = 0; l < kControlLevels; ++l) {
        depth_mean.x.push_back(100 * kReferenceCells_m[l]);
        depth_mean.y.push_back(100 * phase_depth[l]);
        peak_mean.x.push_back(100 * kReferenceCells_m[l]);
        peak_mean.y.push_back(phase_peak[l]);
      }
      for (std::size_t i = 0; i < n; ++i) {
        depth_row.x.push_back(100 * kReferenceCells_m[i]);
        depth_row.y.push_back(100 * depth[i]);
        peak_row.x.push_back(100 * kReferenceCells_m[i]);
        peak_row.y.push_back(peak[i]);
      }
      const Plot depth_plot{"Final penetration against the cell size, four tip phases per level",
                            "min cell (cm)",
                            "final penetration (cm)",
                            {depth_phases, depth_mean, depth_row},
                            true,
                            false,
                            false,
                            "top right"};
      const Plot peak_plot{"2 ms peak deceleration against the cell size",
                           "min cell (cm)",
                           "2 ms peak (g)",
                           {peak_phases, peak_mean, peak_row},
                           true,
                           false,
                           false,
                           "top left"};
      if (write_png_stack({depth_plot, peak_plot}, out.figures_dir / "convergence_tip_phases.png"))
        md.figure(out.figures_relative + "/convergence_tip_phases.png",
                  "Each tip phase's final penetration and 2 ms peak at its level (points), their means (line) and "
                  "the tip-on-a-row series of every level (dashed).");
    }
    auto steps = [](const std::vector<double>& q, double scale) {
      std::string text;
      for (std::size_t i = 1; i < q.size(); ++i) text += (i > 1 ? ", " : "") + fixed(scale * (q[i] - q[i - 1]), 2);
      return text;
    };
    // A step between the two finest levels that is smaller than the phase scatter of the coarser one
    // cannot show convergence: one run per level is one sample of that scatter.
    const double last_depth_step = depth[n - 1] - depth[n - 2], last_peak_step = peak[n - 1] - peak[n - 2];
    const std::size_t finest = kControlLevels - 1;  // the finest level with phases (0.5 cm)
    const bool depth_within = std::abs(last_depth_step) < depth_range[finest];
    const bool peak_within = std::abs(last_peak_step) < peak_range[finest];
    auto within = [](bool is_within) {
      return is_within ? "within that level's phase range" : "larger than that level's phase range";
    };
    md.paragraph("Means over the four phases at 2, 1 and 0.5 cm: final penetration " + fixed(100 * phase_depth[0], 2) +
                 " / " + fixed(100 * phase_depth[1], 2) + " / " + fixed(100 * phase_depth[2], 2) + " cm (steps " +
                 steps(phase_depth, 100.0) + " cm), 2 ms peak " + fixed(phase_peak[0], 2) + " / " +
                 fixed(phase_peak[1], 2) + " / " + fixed(phase_peak[2], 2) + " g (steps " + steps(phase_peak, 1.0) +
                 " g). The step from 0.5 to 0.25 cm, " + fixed(100 * last_depth_step, 2) +
                 " cm in the final penetration and " + fixed(last_peak_step, 2) + " g in the peak, is " +
                 within(depth_within) + " at 0.5 cm (" + fixed(100 * depth_range[finest], 2) + " cm) and " +
                 within(peak_within) + " (" + fixed(peak_range[finest], 2) + " g)" +
                 (depth_within || peak_within
                      ? ", so the Richardson figures below rest on single samples of the staircase."
                      : "."));
    auto describe = [](const char* what, const Extrapolation& e, double scale, const char* unit) {
      return std::string(what) + ": reference " + fixed(scale * e.value, 2) + " " + unit +
             (std::isfinite(e.order) ? " (Richardson, observed order " + fixed(e.order, 2) + ")"
                                     : " (finest mesh: the sequence is not in the asymptotic range)");
    };
    md.paragraph(describe("2 ms peak deceleration", peak_ref, 1.0, "g") + "; " +
                 describe("final penetration", depth_ref, 100.0, "cm") + "; " +
                 describe("impulse over 0–40 ms", impulse_ref, 1.0, "N s") + ".");
    // Where in the drop the levels part: the penetration of every level at fixed times, the steps
    // between levels, the observed order from the three finest, and the 0.5 cm level's phase range
    // at the same time (a step below it is not evidence either way).
    {
      const std::size_t finest_phases = n + kRunsPerControlLevel * (kControlLevels - 1) + 1;
      auto penetration_at = [&](std::size_t run, double t) {
        return value_at(results.history(run), "penetration_m", t);
      };
      auto phase_range_at = [&](double t) {
        std::vector<double> z{penetration_at(kControlLevels - 1, t)};
        for (std::size_t k = 0; k < kTipPhases.size(); ++k) z.push_back(penetration_at(finest_phases + k, t));
        return std::ranges::all_of(z, [](double x) { return std::isfinite(x); }) ? phase_spread(z) : std::nan("");
      };
      std::vector<std::vector<std::string>> timeline;
      std::size_t shrinking = 0;  // compare times, from the first, whose steps all shrink
      std::size_t resolved = 0;   // ... and whose last step exceeds the 0.5 cm level's phase range
      bool still_shrinking = true, still_resolved = true;
      for (double t : kCompareTimes_s) {
        std::vector<double> z(n);
        for (std::size_t i = 0; i < n; ++i) z[i] = penetration_at(i, t);
        std::vector<std::string> row{fixed(1000 * t, 0)};
        for (double x : z) row.push_back(fixed(100 * x, 2));
        bool shrinks = true;
        for (std::size_t i = 1; i < n; ++i) {
          row.push_back(fixed(100 * (z[i] - z[i - 1]), 2));
          if (i > 1) shrinks = shrinks && std::abs(z[i] - z[i - 1]) < std::abs(z[i - 1] - z[i - 2]);
        }
        const Extrapolation e = richardson(z[n - 3], z[n - 2], z[n - 1]);
        row.push_back(std::isfinite(e.order) ? fixed(e.order, 2) : "–");
        const double range = phase_range_at(t);
        row.push_back(fixed(100 * range, 2));
        timeline.push_back(row);
        still_shrinking = still_shrinking && shrinks;
        still_resolved = still_resolved && still_shrinking && std::abs(z[n - 1] - z[n - 2]) > range;
        if (still_shrinking) ++shrinking;
        if (still_resolved) ++resolved;
      }
      auto ms = [](std::size_t k) { return fixed(1000 * kCompareTimes_s[k], 0) + " ms"; };
      std::string reading = shrinking == 0 ? " The steps do not shrink at any of these times."
                            : shrinking == kCompareTimes_s.size()
                                ? " The steps shrink at every one of these times."
                                : " The steps shrink at each halving up to " + ms(shrinking - 1) +
                                      " and no longer at " + ms(shrinking) + ".";
      if (resolved > 0 && resolved < shrinking)
        reading += " Up to " + ms(resolved - 1) +
                   " the last step is larger than the 0.5 cm level's phase range, so the shrinking is measured; "
                   "from " +
                   ms(resolved) +
                   " on it lies within that range, and one run per level cannot show whether the steps shrink "
                   "there.";
      else if (resolved == 0 && shrinking > 0)
        reading += " The last step lies within the 0.5 cm level's phase range from the first of these times on.";
      md.paragraph(
          "Where in the drop the levels part: each level's penetration (tip on a row) at fixed times, the steps "
          "between successive levels, the observed order of the three finest (– where the steps do not shrink "
          "monotonically or the order lies outside 0.3–4) and the 0.5 cm level's range over its four tip phases at "
          "that time." +
          reading);
      std::vector<std::string> header{"t [ms]"};
      for (double h : kReferenceCells_m) header.push_back("z at " + fixed(100 * h, 2) + " cm [cm]");
      for (std::size_t i = 1; i < n; ++i)
        header.push_back("step " + fixed(100 * kReferenceCells_m[i - 1], 2) + "→" +
                         fixed(100 * kReferenceCells_m[i], 2));
      header.push_back("order");
      header.push_back("0.5 cm phase range [cm]");
      md.table(header, timeline);
      // The same on a 2 ms raster as a figure: each halving's step against time.
      std::vector<Series> halvings;
      for (std::size_t i = 1; i < n; ++i)
        halvings.push_back(
            {{},
             {},
             fixed(100 * kReferenceCells_m[i - 1], 2) + " → " + fixed(100 * kReferenceCells_m[i], 2) + " cm",
             "lines"});
      Series range{{}, {}, "0.5 cm level's phase range", "lines dashtype 2"};
      for (double t = 0.002; t <= kCompareTimes_s.back() + 1e-9; t += 0.002) {
        for (std::size_t i = 1; i < n; ++i) {
          const double step = penetration_at(i, t) - penetration_at(i - 1, t);
          if (!std::isfinite(step)) continue;
          halvings[i - 1].x.push_back(1000 * t);
          halvings[i - 1].y.push_back(100 * step);
        }
        const double r = phase_range_at(t);
        if (std::isfinite(r)) {
          range.x.push_back(1000 * t);
          range.y.push_back(100 * r);
        }
      }
      halvings.push_back(range);
      const Plot step_plot{"Penetration step at each halving of the cell against time",
                           "time (ms)",
                           "penetration on the finer mesh − on the coarser (cm)",
                           halvings,
                           false,
                           false,
                           false,
                           "top left"};
      if (write_png(step_plot, out.figures_dir / "convergence_steps_in_time.png"))
        md.figure(out.figures_relative + "/convergence_steps_in_time.png",
                  "The change of penetration at each halving of the cell, against time, and the 0.5 cm level's "
                  "range over its tip phases.");
    }
    Plot p{"Error against wall time (2 cores)",
           "wall time of the run (s)",
           "relative error",
           {peak_error, depth_error},
           true,
           true,
           false,
           "top right"};
    if (write_png(p, out.figures_dir / "convergence_error_vs_wall_time.png"))
      md.figure(out.figures_relative + "/convergence_error_vs_wall_time.png",
                "Relative error of peak deceleration and final penetration against wall time, one point per mesh.");
    std::vector<LabelledRun> runs;
    for (std::size_t i = 0; i < n; ++i) runs.push_back({i, "min cell " + fixed(100 * kReferenceCells_m[i], 2) + " cm"});
    ffp_depth_profiles_figure(results, runs, "Mesh convergence", "convergence_profiles.png", out);
    md.paragraph(
        "The soil's mean stress p at t = 0.04 s on the 1, 0.5 and 0.25 cm levels (colours up to each map's 98th "
        "percentile of p). Stripes and layers a few cells apart, finer as h halves, are the pattern that "
        "docs/verification.md#mesh-convergence describes (the push of `cpt_mohr_coulomb.json` shows them more plainly; "
        "with a dilatant flow, ψ = 20°, the same push has a smooth pressure bulb).");
    for (std::size_t i = 1; i < n; ++i)
      include_run_figure(results, i, "plots/mean_stress_t0.040.png",
                         "convergence_p_" + fixed(100 * kReferenceCells_m[i], 2) + "cm.png",
                         "Mean stress p at t = 0.04 s, min cell " + fixed(100 * kReferenceCells_m[i], 2) + " cm", out);
  };
  return study;
}

}  // namespace ffp
