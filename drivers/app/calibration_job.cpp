/// The `calibration` scene kind: the SSMC softening factor η fitted to a lab
/// triaxial curve so that the numerical triaxial dissipates the lab's work
/// (paper section 4.2, Fig. 3; calibration/softening_calibration.hpp).
///
/// Scene (geotechnical units, compression positive):
///   lab_curve_csv        the lab curve, relative to the scene file (data/lab/README.md)
///   material             an ssmc material (no density: weightless specimen); its eta
///                        is where the fit starts
///   mode                 dissipated_work (the paper's, default) | curve_least_squares
///   compare_modes        also fit with the other criterion, reported under other_mode (default true)
///   fit_peak_friction    replace phi_peak_deg by the lab peak's, asin((N−1)/(N+1)),
///                        N = 1 + q_peak/σ3 (c' = 0 only; default false)
///   eta_min, eta_max     bounds of η (default 0.1, 500)
///   compare_eta          η of the extra curves in the figure (default the paper's [2.5, 15])
///   cell_pressure_kPa    σ3 (default 1.72)
///   specimen             {height_m: 0.15, diameter_m: 0.07}
///   increments           of the element test over the lab's strain range (default 1000)
///   strain_rate_per_s    only the rate law sees it (default 1e-4)
///   scan_points          log-spaced η of the W(η) check (default 9)
///   max_iterations       Ceres iterations (default 50)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>

#include "calibration/lab_curve.hpp"
#include "calibration/softening_calibration.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/scene/material_scene.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

std::string format(double v, int digits = 4) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

CalibrationMode mode_named(const std::string& name) {
  return name == "dissipated_work" ? CalibrationMode::dissipated_work : CalibrationMode::curve_least_squares;
}

CalibrationMode other(CalibrationMode mode) {
  return mode == CalibrationMode::dissipated_work ? CalibrationMode::curve_least_squares
                                                  : CalibrationMode::dissipated_work;
}

const char* kWorkNote =
    "dissipated work = ∫F dδ (F = q·A, δ = ε_a·H), trapezoid rule on each curve's own points (the lab's rows; "
    "the model's increments), both over the lab's displacement range. It is the piston's deviatoric work: it "
    "differs from the model's plastic work (what the law dissipates) by the elastic energy still stored and by "
    "the cell pressure's work σ3·ΔV on the specimen's volume change";

struct CalibrationSpec {
  fs::path lab_file;
  LabCurve lab;
  StrainSofteningParameters material;
  bool fitted_peak_friction = false;
  double eta_start = 8.0;
  TriaxialTestConfig test;
  CalibrationSettings settings;
  bool compare_modes = true;
  std::vector<double> compare_eta;
};

class CalibrationJob : public Job {
 public:
  explicit CalibrationJob(CalibrationSpec spec) : spec_(std::move(spec)) {}

  void describe(std::ostream& out) const override {
    out << "calibration: η of the ssmc by " << to_string(spec_.settings.mode) << " on " << spec_.lab_file.string()
        << " (" << spec_.lab.axial_strain.size() << " points, ε_a to " << spec_.lab.axial_strain.back()
        << "), η in [" << spec_.settings.eta_min << ", " << spec_.settings.eta_max << "], element test with "
        << spec_.test.increments << " increments\n";
  }

  void run(RunContext& context) override {
    const NumericalTriaxial triaxial = element_test_triaxial(spec_.material, spec_.test);
    const CalibrationResult result = calibrate(triaxial, spec_.settings);
    throw_if_interrupted();
    std::optional<CalibrationResult> second;
    if (spec_.compare_modes) {
      CalibrationSettings s = spec_.settings;
      s.mode = other(s.mode);
      second = calibrate(triaxial, s);
    }
    std::vector<std::pair<double, SpecimenCurve>> compared;
    for (double eta : spec_.compare_eta) compared.emplace_back(eta, run_element_test(triaxial, eta));
    context.steps = static_cast<long>(result.model_runs + (second ? second->model_runs : 0) +
                                      static_cast<int>(compared.size())) *
                    spec_.test.increments;

    if (!result.work_decreases_with_eta)
      std::fprintf(stderr, "warning: W(η) does not decrease strictly along the scan (see work_scan.csv): "
                           "the dissipated-work criterion may match more than one η\n");
    if (result.at_bound)
      std::fprintf(stderr, "warning: the fitted η = %s lies on a bound of [%s, %s]\n", format(result.eta).c_str(),
                   format(spec_.settings.eta_min).c_str(), format(spec_.settings.eta_max).c_str());

    write_summary(result, second, compared, context.summary);
    write_tables(result, second, compared, context);
    write_plots(result, second, compared, context);
  }

 private:
  CalibrationResult calibrate(const NumericalTriaxial& triaxial, const CalibrationSettings& settings) const {
    try {
      return calibrate_softening_factor(spec_.lab, triaxial, settings);
    } catch (const CalibrationFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) + "): " + e.what());
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) + "): the element test failed: " +
                       e.what());
    }
  }

  static SpecimenCurve run_element_test(const NumericalTriaxial& triaxial, double eta) {
    try {
      return triaxial(eta);
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure("calibration: the element test with η = " + format(eta) + " failed: " + e.what());
    }
  }

  double work_of(const SpecimenCurve& c) const {
    return dissipated_work_J(c.axial_strain, c.deviatoric_stress_Pa, spec_.settings.specimen,
                             spec_.lab.axial_strain.front(), spec_.lab.axial_strain.back());
  }

  static json fit_json(const CalibrationResult& r) {
    return {{"mode", to_string(r.mode)},
            {"eta", r.eta},
            {"dissipated_work_model_J", r.dissipated_work_model_J},
            {"relative_work_residual", r.relative_work_residual},
            {"plastic_work_model_J", r.plastic_work_model_J},
            {"rms_q_error_kPa", 1e-3 * r.rms_q_error_Pa},
            {"iterations", r.iterations},
            {"model_runs", r.model_runs},
            {"termination", r.termination},
            {"converged", r.converged},
            {"at_bound", r.at_bound},
            {"wall_time_s", r.wall_time_s}};
  }

  void write_summary(const CalibrationResult& r, const std::optional<CalibrationResult>& second,
                     const std::vector<std::pair<double, SpecimenCurve>>& compared, json& s) const {
    const auto peak = std::max_element(r.fitted.deviatoric_stress_Pa.begin(), r.fitted.deviatoric_stress_Pa.end());
    s["eta"] = r.eta;
    s["mode"] = to_string(r.mode);
    s["dissipated_work_lab_J"] = r.dissipated_work_lab_J;
    s["dissipated_work_model_J"] = r.dissipated_work_model_J;
    s["relative_work_residual"] = r.relative_work_residual;
    s["plastic_work_model_J"] = r.plastic_work_model_J;
    s["work_note"] = kWorkNote;
    s["displacement_range_m"] = {r.displacement_range_m[0], r.displacement_range_m[1]};
    s["iterations"] = r.iterations;
    s["model_runs"] = r.model_runs;
    s["termination"] = r.termination;
    s["converged"] = r.converged;
    s["at_bound"] = r.at_bound;
    s["calibration_wall_time_s"] = r.wall_time_s;
    s["rms_q_error_kPa"] = 1e-3 * r.rms_q_error_Pa;
    s["peak_q_kPa"] = 1e-3 * *peak;
    s["axial_strain_at_peak"] = r.fitted.axial_strain[static_cast<std::size_t>(peak - r.fitted.deviatoric_stress_Pa.begin())];
    s["residual_q_kPa"] = 1e-3 * interpolate_linear(r.fitted.axial_strain, r.fitted.deviatoric_stress_Pa,
                                                    spec_.lab.axial_strain.back());
    s["phi_peak_deg"] = spec_.material.friction_peak_rad / kDegree;
    s["phi_peak_from_lab_peak"] = spec_.fitted_peak_friction;
    s["element_test_increments"] = spec_.test.increments;
    s["lab"] = {{"file", spec_.lab_file.string()},
                {"points", spec_.lab.axial_strain.size()},
                {"peak_q_kPa", 1e-3 * spec_.lab.peak_q_Pa()},
                {"axial_strain_at_peak", spec_.lab.axial_strain_at_peak()},
                {"axial_strain_range", {spec_.lab.axial_strain.front(), spec_.lab.axial_strain.back()}}};
    json scan = json::array();
    for (const WorkSample& w : r.scan) scan.push_back({{"eta", w.eta}, {"dissipated_work_J", w.work_J}});
    s["work_scan"] = scan;
    s["work_decreases_with_eta"] = r.work_decreases_with_eta;
    if (second) s["other_mode"] = fit_json(*second);
    json curves = json::array();
    for (const auto& [eta, curve] : compared)
      curves.push_back({{"eta", eta}, {"dissipated_work_J", work_of(curve)},
                        {"relative_to_lab", work_of(curve) / r.dissipated_work_lab_J - 1.0}});
    s["compared_eta"] = curves;
  }

  void write_tables(const CalibrationResult& r, const std::optional<CalibrationResult>& second,
                    const std::vector<std::pair<double, SpecimenCurve>>& compared, RunContext& context) const {
    const LabCurve& lab = spec_.lab;
    const TriaxialSpecimen& specimen = spec_.settings.specimen;
    const bool volumetric = !lab.volumetric_strain.empty();
    // One row per lab point: the lab and the fitted model side by side.
    std::vector<std::string> columns = {"axial_strain", "axial_displacement_m", "q_lab_kPa", "q_model_kPa",
                                        "axial_force_lab_N", "axial_force_model_N"};
    if (second) columns.emplace_back("q_other_mode_kPa");
    if (volumetric) columns.emplace_back("volumetric_strain_lab");
    columns.emplace_back("volumetric_strain_model");
    for (const auto& c : compared) columns.push_back("q_eta_" + format(c.first) + "_kPa");
    CsvTable table(columns);
    for (std::size_t i = 0; i < lab.axial_strain.size(); ++i) {
      const double e = lab.axial_strain[i];
      const double q_model = interpolate_linear(r.fitted.axial_strain, r.fitted.deviatoric_stress_Pa, e);
      std::vector<double> row = {e, e * specimen.height_m, 1e-3 * lab.deviatoric_stress_Pa[i], 1e-3 * q_model,
                                 lab.deviatoric_stress_Pa[i] * specimen.area_m2(), q_model * specimen.area_m2()};
      if (second)
        row.push_back(1e-3 * interpolate_linear(second->fitted.axial_strain, second->fitted.deviatoric_stress_Pa, e));
      if (volumetric) row.push_back(lab.volumetric_strain[i]);
      row.push_back(interpolate_linear(r.fitted.axial_strain, r.fitted.volumetric_strain, e));
      for (const auto& c : compared)
        row.push_back(1e-3 * interpolate_linear(c.second.axial_strain, c.second.deviatoric_stress_Pa, e));
      table.add_row(row);
    }
    table.write(context.out_dir / "history.csv");

    CsvTable model({"axial_strain", "q_kPa", "volumetric_strain", "axial_displacement_m", "axial_force_N"});
    for (std::size_t i = 0; i < r.fitted.axial_strain.size(); ++i)
      model.add_row({r.fitted.axial_strain[i], 1e-3 * r.fitted.deviatoric_stress_Pa[i], r.fitted.volumetric_strain[i],
                     r.fitted.axial_strain[i] * specimen.height_m, r.fitted.deviatoric_stress_Pa[i] * specimen.area_m2()});
    model.write(context.out_dir / "model_curve.csv");

    CsvTable scan({"eta", "dissipated_work_J", "relative_to_lab"});
    for (const WorkSample& w : r.scan) scan.add_row({w.eta, w.work_J, w.work_J / r.dissipated_work_lab_J - 1.0});
    scan.write(context.out_dir / "work_scan.csv");
  }

  void write_plots(const CalibrationResult& r, const std::optional<CalibrationResult>& second,
                   const std::vector<std::pair<double, SpecimenCurve>>& compared, RunContext& context) const {
    const fs::path plots = context.out_dir / "plots";
    fs::create_directories(plots);
    const LabCurve& lab = spec_.lab;
    const TriaxialSpecimen& specimen = spec_.settings.specimen;
    auto percent = [](const std::vector<double>& v) {
      std::vector<double> out;
      for (double x : v) out.push_back(100.0 * x);
      return out;
    };
    auto scaled = [](const std::vector<double>& v, double f) {
      std::vector<double> out;
      for (double x : v) out.push_back(f * x);
      return out;
    };
    const std::string mode = to_string(r.mode);
    // Fig. 3 of the paper: lab points, the fitted curve and the curves for η = 2.5 (blue) and 15 (red).
    const std::vector<const char*> colours = {"blue", "red", "orange", "purple", "brown"};
    Plot fig3{"Drained triaxial, σ3 = " + format(1e-3 * spec_.test.cell_pressure_Pa) + " kPa: " +
                  fs::path(lab.source).filename().string() + " and the SSMC",
              "axial strain ε_a (%)", "deviatoric stress q (kPa)", {}};
    fig3.series.push_back({percent(lab.axial_strain), scaled(lab.deviatoric_stress_Pa, 1e-3), "lab",
                           "points pt 7 ps 0.8 lc rgb 'black'"});
    fig3.series.push_back({percent(r.fitted.axial_strain), scaled(r.fitted.deviatoric_stress_Pa, 1e-3),
                           "fit by " + mode + ": η = " + format(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
    if (second)
      fig3.series.push_back({percent(second->fitted.axial_strain), scaled(second->fitted.deviatoric_stress_Pa, 1e-3),
                             "fit by " + to_string(second->mode) + ": η = " + format(second->eta, 3),
                             "lines lw 2 dashtype 2 lc rgb 'dark-green'"});
    for (std::size_t k = 0; k < compared.size(); ++k)
      fig3.series.push_back({percent(compared[k].second.axial_strain),
                             scaled(compared[k].second.deviatoric_stress_Pa, 1e-3),
                             "η = " + format(compared[k].first, 3), std::string("lines lw 2 lc rgb '") +
                                                                      colours[k % colours.size()] + "'"});
    write_png(fig3, plots / "fig3_q_axial_strain.png");

    Plot force{"Force–displacement: the areas matched (W_{lab} = " + format(r.dissipated_work_lab_J) +
                   " J, W_{model} = " + format(r.dissipated_work_model_J) + " J)",
               "axial displacement δ = ε_a·H (mm)", "axial force F = q·A (N)", {}};
    force.series.push_back({scaled(lab.axial_strain, 1e3 * specimen.height_m),
                            scaled(lab.deviatoric_stress_Pa, specimen.area_m2()), "lab",
                            "points pt 7 ps 0.8 lc rgb 'black'"});
    force.series.push_back({scaled(r.fitted.axial_strain, 1e3 * specimen.height_m),
                            scaled(r.fitted.deviatoric_stress_Pa, specimen.area_m2()),
                            "model, η = " + format(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
    Plot volume{"Volumetric strain (compression positive)", "axial strain ε_a (%)", "ε_v (%)", {}};
    if (!lab.volumetric_strain.empty())
      volume.series.push_back({percent(lab.axial_strain), percent(lab.volumetric_strain), "lab",
                               "points pt 7 ps 0.8 lc rgb 'black'"});
    volume.series.push_back({percent(r.fitted.axial_strain), percent(r.fitted.volumetric_strain),
                             "model, η = " + format(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
    write_png_stack({force, volume}, plots / "force_displacement_volumetric.png");

    Plot scan{"Dissipated work against η (the criterion of the fit)", "η", "W = ∫F dδ (J)", {}, true, false};
    Series model{{}, {}, "W_{model}(η)", "linespoints pt 7 lc rgb 'dark-green'"};
    for (const WorkSample& w : r.scan) {
      model.x.push_back(w.eta);
      model.y.push_back(w.work_J);
    }
    scan.series.push_back(model);
    scan.series.push_back({{spec_.settings.eta_min, spec_.settings.eta_max},
                           {r.dissipated_work_lab_J, r.dissipated_work_lab_J}, "W_{lab}", "lines lc rgb 'black'"});
    scan.series.push_back({{r.eta}, {r.dissipated_work_model_J}, "fit: η = " + format(r.eta, 4),
                           "points pt 6 ps 2 lw 2 lc rgb 'red'"});
    write_png(scan, plots / "work_against_eta.png");
  }

  CalibrationSpec spec_;
};

}  // namespace

std::unique_ptr<Job> make_calibration_job(SceneReader& scene, const fs::path& scene_dir) {
  CalibrationSpec spec;
  const std::string file = scene.text("lab_curve_csv");
  spec.lab_file = (fs::path(file).is_absolute() ? fs::path(file) : scene_dir / file).lexically_normal();
  try {
    spec.lab = read_lab_curve(spec.lab_file);
  } catch (const SceneError& e) {
    throw SceneError(std::string("lab_curve_csv: ") + e.what());
  }

  SceneReader material_reader = scene.object("material", true);
  const MaterialSpec material = read_material(material_reader, DensityRule::not_used);
  if (material.model != "ssmc")
    scene.fail("material.model", "must be ssmc: the calibration fits its softening factor eta");
  spec.material = std::get<StrainSofteningParameters>(material.parameters);

  spec.settings.mode = mode_named(scene.choice("mode", {"dissipated_work", "curve_least_squares"}, "dissipated_work"));
  spec.compare_modes = scene.boolean("compare_modes", true);
  spec.settings.eta_min = scene.number("eta_min", Range::positive(1e4), 0.1);
  spec.settings.eta_max = scene.number("eta_max", Range::positive(1e4), 500.0);
  if (!(spec.settings.eta_max > spec.settings.eta_min))
    scene.fail("eta_max", "must be above eta_min (" + format(spec.settings.eta_min) + ")");
  spec.eta_start = spec.material.softening_factor;
  if (!(spec.eta_start >= spec.settings.eta_min && spec.eta_start <= spec.settings.eta_max))
    scene.fail("material.eta", "is where the fit starts: must lie in [eta_min, eta_max] = [" +
                                   format(spec.settings.eta_min) + ", " + format(spec.settings.eta_max) + "]");
  spec.settings.eta_start = spec.eta_start;
  spec.compare_eta = scene.optional_numbers("compare_eta", Range::positive(1e4), 0, 5).value_or(std::vector<double>{2.5, 15.0});

  spec.test.cell_pressure_Pa = 1e3 * scene.number("cell_pressure_kPa", Range::positive(1e7, "kPa"), 1.72);
  SceneReader specimen = scene.object("specimen");
  spec.test.specimen.height_m = specimen.number("height_m", Range::positive(100.0, "m"), 0.15);
  spec.test.specimen.diameter_m = specimen.number("diameter_m", Range::positive(100.0, "m"), 0.07);
  specimen.finish("specimen (height_m, diameter_m)");
  spec.settings.specimen = spec.test.specimen;
  spec.test.increments = scene.integer("increments", 10, 1'000'000, 1000);
  spec.test.strain_rate_per_s = scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4);
  spec.test.axial_strain_max = spec.lab.axial_strain.back();  // the model covers the lab's range exactly
  spec.settings.scan_points = scene.integer("scan_points", 2, 1000, 9);
  spec.settings.max_iterations = scene.integer("max_iterations", 1, 10000, 50);

  spec.fitted_peak_friction = scene.boolean("fit_peak_friction", false);
  if (spec.fitted_peak_friction) {
    if (spec.material.cohesion_peak_Pa != 0.0)
      scene.fail("fit_peak_friction", "assumes c' = 0 (q_peak = σ3 (Nφ − 1)); the material has c_peak_kPa > 0");
    const double phi = peak_friction_from_peak_q(spec.lab.peak_q_Pa(), spec.test.cell_pressure_Pa);
    if (!(phi > spec.material.friction_residual_rad))
      scene.fail("fit_peak_friction", "the lab peak q = " + format(1e-3 * spec.lab.peak_q_Pa()) + " kPa implies φ'_p = " +
                                          format(phi / kDegree) + "°, not above phi_residual_deg = " +
                                          format(spec.material.friction_residual_rad / kDegree) + "°");
    spec.material.friction_peak_rad = phi;
  }
  scene.finish("a calibration scene");
  return std::make_unique<CalibrationJob>(std::move(spec));
}

}  // namespace ffp
