/// Mesh convergence of the reference FFP run: 2 ms peak deceleration, final
/// penetration and the 0–40 ms impulse against wall time, with the error against
/// a Richardson extrapolation of the three finest meshes (or the finest, if that
/// fails); the run's health per level; pure FLIP as a control, and the tip at four
/// phases between two node rows (the staircase of the non-conforming cone); the
/// levels' penetration at fixed times, to show where in the drop they part.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

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
// half a cell off, the tip midway between two rows. The four phases sample the staircase the moving
// mesh freezes.
constexpr std::array<double, 3> kTipPhases = {0.25, 0.5, 0.75};
// Where half a cell off sits among a level's phases (0 first, then kTipPhases).
constexpr std::size_t kHalfCellPhase = 2;
static_assert(kTipPhases[kHalfCellPhase - 1] == 0.5);
// Times at which the levels' penetrations are compared: the fast first half of the drop, where the
// cone is embedded and the peak comes, and the slow second half, where the sand bears the body.
constexpr std::array<double, 7> kCompareTimes_s = {0.01, 0.02, 0.03, 0.04, 0.06, 0.08, 0.15};

/// Where each run sits in the study's results, recorded as the runs are asked for.
struct ConvergenceRuns {
  std::vector<std::size_t> level;  ///< each level's own run (tip on a row), in kReferenceCells_m's order
  struct Controls {
    std::size_t pure_flip;
    std::array<std::size_t, kTipPhases.size()> tip_phase;  ///< in kTipPhases' order
  };
  std::vector<Controls> controls;  ///< the first kControlLevels levels'
};

/// A level's figures, from its own run.
struct Level {
  double cell_m, peak_g, depth_m, wall_s, impulse_N_s;
};

/// The reference of each quantity: Richardson of the three finest levels, or the finest.
struct References {
  Extrapolation peak, depth, impulse;
};

/// A control level's final penetrations and 2 ms peaks at its tip phases (0 first: the
/// level's own run, then kTipPhases), their means and ranges.
struct Phases {
  std::vector<double> depth_m, peak_g;
  double depth_mean = 0, peak_mean = 0, depth_range = 0, peak_range = 0;
};

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

double last(const CsvData& h, const std::string& column) {
  return h.has(column) && !h.column(column).empty() ? h.column(column).back() : std::nan("");
}

double relative_error(double value, const Extrapolation& reference) {
  return std::abs(value - reference.value) / std::abs(reference.value);
}

std::string in_cm(double length_m) { return fixed(100 * length_m, 2); }

/// The runs: each level, then per control level pure FLIP and the tip phases.
std::vector<RunRequest> convergence_runs(const std::filesystem::path& scenes_dir, ConvergenceRuns& where) {
  std::vector<RunRequest> runs;
  auto add = [&](const std::string& label, std::vector<std::string> overrides, double h) {
    runs.push_back(scene_run(scenes_dir, "ffp_reference.json", label, std::move(overrides)));
    runs.back().expected_wall_s = level_wall_s(h);  // a control as its level's own run
    return runs.size() - 1;
  };
  for (double h : kReferenceCells_m)
    where.level.push_back(add("min cell " + in_cm(h) + " cm", {"mesh.min_cell_m=" + fixed(h, 4), kPicPerSecond}, h));
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    const double h = kReferenceCells_m[l];
    const std::string mesh = "mesh.min_cell_m=" + fixed(h, 4);
    ConvergenceRuns::Controls controls{};
    controls.pure_flip =
        add("pure FLIP, " + in_cm(h) + " cm", {mesh, "solver.flip_fraction=1", "output.field_times_s=[]"}, h);
    for (std::size_t k = 0; k < kTipPhases.size(); ++k) {
      const double phase = kTipPhases[k];
      // The 0.5 phase is labelled in words, as the text names it.
      const std::string label = phase == 0.5 ? "tip half a cell off, " : "tip " + fixed(phase, 2) + " cell off, ";
      controls.tip_phase[k] =
          add(label + in_cm(h) + " cm",
              {mesh, "mesh.tip_offset_cells=" + fixed(phase, 2), kPicPerSecond, "output.field_times_s=[]"}, h);
    }
    where.controls.push_back(controls);
  }
  return runs;
}

std::vector<Level> level_figures(const StudyResults& results, const ConvergenceRuns& where) {
  std::vector<Level> levels;
  for (std::size_t i = 0; i < kReferenceCells_m.size(); ++i) {
    const std::size_t run = where.level[i];
    levels.push_back({kReferenceCells_m[i], figure(results, run, "peak_deceleration_2ms_g"),
                      figure(results, run, "final_penetration_m"), figure(results, run, "wall_time_s"),
                      value_at(results.history(run), "impulse_N_s", 0.04)});
  }
  return levels;
}

References references(const std::vector<Level>& levels) {
  const std::size_t n = levels.size();
  auto three_finest = [&](double Level::*q) {
    return richardson(levels[n - 3].*q, levels[n - 2].*q, levels[n - 1].*q);
  };
  return {three_finest(&Level::peak_g), three_finest(&Level::depth_m), three_finest(&Level::impulse_N_s)};
}

void write_introduction(Markdown& md) {
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
}

void write_level_table(Markdown& md, const StudyResults& results, const ConvergenceRuns& where,
                       const std::vector<Level>& levels, const References& refs) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const Level& l = levels[i];
    const std::size_t run = where.level[i];
    rows.push_back({in_cm(l.cell_m), fixed(figure(results, run, "particles"), 0),
                    fixed(figure(results, run, "steps"), 0), fixed(l.wall_s, 1), fixed(l.peak_g, 2),
                    fixed(100 * relative_error(l.peak_g, refs.peak), 1), in_cm(l.depth_m),
                    fixed(100 * relative_error(l.depth_m, refs.depth), 1), fixed(l.impulse_N_s, 2),
                    fixed(100 * relative_error(l.impulse_N_s, refs.impulse), 1)});
  }
  md.table({"min cell [cm]", "particles", "steps", "wall time [s]", "2 ms peak [g]", "error [%]",
            "final penetration [cm]", "error [%]", "impulse 0–40 ms [N s]", "error [%]"},
           rows);
}

// What each level's run did to the soil: the contact's intrusion (it should
// shrink with h), the largest V/V0, the smallest step, and the soil's kinetic
// energy at the end (a level whose Δt collapses or whose soil gains energy with
// no work done on it is not a solution: flag it).
void write_health_table(Markdown& md, const StudyResults& results, const ConvergenceRuns& where) {
  std::vector<std::vector<std::string>> health;
  for (std::size_t i = 0; i < kReferenceCells_m.size(); ++i) {
    const std::size_t run = where.level[i];
    if (results.summary(run).empty()) continue;
    const double dt0 = figure(results, run, "dt_s"), dt_min = figure(results, run, "dt_min_s");
    const bool collapsed = std::isfinite(dt0) && std::isfinite(dt_min) && dt_min < 0.01 * dt0;
    health.push_back({in_cm(kReferenceCells_m[i]), fixed(1000 * figure(results, run, "max_soil_intrusion_m"), 2),
                      fixed(figure(results, run, "max_soil_intrusion_cells"), 2),
                      fixed(figure(results, run, "max_volume_ratio"), 2),
                      fixed(figure(results, run, "inflated_particles_max"), 0), scientific(dt_min),
                      scientific(last(results.history(run), "soil_kinetic_energy_J")),
                      collapsed ? "Δt collapsed (< 1 % of the first step): not used" : "ok"});
  }
  md.table({"min cell [cm]", "max intrusion [mm]", "[cells]", "max V/V0", "particles at V/V0 ≥ 2", "Δt_min [s]",
            "soil kinetic energy at 0.15 s [J]", "level"},
           health);
}

// The controls: pure FLIP (no PIC share: a level whose soil then gains energy with no work
// done on it has an unstable step).
void write_pure_flip_table(Markdown& md, const StudyResults& results, const ConvergenceRuns& where,
                           const std::vector<Level>& levels) {
  std::vector<std::vector<std::string>> controls;
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    const std::size_t flip = where.controls[l].pure_flip;
    controls.push_back({in_cm(levels[l].cell_m), in_cm(levels[l].depth_m),
                        in_cm(figure(results, flip, "final_penetration_m")),
                        scientific(last(results.history(where.level[l]), "soil_kinetic_energy_J")),
                        scientific(last(results.history(flip), "soil_kinetic_energy_J"))});
  }
  md.table({"min cell [cm]", "final penetration [cm]", "pure FLIP [cm]", "soil KE at 0.15 s [J]", "pure FLIP [J]"},
           controls);
}

std::vector<Phases> tip_phases(const StudyResults& results, const ConvergenceRuns& where,
                               const std::vector<Level>& levels) {
  std::vector<Phases> phases(kControlLevels);
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    Phases& p = phases[l];
    p.depth_m = {levels[l].depth_m};  // phase 0 is the level's own run
    p.peak_g = {levels[l].peak_g};
    for (const std::size_t run : where.controls[l].tip_phase) {
      p.depth_m.push_back(figure(results, run, "final_penetration_m"));
      p.peak_g.push_back(figure(results, run, "peak_deceleration_2ms_g"));
    }
    p.depth_mean = phase_mean(p.depth_m);
    p.peak_mean = phase_mean(p.peak_g);
    p.depth_range = phase_spread(p.depth_m);
    p.peak_range = phase_spread(p.peak_g);
  }
  return phases;
}

void write_phase_table(Markdown& md, const std::vector<Phases>& phases) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    const Phases& p = phases[l];
    std::vector<std::string> row{in_cm(kReferenceCells_m[l])};
    for (double x : p.depth_m) row.push_back(in_cm(x));
    row.push_back(in_cm(p.depth_mean));
    row.push_back(fixed(100 * p.depth_range / p.depth_mean, 1));
    row.push_back(fixed(100 * (p.depth_m[kHalfCellPhase] - p.depth_m[0]) / p.depth_m[0], 1));
    for (double x : p.peak_g) row.push_back(fixed(x, 2));
    row.push_back(fixed(p.peak_mean, 2));
    row.push_back(fixed(100 * p.peak_range / p.peak_mean, 1));
    rows.push_back(row);
  }
  md.paragraph(
      "The tip at four phases between two node rows (mesh.tip_offset_cells 0, 0.25, 0.5, 0.75; 0 is the "
      "level's run above). The moving mesh freezes the cone's staircase for the whole run, so each phase is "
      "one sample of it; the range over the phases (as % of their mean) is the scatter any one run carries, "
      "and the bias is the run half a cell off against the run on a row.");
  md.table({"min cell [cm]", "z_f at 0 [cm]", "0.25", "0.5", "0.75", "mean [cm]", "range [%]", "bias at 0.5 [%]",
            "2 ms peak at 0 [g]", "0.25", "0.5", "0.75", "mean [g]", "range [%]"},
           rows);
}

// Every phase as a point at its level's cell size, the phase means as a line, and the tip-on-a-row
// series of every level.
void write_phase_figure(StudyOutput& out, const std::vector<Level>& levels, const std::vector<Phases>& phases) {
  Series depth_phases{.title = "final penetration, each phase", .style = "points"},
      peak_phases{.title = "2 ms peak, each phase", .style = "points"};
  Series depth_mean{.title = "mean of the phases", .style = "linespoints"},
      peak_mean{.title = "mean of the phases", .style = "linespoints"};
  Series depth_row{.title = "tip on a row, every level", .style = "lines dashtype 2"},
      peak_row{.title = "tip on a row, every level", .style = "lines dashtype 2"};
  for (std::size_t l = 0; l < kControlLevels; ++l) {
    const double cell_cm = 100 * kReferenceCells_m[l];
    for (std::size_t k = 0; k < phases[l].depth_m.size(); ++k) {
      depth_phases.x.push_back(cell_cm);
      depth_phases.y.push_back(100 * phases[l].depth_m[k]);
      peak_phases.x.push_back(cell_cm);
      peak_phases.y.push_back(phases[l].peak_g[k]);
    }
    depth_mean.x.push_back(cell_cm);
    depth_mean.y.push_back(100 * phases[l].depth_mean);
    peak_mean.x.push_back(cell_cm);
    peak_mean.y.push_back(phases[l].peak_mean);
  }
  for (const Level& l : levels) {
    depth_row.x.push_back(100 * l.cell_m);
    depth_row.y.push_back(100 * l.depth_m);
    peak_row.x.push_back(100 * l.cell_m);
    peak_row.y.push_back(l.peak_g);
  }
  auto against_cell = [](std::string title, std::string y_label, std::vector<Series> series, std::string key) {
    return Plot{.title = std::move(title),
                .x_label = "min cell (cm)",
                .y_label = std::move(y_label),
                .series = std::move(series),
                .log_x = true,
                .key_position = std::move(key)};
  };
  const Plot depth_plot = against_cell("Final penetration against the cell size, four tip phases per level",
                                       "final penetration (cm)", {depth_phases, depth_mean, depth_row}, "top right");
  const Plot peak_plot = against_cell("2 ms peak deceleration against the cell size", "2 ms peak (g)",
                                      {peak_phases, peak_mean, peak_row}, "top left");
  if (write_png_stack({depth_plot, peak_plot}, out.figures_dir / "convergence_tip_phases.png"))
    out.document.figure(out.figures_relative + "/convergence_tip_phases.png",
                        "Each tip phase's final penetration and 2 ms peak at its level (points), their means (line) "
                        "and the tip-on-a-row series of every level (dashed).");
}

// A step between the two finest levels that is smaller than the phase scatter of the coarser one
// cannot show convergence: one run per level is one sample of that scatter.
void write_phase_reading(Markdown& md, const std::vector<Level>& levels, const std::vector<Phases>& phases) {
  auto steps = [&](double Phases::*mean, double scale) {
    std::string text;
    for (std::size_t i = 1; i < phases.size(); ++i)
      text += (i > 1 ? ", " : "") + fixed(scale * (phases[i].*mean - phases[i - 1].*mean), 2);
    return text;
  };
  auto means = [&](double Phases::*mean, double scale) {
    return fixed(scale * phases[0].*mean, 2) + " / " + fixed(scale * phases[1].*mean, 2) + " / " +
           fixed(scale * phases[2].*mean, 2);
  };
  const std::size_t n = levels.size();
  const double last_depth_step = levels[n - 1].depth_m - levels[n - 2].depth_m;
  const double last_peak_step = levels[n - 1].peak_g - levels[n - 2].peak_g;
  const Phases& finest = phases.back();  // the finest level with phases (0.5 cm)
  const bool depth_within = std::abs(last_depth_step) < finest.depth_range;
  const bool peak_within = std::abs(last_peak_step) < finest.peak_range;
  auto within = [](bool is_within) {
    return is_within ? "within that level's phase range" : "larger than that level's phase range";
  };
  md.paragraph("Means over the four phases at 2, 1 and 0.5 cm: final penetration " + means(&Phases::depth_mean, 100.0) +
               " cm (steps " + steps(&Phases::depth_mean, 100.0) + " cm), 2 ms peak " + means(&Phases::peak_mean, 1.0) +
               " g (steps " + steps(&Phases::peak_mean, 1.0) + " g). The step from 0.5 to 0.25 cm, " +
               fixed(100 * last_depth_step, 2) + " cm in the final penetration and " + fixed(last_peak_step, 2) +
               " g in the peak, is " + within(depth_within) + " at 0.5 cm (" + fixed(100 * finest.depth_range, 2) +
               " cm) and " + within(peak_within) + " (" + fixed(finest.peak_range, 2) + " g)" +
               (depth_within || peak_within
                    ? ", so the Richardson figures below rest on single samples of the staircase."
                    : "."));
}

void write_references(Markdown& md, const References& refs) {
  auto describe = [](const char* what, const Extrapolation& e, double scale, const char* unit) {
    return std::string(what) + ": reference " + fixed(scale * e.value, 2) + " " + unit +
           (std::isfinite(e.order) ? " (Richardson, observed order " + fixed(e.order, 2) + ")"
                                   : " (finest mesh: the sequence is not in the asymptotic range)");
  };
  md.paragraph(describe("2 ms peak deceleration", refs.peak, 1.0, "g") + "; " +
               describe("final penetration", refs.depth, 100.0, "cm") + "; " +
               describe("impulse over 0–40 ms", refs.impulse, 1.0, "N s") + ".");
}

/// The levels' penetrations (tip on a row) at time t, and the 0.5 cm level's range over its tip
/// phases then (NaN where a run lacks t).
class PenetrationAt {
 public:
  PenetrationAt(const StudyResults& results, const ConvergenceRuns& where) : results_(results), where_(where) {}
  std::vector<double> levels(double t) const {
    std::vector<double> z;
    for (const std::size_t run : where_.level) z.push_back(at(run, t));
    return z;
  }
  double phase_range(double t) const {
    const std::size_t finest = kControlLevels - 1;  // the finest level with phases (0.5 cm)
    std::vector<double> z{at(where_.level[finest], t)};
    for (const std::size_t run : where_.controls[finest].tip_phase) z.push_back(at(run, t));
    return std::ranges::all_of(z, [](double x) { return std::isfinite(x); }) ? phase_spread(z) : std::nan("");
  }

 private:
  double at(std::size_t run, double t) const { return value_at(results_.history(run), "penetration_m", t); }
  const StudyResults& results_;
  const ConvergenceRuns& where_;
};

/// How far, from the first compare time, the steps between levels shrink at every halving
/// (`shrinking` times) and, of those, the last step also exceeds the phase range (`resolved`).
struct TimelineReading {
  std::size_t shrinking = 0, resolved = 0;
};

std::string reading_text(const TimelineReading& r) {
  auto ms = [](std::size_t k) { return fixed(1000 * kCompareTimes_s[k], 0) + " ms"; };
  std::string reading = r.shrinking == 0 ? " The steps do not shrink at any of these times."
                        : r.shrinking == kCompareTimes_s.size()
                            ? " The steps shrink at every one of these times."
                            : " The steps shrink at each halving up to " + ms(r.shrinking - 1) + " and no longer at " +
                                  ms(r.shrinking) + ".";
  if (r.resolved > 0 && r.resolved < r.shrinking)
    reading += " Up to " + ms(r.resolved - 1) +
               " the last step is larger than the 0.5 cm level's phase range, so the shrinking is measured; "
               "from " +
               ms(r.resolved) +
               " on it lies within that range, and one run per level cannot show whether the steps shrink "
               "there.";
  else if (r.resolved == 0 && r.shrinking > 0)
    reading += " The last step lies within the 0.5 cm level's phase range from the first of these times on.";
  return reading;
}

// Where in the drop the levels part: the penetration of every level at fixed times, the steps
// between levels, the observed order from the three finest, and the 0.5 cm level's phase range
// at the same time (a step below it is not evidence either way).
void write_timeline_table(Markdown& md, const PenetrationAt& penetration) {
  const std::size_t n = kReferenceCells_m.size();
  std::vector<std::vector<std::string>> timeline;
  TimelineReading reading;
  bool still_shrinking = true, still_resolved = true;
  for (double t : kCompareTimes_s) {
    const std::vector<double> z = penetration.levels(t);
    std::vector<std::string> row{fixed(1000 * t, 0)};
    for (double x : z) row.push_back(in_cm(x));
    bool shrinks = true;
    for (std::size_t i = 1; i < n; ++i) {
      row.push_back(in_cm(z[i] - z[i - 1]));
      if (i > 1) shrinks = shrinks && std::abs(z[i] - z[i - 1]) < std::abs(z[i - 1] - z[i - 2]);
    }
    const Extrapolation e = richardson(z[n - 3], z[n - 2], z[n - 1]);
    row.push_back(std::isfinite(e.order) ? fixed(e.order, 2) : "–");
    const double range = penetration.phase_range(t);
    row.push_back(in_cm(range));
    timeline.push_back(row);
    still_shrinking = still_shrinking && shrinks;
    still_resolved = still_resolved && still_shrinking && std::abs(z[n - 1] - z[n - 2]) > range;
    if (still_shrinking) ++reading.shrinking;
    if (still_resolved) ++reading.resolved;
  }
  md.paragraph(
      "Where in the drop the levels part: each level's penetration (tip on a row) at fixed times, the steps "
      "between successive levels, the observed order of the three finest (– where the steps do not shrink "
      "monotonically or the order lies outside 0.3–4) and the 0.5 cm level's range over its four tip phases at "
      "that time." +
      reading_text(reading));
  std::vector<std::string> header{"t [ms]"};
  for (double h : kReferenceCells_m) header.push_back("z at " + in_cm(h) + " cm [cm]");
  for (std::size_t i = 1; i < n; ++i)
    header.push_back("step " + in_cm(kReferenceCells_m[i - 1]) + "→" + in_cm(kReferenceCells_m[i]));
  header.push_back("order");
  header.push_back("0.5 cm phase range [cm]");
  md.table(header, timeline);
}

// The same on a 2 ms raster as a figure: each halving's step against time.
void write_timeline_figure(StudyOutput& out, const PenetrationAt& penetration) {
  const std::size_t n = kReferenceCells_m.size();
  std::vector<Series> halvings;
  for (std::size_t i = 1; i < n; ++i)
    halvings.push_back(
        {.title = in_cm(kReferenceCells_m[i - 1]) + " → " + in_cm(kReferenceCells_m[i]) + " cm", .style = "lines"});
  Series range{.title = "0.5 cm level's phase range", .style = "lines dashtype 2"};
  for (double t = 0.002; t <= kCompareTimes_s.back() + 1e-9; t += 0.002) {
    const std::vector<double> z = penetration.levels(t);
    for (std::size_t i = 1; i < n; ++i) {
      const double step = z[i] - z[i - 1];
      if (!std::isfinite(step)) continue;
      halvings[i - 1].x.push_back(1000 * t);
      halvings[i - 1].y.push_back(100 * step);
    }
    const double r = penetration.phase_range(t);
    if (std::isfinite(r)) {
      range.x.push_back(1000 * t);
      range.y.push_back(100 * r);
    }
  }
  halvings.push_back(range);
  const Plot step_plot{.title = "Penetration step at each halving of the cell against time",
                       .x_label = "time (ms)",
                       .y_label = "penetration on the finer mesh − on the coarser (cm)",
                       .series = halvings,
                       .key_position = "top left"};
  if (write_png(step_plot, out.figures_dir / "convergence_steps_in_time.png"))
    out.document.figure(out.figures_relative + "/convergence_steps_in_time.png",
                        "The change of penetration at each halving of the cell, against time, and the 0.5 cm "
                        "level's range over its tip phases.");
}

void write_error_figure(StudyOutput& out, const std::vector<Level>& levels, const References& refs) {
  Series peak_error{.title = "peak deceleration", .style = "linespoints"},
      depth_error{.title = "final penetration", .style = "linespoints"};
  for (const Level& l : levels) {
    const double e_peak = relative_error(l.peak_g, refs.peak), e_depth = relative_error(l.depth_m, refs.depth);
    if (std::isfinite(l.wall_s) && e_peak > 0) {
      peak_error.x.push_back(l.wall_s);
      peak_error.y.push_back(e_peak);
    }
    if (std::isfinite(l.wall_s) && e_depth > 0) {
      depth_error.x.push_back(l.wall_s);
      depth_error.y.push_back(e_depth);
    }
  }
  const Plot p{.title = "Error against wall time (2 cores)",
               .x_label = "wall time of the run (s)",
               .y_label = "relative error",
               .series = {peak_error, depth_error},
               .log_x = true,
               .log_y = true,
               .key_position = "top right"};
  if (write_png(p, out.figures_dir / "convergence_error_vs_wall_time.png"))
    out.document.figure(out.figures_relative + "/convergence_error_vs_wall_time.png",
                        "Relative error of peak deceleration and final penetration against wall time, one point per "
                        "mesh.");
}

void write_field_figures(const StudyResults& results, const ConvergenceRuns& where, StudyOutput& out) {
  std::vector<LabelledRun> runs;
  for (std::size_t i = 0; i < kReferenceCells_m.size(); ++i)
    runs.push_back({where.level[i], "min cell " + in_cm(kReferenceCells_m[i]) + " cm"});
  ffp_depth_profiles_figure(results, runs, "Mesh convergence", "convergence_profiles.png", out);
  out.document.paragraph(
      "The soil's mean stress p at t = 0.04 s on the 1, 0.5 and 0.25 cm levels (colours up to each map's 98th "
      "percentile of p). Stripes and layers a few cells apart, finer as h halves, are the pattern that "
      "docs/verification.md#mesh-convergence describes (the push of `cpt_mohr_coulomb.json` shows them more plainly; "
      "with a dilatant flow, ψ = 20°, the same push has a smooth pressure bulb).");
  for (std::size_t i = 1; i < kReferenceCells_m.size(); ++i)
    include_run_figure(results, where.level[i], "plots/mean_stress_t0.040.png",
                       "convergence_p_" + in_cm(kReferenceCells_m[i]) + "cm.png",
                       "Mean stress p at t = 0.04 s, min cell " + in_cm(kReferenceCells_m[i]) + " cm", out);
}

}  // namespace

Study ffp_convergence_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Mesh convergence of the reference run: error against run time";
  ConvergenceRuns where;
  study.runs = convergence_runs(scenes_dir, where);
  study.write = [where](const StudyResults& results, StudyOutput& out) {
    Markdown& md = out.document;
    write_introduction(md);
    const std::vector<Level> levels = level_figures(results, where);
    const References refs = references(levels);
    write_level_table(md, results, where, levels, refs);
    write_health_table(md, results, where);
    write_pure_flip_table(md, results, where, levels);
    const std::vector<Phases> phases = tip_phases(results, where, levels);
    write_phase_table(md, phases);
    write_phase_figure(out, levels, phases);
    write_phase_reading(md, levels, phases);
    write_references(md, refs);
    const PenetrationAt penetration(results, where);
    write_timeline_table(md, penetration);
    write_timeline_figure(out, penetration);
    write_error_figure(out, levels, refs);
    write_field_figures(results, where, out);
  };
  return study;
}

}  // namespace ffp
