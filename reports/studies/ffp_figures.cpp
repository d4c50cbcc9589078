#include "reports/studies/ffp_figures.hpp"

#include <cmath>
#include <limits>

#include "reports/markdown.hpp"

namespace ffp {

namespace {

Series column_series(const CsvData& history, const std::string& x, const std::string& y, const std::string& title,
                     double y_scale = 1.0) {
  Series s;
  s.title = title;
  if (!history.has(x) || !history.has(y)) return s;
  s.x = history.column(x);
  s.y = history.column(y);
  for (auto& v : s.y) v *= y_scale;
  return s;
}

void add_figure(const std::vector<Plot>& panels, const std::string& png_name, const std::string& caption,
                StudyOutput& out) {
  if (write_png_stack(panels, out.figures_dir / png_name))
    out.document.figure(out.figures_relative + "/" + png_name, caption);
  else
    out.document.paragraph("*(Figure not drawn: gnuplot missing — " + caption + ")*");
}

}  // namespace

std::vector<std::string> paper_softening_sand(const std::string& eta) {
  return {"material.model=ssmc", "material.phi_peak_deg=60.0", "material.phi_residual_deg=32.0",
          "material.psi_peak_deg=5.00", "material.eta=" + eta};
}

double figure(const StudyResults& results, std::size_t run, const std::string& key) {
  const auto s = results.summary(run);
  if (!s.contains(key) || !s[key].is_number()) return std::numeric_limits<double>::quiet_NaN();
  return s[key].get<double>();
}

void ffp_depth_profiles_figure(const StudyResults& results, const std::vector<LabelledRun>& runs,
                               const std::string& title, const std::string& png_name, StudyOutput& out) {
  Plot depth{title + ": penetration", "time (s)", "penetration (cm)", {}, false, false, true, "bottom right"};
  Plot velocity{"velocity profile", "penetration (cm)", "velocity (m/s)", {}, false, false, false, "top right"};
  Plot deceleration{
      "deceleration profile", "penetration (cm)", "deceleration (g)", {}, false, false, false, "top left"};
  for (const auto& r : runs) {
    const CsvData h = results.history(r.index);
    Series d = column_series(h, "time_s", "penetration_m", r.label, 100.0);
    Series v = column_series(h, "penetration_m", "velocity_m_s", r.label);
    Series a = column_series(h, "penetration_m", "deceleration_g", r.label);
    for (auto& x : v.x) x *= 100.0;
    for (auto& x : a.x) x *= 100.0;
    depth.series.push_back(d);
    velocity.series.push_back(v);
    deceleration.series.push_back(a);
  }
  add_figure({depth, velocity, deceleration}, png_name,
             title +
                 " (penetration against time; velocity and deceleration against penetration, as the paper's "
                 "Figs. 8, 10–12).",
             out);
}

void ffp_time_histories_figure(const StudyResults& results, const std::vector<LabelledRun>& runs,
                               const std::string& title, const std::string& png_name, StudyOutput& out) {
  Plot depth{title + ": penetration", "time (s)", "penetration (cm)", {}, false, false, true, "bottom right"};
  Plot velocity{"velocity", "time (s)", "velocity (m/s)", {}, false, false, false, "top right"};
  Plot deceleration{"deceleration", "time (s)", "deceleration (g)", {}, false, false, false, "top right"};
  Plot reaction{
      "reaction of the soil on the penetrometer", "time (s)", "reaction (kN)", {}, false, false, false, "top right"};
  for (const auto& r : runs) {
    const CsvData h = results.history(r.index);
    depth.series.push_back(column_series(h, "time_s", "penetration_m", r.label, 100.0));
    velocity.series.push_back(column_series(h, "time_s", "velocity_m_s", r.label));
    deceleration.series.push_back(column_series(h, "time_s", "deceleration_g", r.label));
    reaction.series.push_back(column_series(h, "time_s", "reaction_N", r.label, 1e-3));
  }
  add_figure({depth, velocity, deceleration, reaction}, png_name, title + " (as the paper's Fig. 7).", out);
}

std::vector<std::string> ffp_table_header() {
  return {"run",
          "peak deceleration, 0.2 ms rows [g]",
          "2 ms mean peak [g]",
          "time of peak [s]",
          "depth of peak [cm]",
          "max penetration [cm]",
          "final penetration [cm]",
          "rebound [cm]",
          "steps",
          "wall time [s]"};
}

std::vector<std::vector<std::string>> ffp_table_rows(const StudyResults& results,
                                                     const std::vector<LabelledRun>& runs) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : runs) {
    if (!results.ok(r.index)) {
      rows.push_back({r.label, "FAILED: " + results.outcome(r.index).error, "", "", "", "", "", "", "", ""});
      continue;
    }
    rows.push_back({r.label, fixed(figure(results, r.index, "peak_deceleration_g"), 1),
                    fixed(figure(results, r.index, "peak_deceleration_2ms_g"), 1),
                    fixed(figure(results, r.index, "time_of_peak_s"), 4),
                    fixed(100 * figure(results, r.index, "depth_of_peak_m"), 1),
                    fixed(100 * figure(results, r.index, "max_penetration_m"), 1),
                    fixed(100 * figure(results, r.index, "final_penetration_m"), 1),
                    fixed(100 * figure(results, r.index, "rebound_m"), 2), fixed(figure(results, r.index, "steps"), 0),
                    fixed(figure(results, r.index, "wall_time_s"), 1)});
  }
  return rows;
}

}  // namespace ffp
