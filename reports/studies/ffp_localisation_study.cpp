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

/// "59 % of the 4285 particles on a face or an edge (279 of 2008 on a face, 2277 of 2277 on an
/// edge; 238 more at the apex)" at the row nearest `time_s`.
std::string share_at(const CsvData& history, double time_s) {
  const std::size_t k = history_row_at(history, time_s);
  auto at = [&](const char* column) { return history.column(column)[k]; };
  const double face = at("yield_face_particles"), edge = at("yield_edge_particles");
  return fixed(100 * at("localised_fraction"), 0) + " % of the " + fixed(face + edge, 0) +
         " particles on a face or an edge (" + fixed(at("localised_face_particles"), 0) + " of " + fixed(face, 0) +
         " on a face, " + fixed(at("localised_edge_particles"), 0) + " of " + fixed(edge, 0) + " on an edge; " +
         fixed(at("yield_apex_particles"), 0) + " more at the apex)";
}

/// The diagnostic at a stress of the scene's sand on its surface with σ1 along r, σ3 along z
/// and θθ `hoop_share` of the way from σ1 to σ3 (0: the compression edge, 1: the extension
/// edge, between: a face).
Localisation reference_localisation(const nlohmann::json& material, double hoop_share) {
  const ElasticConstants elastic{1e3 * material.at("E_kPa").get<double>(), material.at("nu").get<double>()};
  const MohrCoulombStrength strength = MohrCoulombStrength::of(
      material.at("phi_peak_deg").get<double>() * kDegree, material.at("psi_peak_deg").get<double>() * kDegree, 0.0);
  const double s3 = -1e4, s1 = s3 * (1 - strength.sin_phi) / (1 + strength.sin_phi);
  Voigt stress = Voigt::Zero();
  stress << s1, s3, s1 + hoop_share * (s3 - s1), 0.0, 0.0, 0.0;
  const MohrCoulombFlow at = mohr_coulomb_flow(stress, strength);
  if (at.region == ReturnRegion::plane) return find_localisation(elastic, at.flow);
  if (at.region == ReturnRegion::edge_compression || at.region == ReturnRegion::edge_extension)
    return find_localisation(elastic, at.corner);
  return {std::nan(""), std::nan(""), std::nan(""), false};
}

/// Rudnicki & Rice's band there: its inclination to the major compression, in degrees. The
/// band runs at θ + 90° from r; its angle to the σ3 (z) axis is then θ, folded into [0°, 90°].
double band_inclination_deg(const Localisation& found) {
  const double theta = found.band_normal_rad / kDegree;
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
    const nlohmann::json material = results.summary(0).at("scene").at("material");
    // θθ with σ1 (the compression edge, as beside the cone), between (a face), with σ3 (the extension edge).
    const Localisation compression = reference_localisation(material, 0.0),
                       face = reference_localisation(material, 0.5), extension = reference_localisation(material, 1.0);
    md.paragraph(
        "The reference drop (MC, φ' = 39°, ψ = 0, the paper's model) with `output.localisation`: at every history row "
        "each sand particle on its yield surface is tested for the loss of ellipticity of its elastoplastic tangent, "
        "det A(n) ≤ 0 for a band normal n in the r–z plane (Rudnicki & Rice 1975; docs/theory.md#localisation): on a "
        "face with that plane's tangent, on an edge (two equal principal stresses; beside the cone σ_rr = σ_θθ above "
        "σ_zz, the triaxial-compression edge) with Koiter's corner tangent of its two planes, both active, as the "
        "return's edge region produces it. Where it holds, the rate equations admit a shear band and a model without "
        "an internal length lets the cells set the band's width. Non-associated flow (ψ < φ') localises on every "
        "face whose intermediate stress is the hoop stress (r_min = " +
        fixed(face.determinant_ratio, 3) +
        " for this sand); where the hoop stress is the major or minor one, perfect plasticity stays elliptic. At an "
        "edge perfect plasticity with ψ ≤ φ' always localises: with the hoop stress one of the equal pair r_min = " +
        fixed(compression.determinant_ratio, 3) + " on the compression edge and " +
        fixed(extension.determinant_ratio, 3) +
        " on the extension edge, and with the pair in the r–z plane the corner sits exactly at the onset (r_min = 0). "
        "Particles at the apex (stress-free) are counted but not tested: the stress is fixed there and the tangent "
        "not defined.");
    const auto& depth = history.column("penetration_m");
    const double deepest_s = history.column(
        "time_s")[static_cast<std::size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin())];
    md.paragraph("During the drive: " + share_at(history, 0.01) + " at 10 ms, " + share_at(history, 0.03) +
                 " at 30 ms, " + share_at(history, peak_time) + " at the peak deceleration (" +
                 fixed(1000 * peak_time, 1) + " ms), " + share_at(history, 0.04) + " at 40 ms and " +
                 share_at(history, 0.06) + " at 60 ms. The share's largest value over the rows where at least " +
                 fixed(figure(results, 0, "localised_fraction_min_yielding"), 0) +
                 " particles yield (5 % of the sand: a share of a handful under the tip says nothing), "
                 "localised_fraction_max = " +
                 fixed(most, 3) + ", comes at localised_time_s = " + fixed(when, 4) + " s, " +
                 (when > deepest_s
                      ? "after the penetrometer's deepest point (" + fixed(1000 * deepest_s, 1) +
                            " ms), while the body bounces and the sand unloads and reloads: "
                      : "before the penetrometer's deepest point (" + fixed(1000 * deepest_s, 1) + " ms): ") +
                 share_at(history, when) +
                 ". The share swings from row to row as particles step on and off the surface with the impact's "
                 "waves; the counts say how many particles it is a share of. Each localised particle's band lies at " +
                 fixed(band_inclination_deg(face), 1) + "° to its major compression in the r–z plane on a face " +
                 "(Rudnicki & Rice for this sand's φ', ψ and ν', between Coulomb's 45° − φ'/2 and Roscoe's " +
                 "45° − ψ/2), at " + fixed(band_inclination_deg(compression), 1) + "° on a compression edge and " +
                 fixed(band_inclination_deg(extension), 1) +
                 "° on an extension edge with the hoop stress in the pair, and at 45° to the axes where the pair "
                 "lies in the r–z plane; the field band_angle_deg gives each band's normal in the r–z plane.");
    include_run_figure(results, 0, "plots/localisation.png", "localisation_history.png",
                       "Localised share of the face and edge particles against time, and the counts of yielding "
                       "particles (on a face, on an edge, localised, at the apex)",
                       out);
    for (const char* t : {"0.040", "0.060"})
      include_run_figure(results, 0, std::string("plots/localisation_t") + t + ".png",
                         std::string("localisation_t") + t + ".png",
                         std::string("Where the sand has lost ellipticity at t = ") + t + " s", out);
  };
  return study;
}

}  // namespace ffp
