/// Error against run time of the constitutive integration.
#include "drivers/integration_study.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

Study integration_error_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Constitutive integration: error against run time";
  study.runs = {scene_run(scenes_dir, "integration_error.json", "integration_error")};
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    md.paragraph(
        "Drained triaxial compression to ε_a = 20 % at σ3 = 1.72 kPa with the paper's sand (E' = 2500 kPa, "
        "ν' = 0.33, φ'_p = 39°, φ'_c = 32°, ψ_p = 5°, η = 8), integrated by the point driver with 10 … 10,000 "
        "equal increments and compared with a 100,000-increment reference. Mohr-Coulomb's return is exact for a "
        "linear path, so its error stays at round-off; the SSMC's implicit softening converges at first order.");
    const auto summary = results.summary(0);
    if (summary.empty()) {
      md.paragraph("**The integration-error run failed:** " + results.outcome(0).error);
      return;
    }
    std::vector<std::vector<std::string>> rows;
    const auto& ssmc = summary["ssmc_triaxial"]["runs"];
    const auto& mc = summary["mohr_coulomb_triaxial"]["runs"];
    for (std::size_t i = 0; i < ssmc.size(); ++i) {
      rows.push_back({std::to_string(ssmc[i]["increments"].get<int>()),
                      scientific(ssmc[i]["wall_time_s"].get<double>()),
                      scientific(ssmc[i]["q_error_end"].get<double>()),
                      scientific(ssmc[i]["volumetric_strain_error_end"].get<double>()),
                      scientific(ssmc[i]["q_error_path"].get<double>()),
                      i < mc.size() ? scientific(mc[i]["q_error_end"].get<double>()) : "–"});
    }
    md.table({"increments", "SSMC wall time [s]", "SSMC q error at 20 %", "SSMC ε_v error at 20 %",
              "SSMC max q error on the path", "MC q error at 20 %"},
             rows);
    include_run_figure(results, 0, "plots/error_vs_wall_time.png", "integration_error_vs_wall_time.png",
                       "Relative error against the wall time of one run (log-log).", out);
    md.paragraph(
        "Iso-error maps: one strain increment of up to 10× the yield strain, from a stress on the plane, on the "
        "triaxial-compression edge and at the apex, against 2000 substeps. Colours are log10 of the relative "
        "stress error.");
    for (const char* law : {"mohr_coulomb", "ssmc"}) {
      for (const MapStartName& entry : kMapStartNames) {
        const std::string start(entry.second);
        const std::string key = std::string(law) + "_" + start;
        const double max_error = summary["iso_error_maps"][key]["max_error"].get<double>();
        include_run_figure(results, 0, "plots/iso_error_" + key + ".png", "iso_error_" + key + ".png",
                           std::string(law == std::string("ssmc") ? "SSMC" : "MC") + ", start on the " + start +
                               ": largest error " + scientific(max_error),
                           out);
      }
    }
  };
  return study;
}

}  // namespace ffp
