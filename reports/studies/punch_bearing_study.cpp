/// Verification of contact plus plasticity against exact answers: a rigid flat
/// circular punch on a weightless Tresca soil, smooth (5.69 c', Shield 1955)
/// and rough (6.05 c', Eason & Shield 1960), at three mesh sizes, and the
/// smooth punch at three more particle densities.
#include <cmath>

#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

const std::vector<double> kPunchCells_m = {0.01, 0.005, 0.0025};
const std::vector<int> kParticlesPerCell = {1, 2, 4};  // the scenes' own 3×3 is the 0.5 cm level
constexpr double kPunchRadius_m = 0.05;
constexpr double kShieldSmooth = 5.69, kEasonShieldRough = 6.05;

struct Punch {
  const char* scene;
  const char* label;
  double exact;
};
const Punch kPunches[] = {{"punch_smooth.json", "smooth", kShieldSmooth},
                          {"punch_rough.json", "rough", kEasonShieldRough}};

}  // namespace

Study punch_bearing_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "Verification: a rigid circular punch on a Tresca soil";
  for (const Punch& punch : kPunches)
    for (double h : kPunchCells_m) {
      study.runs.push_back(scene_run(scenes_dir, punch.scene,
                                     std::string(punch.label) + " " + fixed(100 * h, 2) + " cm",
                                     {"mesh.min_cell_m=" + fixed(h, 4)}));
      study.runs.back().expected_wall_s = 5.0 * std::pow(0.005 / h, 3);  // 0.5 cm: about 5 s on 2 cores
    }
  for (int ppc : kParticlesPerCell) {
    const std::string n = std::to_string(ppc);
    study.runs.push_back(scene_run(scenes_dir, "punch_smooth.json", "smooth 0.5 cm, " + n + "×" + n + " per cell",
                                   {"soil.particles_per_cell_near=[" + n + "," + n + "]"}));
    study.runs.back().expected_wall_s = 5.0;
  }
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    md.paragraph(
        "A rigid flat punch of radius R = 5 cm is pushed at 0.05 m/s into a weightless Tresca soil (mohr_coulomb "
        "with φ' = 0, c' = 10 kPa, G/c' = 300, ν = 0.3), with the FFP scenes' solver settings (GIMP, USL, strain "
        "smoothing, 3×3 particles per min cell below the punch, the contact of the FFP). The exact limit mean "
        "pressures are 5.69 c' for a smooth punch (Shield 1955) and 6.05 c' for a rough one (Eason & Shield 1960). "
        "bearing_factor is the mean pressure over the settlement window s/R = 0.04–0.06 divided by c', read from the "
        "exact impulse; by then the elastic part of the settlement at the limit load (Boussinesq, "
        "s/R = π(1 − ν) p/(4G) ≈ 1 %) is long passed, and the embedment (2.5 % of the diameter) raises the "
        "exact bearing pressure by about 1 % (Skempton's depth factor).");
    const std::size_t levels = kPunchCells_m.size();
    std::vector<std::vector<std::string>> rows;
    std::vector<Series> curves;
    Series error_series[2];
    for (std::size_t k = 0; k < 2; ++k) {
      error_series[k] = {{}, {}, std::string(kPunches[k].label) + " punch", "linespoints"};
      for (std::size_t l = 0; l < levels; ++l) {
        const std::size_t i = k * levels + l;
        const double n = figure(results, i, "bearing_factor");
        const double error = n / kPunches[k].exact - 1.0;
        rows.push_back({kPunches[k].label, fixed(100 * kPunchCells_m[l], 2),
                        fixed(kPunchRadius_m / kPunchCells_m[l], 0), fixed(figure(results, i, "particles"), 0),
                        fixed(figure(results, i, "steps"), 0), fixed(figure(results, i, "wall_time_s"), 1), fixed(n, 3),
                        fixed(kPunches[k].exact, 2), fixed(100 * error, 1)});
        if (std::isfinite(error)) {
          error_series[k].x.push_back(kPunchCells_m[l] / kPunchRadius_m);
          error_series[k].y.push_back(std::abs(error));
        }
        const CsvData h = results.history(i);
        if (h.has("mean_pressure_kPa")) {
          Series c{{}, {}, std::string(kPunches[k].label) + " " + fixed(100 * kPunchCells_m[l], 2) + " cm", "lines"};
          const auto& s = h.column("penetration_m");
          const auto& p = h.column("mean_pressure_kPa");
          for (std::size_t r = 0; r < s.size(); ++r) {
            c.x.push_back(s[r] / kPunchRadius_m);
            c.y.push_back(p[r] / 10.0);  // c' = 10 kPa in both scenes
          }
          curves.push_back(c);
        }
      }
    }
    // Richardson from the three levels: the MPM's own h → 0 limit, to set against the exact one.
    std::string limits;
    for (std::size_t k = 0; k < 2; ++k) {
      const double n1 = figure(results, k * levels, "bearing_factor"),
                   n2 = figure(results, k * levels + 1, "bearing_factor"),
                   n3 = figure(results, k * levels + 2, "bearing_factor");
      const Extrapolation e = richardson(n1, n2, n3);
      rows.push_back({kPunches[k].label, "h → 0 (Richardson)", "–", "–", "–", "–", fixed(e.value, 3),
                      fixed(kPunches[k].exact, 2), fixed(100 * (e.value / kPunches[k].exact - 1), 1)});
      limits += std::string(k ? "; " : "") + kPunches[k].label + ": " + fixed(e.value, 2) + " against " +
                fixed(kPunches[k].exact, 2) +
                (std::isfinite(e.order) ? " (observed order " + fixed(e.order, 2) + ")"
                                        : " (not extrapolated: the finest level, the sequence is not monotone)");
    }
    md.table({"punch", "min cell [cm]", "R/h", "particles", "steps", "wall time [s]", "bearing factor", "exact",
              "error [%]"},
             rows);
    md.paragraph("The h → 0 limits of the MPM's own sequence: " + limits + ".");
    // 1×1, 2×2, the scenes' own 3×3 (the smooth 0.5 cm run above) and 4×4, in that order.
    const std::size_t first_density = 2 * levels;
    const std::pair<int, std::size_t> by_density[] = {
        {1, first_density}, {2, first_density + 1}, {3, 1}, {4, first_density + 2}};
    std::vector<std::vector<std::string>> density;
    for (const auto& [ppc, i] : by_density) {
      const double n = figure(results, i, "bearing_factor");
      density.push_back({std::to_string(ppc) + "×" + std::to_string(ppc) + (ppc == 3 ? " (the scene)" : ""),
                         fixed(figure(results, i, "particles"), 0), fixed(n, 3),
                         fixed(100 * (n / kShieldSmooth - 1), 1)});
    }
    md.paragraph("The smooth punch at 0.5 cm with other particle densities below it (the quadrature of the cells):");
    md.table({"particles per min cell", "particles", "bearing factor", "error [%]"}, density);
    const double one_point = figure(results, first_density, "bearing_factor");
    md.paragraph(
        "Reading: at the scenes' settings the MPM over-predicts both limit pressures and the error shrinks more "
        "slowly than h (the observed orders above), so the default 0.5 cm mesh (R/h = 10) is outside 3 % of the exact "
        "values. "
        "Under the punch the soil is at q = 2c' and its mean stress is too high, so the excess is in the soil's "
        "discretisation rather than in the contact: the constrained node at the punch's edge drags the next half "
        "cell of soil down (a slightly larger effective radius, first order in h), and the excess falls with the "
        "number of particles in a cell (one per cell, a one-point quadrature: " +
        fixed(one_point, 2) + ", " + fixed(100 * (one_point / kShieldSmooth - 1), 1) +
        " % high at 0.5 cm), the mark of cells too stiff in "
        "plastic flow: the cell-mean (B-bar) smoothing frees the volumetric constraint only. The FFP's cone "
        "resistance is bearing of the same kind and carries part of this bias. A remedy that holds at large "
        "deformation (one-point quadrature needs hourglass control) is open work; the scenes keep 3×3 per cell.");
    Plot curves_plot{"Pressure–settlement of the punches", "settlement / radius s/R", "mean pressure / c'", curves};
    curves_plot.key_position = "bottom right";
    curves_plot.series.push_back(
        {{0.0, 0.06}, {kShieldSmooth, kShieldSmooth}, "Shield 1955 (smooth)", "lines dashtype 2"});
    curves_plot.series.push_back(
        {{0.0, 0.06}, {kEasonShieldRough, kEasonShieldRough}, "Eason & Shield 1960 (rough)", "lines dashtype 2"});
    if (write_png(curves_plot, out.figures_dir / "punch_pressure_settlement.png"))
      md.figure(out.figures_relative + "/punch_pressure_settlement.png",
                "Mean pressure over c' against settlement over radius, each punch at each mesh size, with the exact "
                "limits.");
    Plot error_plot{"Bearing factor error against mesh size",
                    "h / R",
                    "|N − N_exact| / N_exact",
                    {error_series[0], error_series[1]},
                    true,
                    true,
                    false,
                    "bottom right"};
    if (write_png(error_plot, out.figures_dir / "punch_convergence.png"))
      md.figure(out.figures_relative + "/punch_convergence.png",
                "Relative error of the bearing factor against h/R (log–log).");
  };
  return study;
}

}  // namespace ffp
