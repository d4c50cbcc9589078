/// Paper section 6, Fig. 14: dynamic and quasi-static reaction profiles and the
/// rate factor K of F_dyn = F_0 (1 + K log10(v / v_ref)) (paper eq. 6).
#include <algorithm>
#include <cmath>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

constexpr double kReferenceVelocity_m_s = 0.02;  // CPT rate, paper section 6

/// The part of a push history that only goes deeper (a monotone depth table).
void monotone_in_depth(const std::vector<double>& depth, const std::vector<double>& value, std::vector<double>& d_out,
                       std::vector<double>& v_out) {
  double deepest = -1e300;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (depth[i] > deepest) {
      deepest = depth[i];
      d_out.push_back(depth[i]);
      v_out.push_back(value[i]);
    }
  }
}

}  // namespace

Study ffp_rate_factor_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Quasi-static push, dynamic reaction and the rate factor K (paper section 6, Fig. 14)";
  // The paper's "calibrated model" of section 5.5 (φ'_p = 60°, η = 8: the one that matches the
  // experiment), as in the peak-friction study, so the run is shared.
  study.runs = {scene_run(scenes_dir, "ffp_reference.json", "φ'_p = 60°", paper_softening_sand("8")),
                scene_run(scenes_dir, "cpt_reference.json", "CPT-like push, φ'_p = 39°"),
                scene_run(scenes_dir, "cpt_slow.json", "CPT-like push at half speed")};
  // From `ffp check`: 6086 particles over about 10,000 and 20,000 steps, SSMC at ~2 M particle-steps
  // per second on one core: the pushes are among the longer 1 cm runs.
  study.runs[1].expected_wall_s = 30;
  study.runs[2].expected_wall_s = 60;
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    md.paragraph(
        "F_dyn(z) is the soil's reaction on the penetrometer in the paper's calibrated dynamic run (section 5.5: "
        "SSMC, φ'_p = 60°, φ'_c = 32°, ψ_p = 5°, η = 8); F_0(z) comes from pushing the same penetrometer at a "
        "constant speed into the same sand with the quasi-static φ'_p = 39° (the paper pushes at v_ref = 2 cm/s; "
        "we push at 25 cm/s and check the speed does not matter by pushing at 12.5 cm/s too). K(z) follows from paper "
        "eq. 6 with the dynamic run's velocity: "
        "K = (F_dyn/F_0 − 1)/log10(v/v_ref). Paper: K between 0.8 and 2.0 before the tip is fully embedded and "
        "about 0.75 after; literature 0.2–1.5.");
    const CsvData dynamic = results.history(0);
    const CsvData push = results.history(1);
    const CsvData slow = results.history(2);
    if (!dynamic.has("penetration_m") || !push.has("penetration_m")) {
      md.paragraph("**A run of this study failed**; no K profile.");
      return;
    }
    std::vector<double> z0, f0, z_slow, f_slow;
    monotone_in_depth(push.column("penetration_m"), push.column("reaction_N"), z0, f0);
    if (slow.has("penetration_m"))
      monotone_in_depth(slow.column("penetration_m"), slow.column("reaction_N"), z_slow, f_slow);

    // Push-speed independence of F_0 over the common depths beyond 2 cm: the mean of |ΔF_0| relative to
    // the mean F_0 (the rows carry ±10 % noise of their own), and the largest |ΔF_0|.
    double max_difference = 0.0, sum_difference = 0.0, sum_f0 = 0.0, max_f0 = 0.0;
    for (std::size_t i = 0; i < z0.size(); ++i) {
      if (z0[i] < 0.02) continue;
      const double other = interpolate(z_slow, f_slow, z0[i]);
      if (!std::isfinite(other)) continue;
      max_difference = std::max(max_difference, std::abs(other - f0[i]));
      sum_difference += std::abs(other - f0[i]);
      sum_f0 += f0[i];
      max_f0 = std::max(max_f0, f0[i]);
    }

    const double cone_height = 0.04375 * std::sqrt(3.0);
    // K only where the embedded part of the cone spans at least three cells: above
    // that the contact acts on one or two node rows and F_0 is a few newtons, so
    // K = (F_dyn/F_0 − 1)/log10(v/v_ref) divides by a number that is mostly
    // discretisation (measured: K = 8–31 there at 1 cm).
    const auto summary = results.summary(0);
    const double h = summary.contains("scene") ? summary["scene"]["mesh"]["min_cell_m"].get<double>() : 0.01;
    const double shallowest = 3.0 * h;
    const auto& z = dynamic.column("penetration_m");
    const auto& f = dynamic.column("reaction_N");
    const auto& v = dynamic.column("velocity_m_s");
    Series dyn{{}, {}, "F_dyn (FFP, φ'_p = 60°, η = 8)", "lines"}, stat{{}, {}, "F_0 (push, φ'_p = 39°)", "lines"};
    Series k_series{{}, {}, "K from eq. 6", "lines"};
    double before_sum = 0, after_sum = 0;
    int before_n = 0, after_n = 0;
    double k_min_before = 1e300, k_max_before = -1e300;
    for (std::size_t i = 0; i < z.size(); ++i) {
      if (i > 0 && z[i] <= z[i - 1]) break;  // only the way down
      const double f0_here = interpolate(z0, f0, z[i]);
      dyn.x.push_back(100 * z[i]);
      dyn.y.push_back(f[i]);
      if (!std::isfinite(f0_here) || f0_here < 1.0 || v[i] < 2 * kReferenceVelocity_m_s || z[i] < shallowest) continue;
      const double k = (f[i] / f0_here - 1.0) / std::log10(v[i] / kReferenceVelocity_m_s);
      k_series.x.push_back(100 * z[i]);
      k_series.y.push_back(k);
      if (z[i] < cone_height) {
        before_sum += k;
        ++before_n;
        k_min_before = std::min(k_min_before, k);
        k_max_before = std::max(k_max_before, k);
      } else {
        after_sum += k;
        ++after_n;
      }
    }
    for (std::size_t i = 0; i < z0.size(); ++i) {
      stat.x.push_back(100 * z0[i]);
      stat.y.push_back(f0[i]);
    }
    Plot forces{"Reaction profiles (Fig. 14a)",
                "penetration (cm)",
                "reaction (N)",
                {dyn, stat},
                false,
                false,
                false,
                "top left"};
    Plot factor{"Rate factor K (Fig. 14b)", "penetration (cm)", "K", {k_series}, false, false, false, "top right"};
    factor.series.push_back({{0, 25}, {0.2, 0.2}, "literature 0.2–1.5", "lines dashtype 2"});
    factor.series.push_back({{0, 25}, {1.5, 1.5}, "", "lines dashtype 2"});
    if (write_png_stack({forces, factor}, out.figures_dir / "fig14_rate_factor.png"))
      md.figure(out.figures_relative + "/fig14_rate_factor.png", "F_dyn, F_0 and K against penetration (Fig. 14).");
    const double before = before_n ? before_sum / before_n : std::nan("");
    const double after = after_n ? after_sum / after_n : std::nan("");
    md.table(
        {"quantity", "paper", "ours"},
        {{"K before full embedment (" + fixed(100 * shallowest, 1) + " cm ≤ z < cone height " +
              fixed(100 * cone_height, 1) + " cm; shallower, the embedded cone spans fewer than 3 cells)",
          "0.8–2.0", fixed(k_min_before, 2) + " to " + fixed(k_max_before, 2) + " (mean " + fixed(before, 2) + ")"},
         {"K after full embedment (mean)", "≈ 0.75", fixed(after, 2)},
         {"literature range", "0.2–1.5", ""},
         {"F_0 change when the push speed halves (z > 2 cm)", "–",
          "mean " + fixed(100 * sum_difference / std::max(sum_f0, 1e-9), 1) + " % of F_0; largest " +
              fixed(max_difference, 1) + " N (" + fixed(100 * max_difference / std::max(max_f0, 1e-9), 1) +
              " % of the largest F_0)"}});
  };
  return study;
}

}  // namespace ffp
