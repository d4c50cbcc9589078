/// Mesh convergence of the softening FFP run (the paper's section 5.5 SSMC,
/// φ'_p = 60°, η = 8): with η fixed, and with η scaled with the mesh by the
/// paper's mesh-aware calibration (section 4.2: η fitted by dissipated work on
/// a specimen meshed like the FFP), η(h) = 8 · η_cal(h) / η_cal(1 cm).
#include <cmath>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

const std::vector<double> kSofteningCells_m = {0.02, 0.01, 0.005, 0.0025};
// The calibrations exist for these cells (calibration_dr15_mpm_*.json); a 0.25 cm specimen takes hours.
const std::vector<std::pair<double, const char*>> kCalibrations = {{0.02, "calibration_dr15_mpm_2cm.json"},
                                                                   {0.01, "calibration_dr15_mpm_1cm.json"},
                                                                   {0.005, "calibration_dr15_mpm_05cm.json"}};
constexpr double kPaperEta = 8.0;  // at the FFP's 1 cm cells

std::vector<std::string> softening(double h, double eta) {
  std::vector<std::string> overrides = paper_softening_sand(fixed(eta, 2));
  overrides.push_back("mesh.min_cell_m=" + fixed(h, 4));
  // No particle fields, except on the scene's own 1 cm cells with η = 8: that run is then the
  // paper-comparison and peak-friction studies' φ'_p = 60° run (the same key), made once.
  if (!(h == 0.01 && eta == kPaperEta)) overrides.push_back("output.field_times_s=[]");
  return overrides;
}

std::string cm_label(double h) { return fixed(100 * h, 2) + " cm"; }

}  // namespace

Study ffp_softening_convergence_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Mesh convergence of the softening run (SSMC φ'_p = 60°)";
  // Its 0.25 cm level alone is 230 s of one core, a third of the main job's runs: the study runs
  // when asked (`ffp report --only "softening run"`); the reference's own series stays in.
  study.outside_main_job = true;
  for (double h : kSofteningCells_m) {
    study.runs.push_back(
        scene_run(scenes_dir, "ffp_reference.json", "SSMC η = 8, " + cm_label(h), softening(h, kPaperEta)));
    study.runs.back().expected_wall_s = 5.0 * std::pow(0.01 / h, 3);
  }
  // The same runs as the mesh-calibration study's: the cache shares them.
  for (const auto& [h, scene] : kCalibrations)
    study.runs.push_back(scene_run(scenes_dir, scene, "calibration " + cm_label(h)));
  study.runs[4].expected_wall_s = 8;  // as in the mesh-calibration study
  study.runs[5].expected_wall_s = 26;
  study.runs[6].expected_wall_s = 160;
  study.follow_up = [scenes_dir](const StudyResults& first) -> std::vector<RunRequest> {
    const double eta_1cm = figure(first, 5, "eta");
    std::vector<RunRequest> runs;
    for (std::size_t c : {std::size_t{0}, std::size_t{2}}) {  // 1 cm is η = 8 itself
      const double eta = kPaperEta * figure(first, 4 + c, "eta") / eta_1cm;
      if (!std::isfinite(eta)) continue;
      runs.push_back(scene_run(scenes_dir, "ffp_reference.json", "SSMC η scaled, " + cm_label(kCalibrations[c].first),
                               softening(kCalibrations[c].first, eta)));
      runs.back().expected_wall_s = 5.0 * std::pow(0.01 / kCalibrations[c].first, 3);
    }
    return runs;
  };
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    const std::size_t levels = kSofteningCells_m.size();
    std::vector<double> peak(levels), depth(levels);
    for (std::size_t i = 0; i < levels; ++i) {
      peak[i] = figure(results, i, "peak_deceleration_2ms_g");
      depth[i] = figure(results, i, "final_penetration_m");
    }
    const double eta_1cm = figure(results, 5, "eta");
    const bool scaled = results.size() == 9;
    // The scaled series on 2, 1, 0.5 cm (its 1 cm run is the fixed one).
    const double scaled_eta[3] = {kPaperEta * figure(results, 4, "eta") / eta_1cm, kPaperEta,
                                  kPaperEta * figure(results, 6, "eta") / eta_1cm};
    const double scaled_peak[3] = {scaled ? figure(results, 7, "peak_deceleration_2ms_g") : std::nan(""), peak[1],
                                   scaled ? figure(results, 8, "peak_deceleration_2ms_g") : std::nan("")};
    const double scaled_depth[3] = {scaled ? figure(results, 7, "final_penetration_m") : std::nan(""), depth[1],
                                    scaled ? figure(results, 8, "final_penetration_m") : std::nan("")};
    md.paragraph(
        "The paper's section 5.5 sand (SSMC, φ'_p = 60°, φ'_c = 32°, ψ_p = 5°) in the reference scene at 2, 1, 0.5 "
        "and 0.25 cm, once with η = 8 at every level and once with η scaled by the paper's mesh-aware "
        "calibration: η(h) = 8 · η_cal(h)/η_cal(1 cm), with η_cal fitted by dissipated work on the D_r = 15 % "
        "specimen meshed with cells h (the calibration study above; no 0.25 cm specimen: it takes hours). "
        "Peak: the 2 ms running mean.");
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 0; i < levels; ++i) {
      const bool has_scaled = i < 3;
      rows.push_back({cm_label(kSofteningCells_m[i]), fixed(figure(results, i, "particles"), 0),
                      fixed(figure(results, i, "steps"), 0), fixed(figure(results, i, "wall_time_s"), 1),
                      fixed(peak[i], 2), fixed(100 * depth[i], 2),
                      has_scaled ? fixed(figure(results, 4 + i, "eta"), 1) : "–",
                      has_scaled ? fixed(scaled_eta[i], 2) : "–", has_scaled ? fixed(scaled_peak[i], 2) : "–",
                      has_scaled ? fixed(100 * scaled_depth[i], 2) : "–"});
    }
    md.table({"min cell", "particles", "steps", "wall time [s]", "η = 8: 2 ms peak [g]", "final penetration [cm]",
              "η_cal(h)", "scaled η", "scaled: 2 ms peak [g]", "final penetration [cm]"},
             rows);
    auto series = [](const char* what, const double* q, std::size_t n, double scale, const char* unit) {
      std::string text = std::string(what) + ": changes";
      bool shrinking = true;
      for (std::size_t i = 1; i < n; ++i) {
        text += " " + fixed(scale * (q[i] - q[i - 1]), 2);
        if (i > 1 && std::abs(q[i] - q[i - 1]) >= std::abs(q[i - 1] - q[i - 2])) shrinking = false;
      }
      const Extrapolation e = richardson(q[n - 3], q[n - 2], q[n - 1]);
      text += std::string(" ") + unit + " per halving, " + (shrinking ? "shrinking" : "not shrinking") +
              (std::isfinite(e.order)
                   ? "; observed order " + fixed(e.order, 2) + ", Richardson " + fixed(scale * e.value, 2) + " " + unit
                   : "; no observed order (not monotone or outside 0.3–4)");
      return text;
    };
    md.paragraph(series("η = 8, 2 ms peak", peak.data(), levels, 1.0, "g") + ". " +
                 series("η = 8, final penetration", depth.data(), levels, 100.0, "cm") + ".");
    if (scaled)
      md.paragraph(series("Scaled η (2, 1, 0.5 cm), 2 ms peak", scaled_peak, 3, 1.0, "g") + ". " +
                   series("Scaled η, final penetration", scaled_depth, 3, 100.0, "cm") + ".");
    std::vector<LabelledRun> runs;
    for (std::size_t i = 0; i < levels; ++i) runs.push_back({i, "η = 8, " + cm_label(kSofteningCells_m[i])});
    ffp_depth_profiles_figure(results, runs, "Softening run, mesh convergence", "softening_convergence_profiles.png",
                              out);
  };
  return study;
}

}  // namespace ffp
