/// The headline table: the paper's and the experiment's figures against ours,
/// for the MC reference, the paper's φ'_p = 60° SSMC and the SSMC fed the η of
/// the mesh-aware calibration.
#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

constexpr std::size_t kMicropolarRun = 3;  // in the study's own runs
constexpr std::size_t kCalibratedRun = 4;  // the follow-up, after the study's runs

/// The micropolar scene's ℓ, from its echoed scene (NaN if the run failed).
double micropolar_length_m(const StudyResults& results) {
  const nlohmann::json s = results.summary(kMicropolarRun);
  return s.empty() ? std::nan("") : s.at("scene").at("material").at("micropolar").at("length_m").get<double>();
}

}  // namespace

Study ffp_paper_comparison_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Summary: the paper and the experiment against ours";
  // The calibrated model is fed the η its calibration finds, on the FFP's own 1 cm cells
  // (paper section 4.2), not a number copied into a scene.
  study.runs = {reference_drop_run(scenes_dir, "rigid FFP"),
                scene_run(scenes_dir, "ffp_reference.json", "φ'_p = 60°", paper_softening_sand("8")),
                scene_run(scenes_dir, "calibration_dr15_mpm_1cm.json", "calibration, MPM specimen 1 cm"),
                micropolar_drop_run(scenes_dir, "micropolar sand, 1 cm")};
  study.follow_up = [scenes_dir](const StudyResults& first) -> std::vector<RunRequest> {
    const auto calibration = first.summary(2);
    if (calibration.empty()) return {};
    RunRequest run = scene_run(scenes_dir, "ffp_calibrated.json", "FFP, calibrated SSMC (φ'_p = 60°)",
                               {"material.eta=" + fixed(calibration["eta"].get<double>(), 1)});
    run.expected_wall_s = 5.0;  // a 1 cm run
    return {run};
  };
  study.write = [scenes_dir](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    const double peak = figure(results, 0, "peak_deceleration_g");
    const double final_depth = figure(results, 0, "final_penetration_m");
    const double time_of_peak = figure(results, 0, "time_of_peak_s");
    const double rest = figure(results, 0, "final_reaction_N");
    const double paper_peak = figure(results, 1, "peak_deceleration_g");
    const double paper_depth = figure(results, 1, "final_penetration_m");
    const double eta = figure(results, 2, "eta");
    const bool calibrated = results.size() > kCalibratedRun;
    const double cal_peak = calibrated ? figure(results, kCalibratedRun, "peak_deceleration_g") : std::nan("");
    const double cal_depth = calibrated ? figure(results, kCalibratedRun, "final_penetration_m") : std::nan("");
    // The micropolar sand beside the paper's: the same scene, its MC law in a micropolar continuum.
    const auto micropolar = [&](const char* key, double scale, int decimals, const std::string& unit) {
      const double value = figure(results, kMicropolarRun, key);
      return std::isfinite(value) ? fixed(scale * value, decimals) + unit : std::string("–");
    };
    md.table(
        {"quantity", "paper / experiment", "ours", "difference",
         "micropolar sand (ℓ = " + fixed(1e3 * micropolar_length_m(results), 1) + " mm), 1 cm, not mesh-converged"},
        {{"MC reference: peak deceleration", "≈ 15 g (paper)", fixed(peak, 1) + " g", percent_difference(peak, 15.0),
          micropolar("peak_deceleration_g", 1.0, 1, " g")},
         {"MC reference: time of peak", "≈ 0.03 s (paper, Fig. 7)", fixed(time_of_peak, 3) + " s",
          percent_difference(time_of_peak, 0.03), micropolar("time_of_peak_s", 1.0, 3, " s")},
         {"MC reference: final penetration", "18–20 cm (paper)", fixed(100 * final_depth, 1) + " cm",
          percent_difference(100 * final_depth, 19.0) + " vs 19 cm",
          micropolar("final_penetration_m", 100.0, 1, " cm")},
         {"MC reference: reaction at the end (mean of the last " +
              fixed(1000 * figure(results, 0, "final_reaction_window_s"), 0) + " ms of 0.15 s)",
          "≈ weight 75.6 N (paper, Fig. 7d)", fixed(rest, 1) + " N", percent_difference(rest, 75.6),
          micropolar("final_reaction_N", 1.0, 1, " N")},
         {"SSMC φ'_p = 60°, η = 8 (paper 5.5): peak deceleration", "19.4 g (experiment; the paper matches it)",
          fixed(paper_peak, 1) + " g", percent_difference(paper_peak, 19.4), ""},
         {"SSMC φ'_p = 60°, η = 8: final penetration", "≈ 15.2 cm (experiment, derived: see data/experiment)",
          fixed(100 * paper_depth, 1) + " cm", percent_difference(100 * paper_depth, 15.2), ""},
         {"SSMC φ'_p = 60°, calibrated η = " + fixed(eta, 1) + ": peak deceleration", "19.4 g (experiment)",
          fixed(cal_peak, 1) + " g", percent_difference(cal_peak, 19.4), ""},
         {"SSMC φ'_p = 60°, calibrated η: final penetration", "≈ 15.2 cm (experiment, derived)",
          fixed(100 * cal_depth, 1) + " cm", percent_difference(100 * cal_depth, 15.2), ""}});
    md.paragraph(
        "The last column is data/scenes/ffp_micropolar.json: the MC reference's sand with a grain-size length, on "
        "the same 1 cm cells, its micro terms held at its friction: one mesh's answer, not a converged one. The "
        "converged drop (ℓ = 1.2 mm, three levels run outside the report) and its comparison with the paper and "
        "the experiment are in docs/verification.md#micropolar-ffp-convergence.");
    {
      // The paper's Fig. 7d shows the reaction settling at the weight; ours is that plus the
      // inertia of a body not yet at rest (its momentum still changes over the window).
      const double inertia = figure(results, 0, "final_reaction_inertia_N");
      md.paragraph("The reaction at the end is not the weight alone: at 0.15 s the FFP is still moving (" +
                   fixed(figure(results, 0, "final_velocity_m_s"), 3) + " m/s down, after a rebound of " +
                   fixed(1000 * figure(results, 0, "rebound_m"), 1) +
                   " mm), and over the window its momentum "
                   "changes by M Δv: the mean reaction is the weight plus M Δv/Δt = " +
                   fixed(inertia, 1) +
                   " N. The miss says the body has not come to rest by 0.15 s (it bounces on the sand), not that the "
                   "sand carries the wrong static load; the FFP left at rest carries its weight within 5 % (tests).");
    }
    md.paragraph(
        "The calibrated run takes η = " + fixed(eta, 1) +
        " from the dissipated-work calibration on the meshed MPM specimen with the FFP's 1 cm cells "
        "(calibration_dr15_mpm_1cm.json, the paper's procedure of section 4.2), passed to ffp_calibrated.json "
        "by the report. The experiment's time histories are not public; the comparisons use the scalar "
        "values the paper states (data/experiment/). The paper's own numbers are read from its text, not "
        "from its figures. The peak deceleration and the time it comes at are the chamber's as much as the "
        "sand's: the sand's p-wave returns from the chamber's base and wall to the cone after about 15 ms, and "
        "in a chamber four times as large the peak is lower (the chamber study below).");
    std::ifstream scene_file(scenes_dir / "ffp_calibrated.json");
    const auto scene = nlohmann::json::parse(scene_file, nullptr, false);
    if (std::isfinite(eta) && scene.is_object() && scene.contains("material") &&
        std::abs(scene["material"].value("eta", 0.0) - eta) > 0.05)
      md.paragraph("**Note:** ffp_calibrated.json carries η = " + fixed(scene["material"].value("eta", 0.0), 2) +
                   ", the calibration now finds " + fixed(eta, 2) +
                   ": the report ran with the calibration's value; update the scene to match.");
  };
  return study;
}

}  // namespace ffp
