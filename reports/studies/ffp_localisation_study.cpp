/// Where and when the reference drop's sand can form shear bands: the loss of ellipticity
/// of its Mohr–Coulomb tangent (Rudnicki & Rice 1975, models/localisation.hpp), written by
/// the reference run itself (output.localisation), so the study adds no run.
#include <cmath>
#include <string>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "models/localisation.hpp"
#include "models/math_constants.hpp"
#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

/// The history row nearest `time_s` (the rows are 0.2 ms apart).
std::size_t row_at(const CsvData& history, double time_s) {
  const auto& t = history.column("time_s");
  std::size_t best = 0;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - time_s) < std::abs(t[best] - time_s)) best = k;
  return best;
}

/// "14 % of 2008 particles on a face (2515 more on an edge or at the apex)" at the row nearest `time_s`.
std::string share_at(const CsvData& history, double time_s) {
  const std::size_t k = row_at(history, time_s);
  return fixed(100 * history.column("localised_fraction")[k], 0) + " % of " +
         fixed(history.column("yield_face_particles")[k], 0) + " particles on a face (" +
         fixed(history.column("yield_edge_particles")[k] + history.column("yield_apex_particles")[k], 0) +
         " more on an edge or at the apex)";
}

/// Rudnicki & Rice's band of a perfectly plastic Mohr–Coulomb face with the hoop stress
/// intermediate: its inclination to the major compression, in degrees (models/localisation.hpp).
double band_inclination_deg(const nlohmann::json& material) {
  const ElasticConstants elastic{1e3 * material.at("E_kPa").get<double>(), material.at("nu").get<double>()};
  const MohrCoulombStrength strength = MohrCoulombStrength::of(
      material.at("phi_peak_deg").get<double>() * kDegree, material.at("psi_peak_deg").get<double>() * kDegree, 0.0);
  const double s3 = -1e4, s1 = s3 * (1 - strength.sin_phi) / (1 + strength.sin_phi);
  Voigt stress = Voigt::Zero();
  stress << s1, s3, 0.5 * (s1 + s3), 0.0, 0.0, 0.0;  // σ1 along r, σ3 along z
  const MohrCoulombFlow at = mohr_coulomb_flow(stress, strength);
  if (at.region != ReturnRegion::plane) return std::nan("");
  // The band runs at θ + 90° from r; its angle to the σ3 (z) axis is then θ, folded into [0°, 90°].
  const double theta = find_localisation(elastic, at.flow).band_normal_rad / kDegree;
  return std::min(theta, 180.0 - theta);
}

}  // namespace

Study ffp_localisation_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Where the reference drop's sand loses ellipticity";
  study.runs = {reference_drop_run(scenes_dir, "rigid FFP")};
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    const CsvData history = results.history(0);
    if (!history.has("localised_fraction")) {
      md.paragraph("The reference run failed or wrote no localisation columns; the figures are left out.");
      return;
    }
    const double most = figure(results, 0, "localised_fraction_max");
    const double when = figure(results, 0, "localised_time_s");
    const double peak_time = figure(results, 0, "time_of_peak_s");
    md.paragraph(
        "The reference drop (MC, φ' = 39°, ψ = 0, the paper's model) with `output.localisation`: at every history row "
        "each sand particle on a face of its yield surface is tested for the loss of ellipticity of its elastoplastic "
        "tangent, det A(n) ≤ 0 for a band normal n in the r–z plane (Rudnicki & Rice 1975; "
        "docs/theory.md#localisation). Where it holds, the rate equations admit a shear band and a model "
        "without an internal length lets the cells set the band's width. Non-associated flow (ψ < φ') localises on "
        "every face whose intermediate stress is the hoop stress; where the hoop stress is the major or minor one, "
        "perfect plasticity stays elliptic. Particles on an edge of the surface (two equal principal stresses, "
        "σ_rr = σ_θθ near the axis) or at its apex are counted but not tested.");
    const auto& depth = history.column("penetration_m");
    const double deepest_s = history.column(
        "time_s")[static_cast<std::size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin())];
    const nlohmann::json summary = results.summary(0);
    const double band = band_inclination_deg(summary.at("scene").at("material"));
    md.paragraph("During the drive the localised share grows: " + share_at(history, 0.01) + " at 10 ms, " +
                 share_at(history, peak_time) + " at the peak deceleration (" + fixed(1000 * peak_time, 1) + " ms), " +
                 share_at(history, 0.04) + " at 40 ms and " + share_at(history, 0.06) +
                 " at 60 ms. Its largest value, localised_fraction_max = " + fixed(most, 3) +
                 ", comes at localised_time_s = " + fixed(when, 4) + " s, " +
                 (when > deepest_s
                      ? "after the penetrometer's deepest point (" + fixed(1000 * deepest_s, 1) +
                            " ms), while the body bounces and the sand unloads and reloads: "
                      : "before the penetrometer's deepest point (" + fixed(1000 * deepest_s, 1) + " ms): ") +
                 share_at(history, when) +
                 ". The share swings from row to row as particles step on and off the surface with the impact's "
                 "waves; the counts say how many particles it is a share of. Each localised particle's band lies at " +
                 fixed(band, 1) + "° to its major compression in the r–z plane (Rudnicki & Rice for this sand's " +
                 "φ', ψ and ν', between Coulomb's 45° − φ'/2 and Roscoe's 45° − ψ/2: where only faces with the hoop "
                 "stress intermediate localise, the angle is the same at every particle; the field band_angle_deg "
                 "gives each band's normal in the r–z plane).");
    include_run_figure(results, 0, "plots/localisation.png", "localisation_history.png",
                       "Localised share of the face particles against time, and the counts of yielding particles "
                       "(on a face, localised, on an edge or at the apex)",
                       out);
    for (const char* t : {"0.040", "0.060"})
      include_run_figure(results, 0, std::string("plots/localisation_t") + t + ".png",
                         std::string("localisation_t") + t + ".png",
                         std::string("Where the sand has lost ellipticity at t = ") + t + " s", out);
  };
  return study;
}

}  // namespace ffp
