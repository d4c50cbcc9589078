#include "drivers/app/calibration_output.hpp"

#include <algorithm>

#include "drivers/output/csv_writer.hpp"
#include "drivers/scene/material_scene.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

const char* kWorkNote =
    "dissipated work = ∫F dδ (F = q·A, δ = ε_a·H), trapezoid rule on each curve's own points (the lab's rows; "
    "the model's increments), both over the lab's displacement range. It is the piston's deviatoric work: it "
    "differs from the model's plastic work (what the law dissipates) by the elastic energy still stored and by "
    "the cell pressure's work σ3·ΔV on the specimen's volume change";

json specimen_json(const CalibrationScene& scene, const CalibrationOutcome& o) {
  const CalibrationResult& r = o.result;
  const TriaxialSpecimen& size = scene.test.specimen;
  if (scene.specimen == SpecimenType::element)
    return {{"type", to_string(scene.specimen)},
            {"height_m", size.height_m},
            {"diameter_m", size.diameter_m},
            {"increments", scene.test.increments}};
  const MpmTriaxialConfig& m = scene.mpm;
  json s = {{"type", to_string(scene.specimen)},
            {"height_m", size.height_m},
            {"diameter_m", size.diameter_m},
            {"cell_m", m.cell_m},
            {"cells_r", o.grid.cells_r},
            {"cells_z", o.grid.cells_z},
            {"cell_r_m", o.grid.cell_r_m},
            {"cell_z_m", o.grid.cell_z_m},
            {"particles", o.grid.particles},
            {"platens", to_string(m.platens)},
            {"platen_velocity_m_s", m.platen_velocity_m_s},
            {"ramp_time_s", o.grid.ramp_time_s},
            {"shape_function", to_string(m.shape_function)},
            {"courant", m.courant},
            {"flip_fraction", m.flip_fraction}};
  double seconds = 0.0, slowest = 0.0;
  long steps = 0;
  for (const MpmRunRecord& k : o.runs) {
    seconds += k.wall_time_s;
    slowest = std::max(slowest, k.wall_time_s);
    steps += k.steps;
  }
  const double n = static_cast<double>(o.runs.size());
  s["runs"] = {{"count", o.runs.size()},
               {"steps", steps},
               {"wall_time_s", seconds},
               {"seconds_per_run", seconds / n},
               {"slowest_run_s", slowest}};
  // The fitted η's run: the calibration evaluates it last before the comparisons.
  const auto fitted =
      std::find_if(o.runs.rbegin(), o.runs.rend(), [&](const MpmRunRecord& k) { return k.eta == r.eta; });
  if (fitted != o.runs.rend())
    s["fitted_run"] = {{"steps", fitted->steps},
                       {"wall_time_s", fitted->wall_time_s},
                       {"platen_force_imbalance", fitted->platen_force_imbalance},
                       {"bulge_at_peak", {fitted->bulge_at_peak[0], fitted->bulge_at_peak[1]}},
                       {"bulge_at_end", {fitted->bulge_at_end[0], fitted->bulge_at_end[1]}},
                       {"work_every_step_J", fitted->work_steps_J},
                       {"work_output_curve_J", fitted->work_curve_J},
                       {"piston_work_J", fitted->work_piston_J},
                       {"wall_clamps", fitted->wall_clamps}};
  return s;
}

double work_of(const CalibrationScene& scene, const SpecimenCurve& c) {
  return dissipated_work_J(c.axial_strain, c.deviatoric_stress_Pa, scene.settings.specimen,
                           scene.lab.axial_strain.front(), scene.lab.axial_strain.back());
}

json fit_json(const CalibrationResult& r) {
  return {{"mode", to_string(r.mode)},
          {"eta", r.eta},
          {"dissipated_work_model_J", r.dissipated_work_model_J},
          {"relative_work_residual", r.relative_work_residual},
          {"plastic_work_model_J", r.plastic_work_model_J},
          {"rms_q_error_kPa", 1e-3 * r.rms_q_error_Pa},
          {"iterations", r.iterations},
          {"model_runs", r.model_runs},
          {"reused_runs", r.reused_runs},
          {"termination", r.termination},
          {"converged", r.converged},
          {"at_bound", r.at_bound},
          {"wall_time_s", r.wall_time_s}};
}

}  // namespace

void write_calibration_summary(const CalibrationScene& scene, const CalibrationOutcome& o, json& s) {
  const CalibrationResult& r = o.result;
  const std::optional<CalibrationResult>& second = o.second;
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
  s["reused_runs"] = r.reused_runs;
  s["specimen_runs"] = o.specimen_runs;
  s["concurrent_runs"] = o.concurrent_runs;
  s["derivative"] = to_string(scene.settings.derivative);
  s["fit_start"] = to_string(scene.fit_start);
  s["scan"] = to_string(scene.settings.scan);
  s["termination"] = r.termination;
  s["converged"] = r.converged;
  s["at_bound"] = r.at_bound;
  s["calibration_wall_time_s"] = r.wall_time_s;
  s["rms_q_error_kPa"] = 1e-3 * r.rms_q_error_Pa;
  s["peak_q_kPa"] = 1e-3 * *peak;
  s["axial_strain_at_peak"] =
      r.fitted.axial_strain[static_cast<std::size_t>(peak - r.fitted.deviatoric_stress_Pa.begin())];
  s["residual_q_kPa"] =
      1e-3 * interpolate_linear(r.fitted.axial_strain, r.fitted.deviatoric_stress_Pa, scene.lab.axial_strain.back());
  s["phi_peak_deg"] = scene.material.friction_peak_rad / kDegree;
  s["phi_peak_from_lab_peak"] = scene.fitted_peak_friction;
  s["specimen"] = specimen_json(scene, o);
  if (scene.specimen == SpecimenType::element) s["element_test_increments"] = scene.test.increments;
  s["lab"] = {{"file", scene.lab_file.string()},
              {"points", scene.lab.axial_strain.size()},
              {"peak_q_kPa", 1e-3 * scene.lab.peak_q_Pa()},
              {"axial_strain_at_peak", scene.lab.axial_strain_at_peak()},
              {"axial_strain_range", {scene.lab.axial_strain.front(), scene.lab.axial_strain.back()}}};
  json scan = json::array();
  for (const WorkSample& w : r.scan) scan.push_back({{"eta", w.eta}, {"dissipated_work_J", w.work_J}});
  s["work_scan"] = scan;
  s["work_decreases_with_eta"] = r.work_decreases_with_eta;
  if (second) s["other_mode"] = fit_json(*second);
  json curves = json::array();
  for (const auto& [eta, curve] : o.compared)
    curves.push_back({{"eta", eta},
                      {"dissipated_work_J", work_of(scene, curve)},
                      {"relative_to_lab", work_of(scene, curve) / r.dissipated_work_lab_J - 1.0}});
  s["compared_eta"] = curves;
}

void write_calibration_tables(const CalibrationScene& scene, const CalibrationOutcome& o, const fs::path& out_dir) {
  const CalibrationResult& r = o.result;
  const std::optional<CalibrationResult>& second = o.second;
  const LabCurve& lab = scene.lab;
  const TriaxialSpecimen& specimen = scene.settings.specimen;
  const bool volumetric = !lab.volumetric_strain.empty();
  // One row per lab point: the lab and the fitted model side by side.
  std::vector<std::string> columns = {"axial_strain", "axial_displacement_m", "q_lab_kPa",
                                      "q_model_kPa",  "axial_force_lab_N",    "axial_force_model_N"};
  if (second) columns.emplace_back("q_other_mode_kPa");
  if (volumetric) columns.emplace_back("volumetric_strain_lab");
  columns.emplace_back("volumetric_strain_model");
  for (const auto& c : o.compared) columns.push_back("q_eta_" + format_significant(c.first) + "_kPa");
  CsvTable table(columns);
  for (std::size_t i = 0; i < lab.axial_strain.size(); ++i) {
    const double e = lab.axial_strain[i];
    const double q_model = interpolate_linear(r.fitted.axial_strain, r.fitted.deviatoric_stress_Pa, e);
    std::vector<double> row = {e,
                               e * specimen.height_m,
                               1e-3 * lab.deviatoric_stress_Pa[i],
                               1e-3 * q_model,
                               lab.deviatoric_stress_Pa[i] * specimen.area_m2(),
                               q_model * specimen.area_m2()};
    if (second)
      row.push_back(1e-3 * interpolate_linear(second->fitted.axial_strain, second->fitted.deviatoric_stress_Pa, e));
    if (volumetric) row.push_back(lab.volumetric_strain[i]);
    row.push_back(interpolate_linear(r.fitted.axial_strain, r.fitted.volumetric_strain, e));
    for (const auto& c : o.compared)
      row.push_back(1e-3 * interpolate_linear(c.second.axial_strain, c.second.deviatoric_stress_Pa, e));
    table.add_row(row);
  }
  table.write(out_dir / "history.csv");

  CsvTable model({"axial_strain", "q_kPa", "volumetric_strain", "axial_displacement_m", "axial_force_N"});
  for (std::size_t i = 0; i < r.fitted.axial_strain.size(); ++i)
    model.add_row({r.fitted.axial_strain[i], 1e-3 * r.fitted.deviatoric_stress_Pa[i], r.fitted.volumetric_strain[i],
                   r.fitted.axial_strain[i] * specimen.height_m,
                   r.fitted.deviatoric_stress_Pa[i] * specimen.area_m2()});
  model.write(out_dir / "model_curve.csv");

  CsvTable scan({"eta", "dissipated_work_J", "relative_to_lab"});
  for (const WorkSample& w : r.scan) scan.add_row({w.eta, w.work_J, w.work_J / r.dissipated_work_lab_J - 1.0});
  scan.write(out_dir / "work_scan.csv");
}

void write_calibration_plots(const CalibrationScene& scene, const CalibrationOutcome& o, const fs::path& out_dir) {
  const CalibrationResult& r = o.result;
  const std::optional<CalibrationResult>& second = o.second;
  const fs::path plots = out_dir / "plots";
  fs::create_directories(plots);
  const LabCurve& lab = scene.lab;
  const TriaxialSpecimen& specimen = scene.settings.specimen;
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
  Plot fig3{"Drained triaxial, σ3 = " + format_significant(1e-3 * scene.test.cell_pressure_Pa) +
                " kPa: " + fs::path(lab.source).filename().string() + " and the SSMC",
            "axial strain ε_a (%)",
            "deviatoric stress q (kPa)",
            {}};
  fig3.series.push_back(
      {percent(lab.axial_strain), scaled(lab.deviatoric_stress_Pa, 1e-3), "lab", "points pt 7 ps 0.8 lc rgb 'black'"});
  fig3.series.push_back({percent(r.fitted.axial_strain), scaled(r.fitted.deviatoric_stress_Pa, 1e-3),
                         "fit by " + mode + ": η = " + format_significant(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
  if (second)
    fig3.series.push_back({percent(second->fitted.axial_strain), scaled(second->fitted.deviatoric_stress_Pa, 1e-3),
                           "fit by " + to_string(second->mode) + ": η = " + format_significant(second->eta, 3),
                           "lines lw 2 dashtype 2 lc rgb 'dark-green'"});
  for (std::size_t k = 0; k < o.compared.size(); ++k)
    fig3.series.push_back({percent(o.compared[k].second.axial_strain),
                           scaled(o.compared[k].second.deviatoric_stress_Pa, 1e-3),
                           "η = " + format_significant(o.compared[k].first, 3),
                           std::string("lines lw 2 lc rgb '") + colours[k % colours.size()] + "'"});
  write_png(fig3, plots / "fig3_q_axial_strain.png");

  Plot force{"Force–displacement: the areas matched (W_{lab} = " + format_significant(r.dissipated_work_lab_J) +
                 " J, W_{model} = " + format_significant(r.dissipated_work_model_J) + " J)",
             "axial displacement δ = ε_a·H (mm)",
             "axial force F = q·A (N)",
             {}};
  force.series.push_back({scaled(lab.axial_strain, 1e3 * specimen.height_m),
                          scaled(lab.deviatoric_stress_Pa, specimen.area_m2()), "lab",
                          "points pt 7 ps 0.8 lc rgb 'black'"});
  force.series.push_back({scaled(r.fitted.axial_strain, 1e3 * specimen.height_m),
                          scaled(r.fitted.deviatoric_stress_Pa, specimen.area_m2()),
                          "model, η = " + format_significant(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
  Plot volume{"Volumetric strain (compression positive)", "axial strain ε_a (%)", "ε_v (%)", {}};
  if (!lab.volumetric_strain.empty())
    volume.series.push_back(
        {percent(lab.axial_strain), percent(lab.volumetric_strain), "lab", "points pt 7 ps 0.8 lc rgb 'black'"});
  volume.series.push_back({percent(r.fitted.axial_strain), percent(r.fitted.volumetric_strain),
                           "model, η = " + format_significant(r.eta, 3), "lines lw 3 lc rgb 'dark-green'"});
  write_png_stack({force, volume}, plots / "force_displacement_volumetric.png");

  Plot scan{"Dissipated work against η (the criterion of the fit)", "η", "W = ∫F dδ (J)", {}, true, false};
  Series model{{}, {}, "W_{model}(η)", "linespoints pt 7 lc rgb 'dark-green'"};
  for (const WorkSample& w : r.scan) {
    model.x.push_back(w.eta);
    model.y.push_back(w.work_J);
  }
  scan.series.push_back(model);
  scan.series.push_back({{scene.settings.eta_min, scene.settings.eta_max},
                         {r.dissipated_work_lab_J, r.dissipated_work_lab_J},
                         "W_{lab}",
                         "lines lc rgb 'black'"});
  scan.series.push_back({{r.eta},
                         {r.dissipated_work_model_J},
                         "fit: η = " + format_significant(r.eta, 4),
                         "points pt 6 ps 2 lw 2 lc rgb 'red'"});
  write_png(scan, plots / "work_against_eta.png");
}

}  // namespace ffp
