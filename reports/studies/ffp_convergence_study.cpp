/// Mesh convergence of the reference FFP run: peak deceleration and final
/// penetration against wall time, with the error against a Richardson
/// extrapolation of the three finest meshes (or the finest, if that fails).
#include <cmath>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

const std::vector<double> kMinCells_m = {0.02, 0.01, 0.005, 0.0025};

}  // namespace

Study ffp_convergence_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Mesh convergence of the reference run: error against run time";
  for (double h : kMinCells_m) {
    study.runs.push_back(scene_run(scenes_dir, "ffp_reference.json", "min cell " + fixed(100 * h, 2) + " cm",
                                   {"mesh.min_cell_m=" + fixed(h, 4)}));
    // Particles grow as h⁻² and steps as h⁻¹; 1 cm takes about 5 s on one core.
    study.runs.back().expected_wall_s = 5.0 * std::pow(0.01 / h, 3);
  }
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    md.paragraph(
        "The reference scene with every mesh size following the minimum cell (2, 1, 0.5 and 0.25 cm). The "
        "reference value of each quantity is the Richardson extrapolation of the three finest meshes when they "
        "converge monotonically with an order between 0.3 and 4, otherwise the finest mesh's value.");
    const std::size_t n = results.size();
    std::vector<double> peak(n), depth(n), wall(n);
    for (std::size_t i = 0; i < n; ++i) {
      peak[i] = figure(results, i, "peak_deceleration_g");
      depth[i] = figure(results, i, "final_penetration_m");
      wall[i] = figure(results, i, "wall_time_s");
    }
    const Extrapolation peak_ref = richardson(peak[n - 3], peak[n - 2], peak[n - 1]);
    const Extrapolation depth_ref = richardson(depth[n - 3], depth[n - 2], depth[n - 1]);
    std::vector<std::vector<std::string>> rows;
    Series peak_error{{}, {}, "peak deceleration", "linespoints"}, depth_error{{}, {}, "final penetration", "linespoints"};
    for (std::size_t i = 0; i < n; ++i) {
      const double e_peak = std::abs(peak[i] - peak_ref.value) / std::abs(peak_ref.value);
      const double e_depth = std::abs(depth[i] - depth_ref.value) / std::abs(depth_ref.value);
      rows.push_back({fixed(100 * kMinCells_m[i], 2), fixed(figure(results, i, "particles"), 0),
                      fixed(figure(results, i, "steps"), 0), fixed(wall[i], 1), fixed(peak[i], 2),
                      fixed(100 * e_peak, 1), fixed(100 * depth[i], 2), fixed(100 * e_depth, 1)});
      if (std::isfinite(wall[i]) && e_peak > 0) {
        peak_error.x.push_back(wall[i]);
        peak_error.y.push_back(e_peak);
      }
      if (std::isfinite(wall[i]) && e_depth > 0) {
        depth_error.x.push_back(wall[i]);
        depth_error.y.push_back(e_depth);
      }
    }
    md.table({"min cell [cm]", "particles", "steps", "wall time [s]", "peak [g]", "error [%]", "final penetration [cm]",
              "error [%]"},
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
      health.push_back({fixed(100 * kMinCells_m[i], 2), fixed(1000 * figure(results, i, "max_soil_intrusion_m"), 2),
                        fixed(figure(results, i, "max_soil_intrusion_cells"), 2),
                        fixed(figure(results, i, "max_volume_ratio"), 2),
                        fixed(figure(results, i, "inflated_particles_max"), 0), scientific(dt_min),
                        collapsed ? "Δt collapsed (< 1 % of the first step): not used" : "ok"});
    }
    md.table({"min cell [cm]", "max intrusion [mm]", "[cells]", "max V/V0", "particles at V/V0 ≥ 2", "Δt_min [s]",
              "level"},
             health);
    auto describe = [](const char* what, const Extrapolation& e, double scale, const char* unit) {
      return std::string(what) + ": reference " + fixed(scale * e.value, 2) + " " + unit +
             (std::isfinite(e.order) ? " (Richardson, observed order " + fixed(e.order, 2) + ")"
                                     : " (finest mesh: the sequence is not in the asymptotic range)");
    };
    md.paragraph(describe("Peak deceleration", peak_ref, 1.0, "g") + "; " +
                 describe("final penetration", depth_ref, 100.0, "cm") + ".");
    Plot p{"Error against wall time (2 cores)", "wall time of the run (s)", "relative error", {peak_error, depth_error},
           true, true, false, "top right"};
    if (write_png(p, out.figures_dir / "convergence_error_vs_wall_time.png"))
      md.figure(out.figures_relative + "/convergence_error_vs_wall_time.png",
                "Relative error of peak deceleration and final penetration against wall time, one point per mesh.");
    std::vector<LabelledRun> runs;
    for (std::size_t i = 0; i < n; ++i) runs.push_back({i, "min cell " + fixed(100 * kMinCells_m[i], 2) + " cm"});
    ffp_depth_profiles_figure(results, runs, "Mesh convergence", "convergence_profiles.png", out);
  };
  return study;
}

}  // namespace ffp
