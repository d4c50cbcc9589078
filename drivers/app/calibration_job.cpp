/// The `calibration` scene kind: the SSMC softening factor η fitted to a lab
/// triaxial curve so that the numerical triaxial dissipates the lab's work
/// (paper section 4.2, Fig. 3; calibration/softening_calibration.hpp).
///
/// Scene (geotechnical units, compression positive):
///   lab_curve_csv        the lab curve, relative to the scene file (data/lab/README.md)
///   material             an ssmc material (no density: weightless specimen); its eta
///                        is where the fit starts
///   mode                 dissipated_work (the paper's, default) | curve_least_squares
///   compare_modes        also fit with the other criterion, reported under other_mode (default
///                        true; false with an mpm specimen, where it doubles the cost)
///   fit_peak_friction    replace phi_peak_deg by the lab peak's, asin((N−1)/(N+1)),
///                        N = 1 + q_peak/σ3 (c' = 0 only; default false)
///   eta_min, eta_max     bounds of η (default 0.1, 500)
///   compare_eta          η of the extra curves in the figure (default the paper's [2.5, 15])
///   cell_pressure_kPa    σ3 (default 1.72)
///   specimen             the numerical triaxial, {type, height_m: 0.15, diameter_m: 0.07, ...}:
///     type: element      (default) the single-point element test (drivers/triaxial_test.hpp),
///                        with the top-level keys
///       increments         over the lab's strain range (default 1000)
///       strain_rate_per_s  only the rate law sees it (default 1e-4)
///     type: mpm          the meshed axisymmetric MPM specimen (calibration/mpm_triaxial_specimen.hpp),
///                        whose own keys sit in the specimen object:
///       cell_m              nominal cell size (default 0.01, the paper's FFP mesh)
///       platen_velocity_m_s after the ramp (default 0.01: halving it moves W by < 1 %)
///       platens             rough (default) | smooth
///       shape_function      gimp (default) | linear
///       courant             (default 0.9)
///       flip_fraction       FLIP share of the particle velocity update (default 0.9)
///       particles_per_cell  per direction (default 2)
///       density_kg_m3       sets the time scale only (default 14.6 kN/m³ / g)
///       output_strain_step  ε_a between the curve's points (default 0.001)
///       radial_margin       empty grid beyond the radius, fraction of it (default 0.5)
///                        Each key belongs to one type: an element scene with mpm keys (or
///                        the other way round) is bad input.
///   scan_points          log-spaced η of the W(η) check (default 9)
///   max_iterations       Ceres iterations (default 50)
///   derivative_step_ln_eta  central-difference step of the fit in ln η (default: element
///                        1e-4; mpm 0.1 — the MPM's W jitters by up to ±0.2 % between
///                        neighbouring η at 0.5 cm, and the slope must stand above that)
///   parameter_tolerance  Ceres stops when ln η changes by less (relative; element 1e-8, mpm 1e-4)
///   work_tolerance       dissipated_work: stop once |W_model/W_lab − 1| is below (element 0:
///                        off; mpm 2e-4). Set it near the specimen's jitter in W: tighter
///                        costs runs, looser costs η where W is flat in η (at 2 cm
///                        1e-3 of W is ±20 % of η)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>

#include "calibration/lab_curve.hpp"
#include "calibration/mpm_triaxial_specimen.hpp"
#include "calibration/softening_calibration.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/scene/material_scene.hpp"
#include "mpm/simulation.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

/// The MPM specimen's size before it is built: the grid spans the specimen and
/// its radial margin (plus a platen cell above and below), the particles fill
/// the specimen at particles_per_cell² per cell.
mpm::ModelSize specimen_size(const MpmTriaxialConfig& m) {
  const double radius = 0.5 * m.specimen.diameter_m;
  const double cells_r = std::ceil(radius * (1.0 + m.radial_margin) / m.cell_m) + 1.0;
  const double cells_z = std::ceil(m.specimen.height_m / m.cell_m) + 2.0;
  const double specimen_cells = std::ceil(radius / m.cell_m) * std::ceil(m.specimen.height_m / m.cell_m);
  mpm::ModelSize size;
  size.nodes = static_cast<std::size_t>(std::min(1e15, (cells_r + 1.0) * (cells_z + 1.0)));
  size.particles = static_cast<std::size_t>(
      std::min(1e15, specimen_cells * m.particles_per_cell * m.particles_per_cell));
  return size;
}


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

enum class SpecimenType { element, mpm };

struct CalibrationSpec {
  fs::path lab_file;
  LabCurve lab;
  StrainSofteningParameters material;
  bool fitted_peak_friction = false;
  double eta_start = 8.0;
  SpecimenType specimen = SpecimenType::element;
  TriaxialTestConfig test;  ///< the element test (σ3 and the specimen's size serve both types)
  MpmTriaxialConfig mpm;    ///< the MPM specimen (type mpm)
  CalibrationSettings settings;
  bool compare_modes = true;
  std::vector<double> compare_eta;
};

/// What one MPM specimen run cost and how it went (its curve is the calibration's).
struct MpmRunRecord {
  double eta = 0.0;
  long steps = 0;
  double wall_time_s = 0.0;
  double platen_force_imbalance = 0.0;
  double bulge_at_peak[2] = {0.0, 0.0};
  double bulge_at_end[2] = {0.0, 0.0};
  double work_steps_J = 0.0, work_curve_J = 0.0, work_piston_J = 0.0;
  long wall_clamps = 0;
};

class CalibrationJob : public Job {
 public:
  explicit CalibrationJob(CalibrationSpec spec) : spec_(std::move(spec)) {}

  void describe(std::ostream& out) const override {
    out << "calibration: η of the ssmc by " << to_string(spec_.settings.mode) << " on " << spec_.lab_file.string()
        << " (" << spec_.lab.axial_strain.size() << " points, ε_a to " << spec_.lab.axial_strain.back()
        << "), η in [" << spec_.settings.eta_min << ", " << spec_.settings.eta_max << "], ";
    if (spec_.specimen == SpecimenType::element) {
      out << "element test with " << spec_.test.increments << " increments\n";
    } else {
      const MpmTriaxialConfig& m = spec_.mpm;
      out << "MPM specimen with " << m.cell_m << " m cells (" << to_string(m.platens) << " platens at "
          << m.platen_velocity_m_s << " m/s)\n";
      describe_memory(out, specimen_size(m));
    }
  }

  void run(RunContext& context) override {
    const NumericalTriaxial triaxial = spec_.specimen == SpecimenType::element
                                           ? element_test_triaxial(spec_.material, spec_.test)
                                           : mpm_triaxial_specimen(spec_.material, spec_.mpm,
                                                                   [this](double eta, const MpmTriaxialResult& r) {
                                                                     record(eta, r);
                                                                     // Ctrl-C waits for one run at most (≤ ~15 s at 0.5 cm).
                                                                     throw_if_interrupted();
                                                                   });
    const CalibrationResult result = calibrate(triaxial, spec_.settings);
    throw_if_interrupted();
    std::optional<CalibrationResult> second;
    if (spec_.compare_modes) {
      CalibrationSettings s = spec_.settings;
      s.mode = other(s.mode);
      second = calibrate(triaxial, s);
    }
    std::vector<std::pair<double, SpecimenCurve>> compared;
    for (double eta : spec_.compare_eta) compared.emplace_back(eta, run_specimen(triaxial, eta));
    if (spec_.specimen == SpecimenType::element) {
      context.steps = static_cast<long>(result.model_runs + (second ? second->model_runs : 0) +
                                        static_cast<int>(compared.size())) *
                      spec_.test.increments;
    } else {
      context.steps = 0;
      for (const MpmRunRecord& r : runs_) context.steps += r.steps;
    }

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
    } catch (const mpm::StepFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) + "): the MPM specimen failed: " +
                       e.what());
    }
  }

  static SpecimenCurve run_specimen(const NumericalTriaxial& triaxial, double eta) {
    try {
      return triaxial(eta);
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure("calibration: the element test with η = " + format(eta) + " failed: " + e.what());
    } catch (const mpm::StepFailure& e) {
      throw RunFailure("calibration: the MPM specimen with η = " + format(eta) + " failed: " + e.what());
    }
  }

  void record(double eta, const MpmTriaxialResult& r) {
    MpmRunRecord k;
    k.eta = eta;
    k.steps = r.steps;
    k.wall_time_s = r.wall_time_s;
    k.platen_force_imbalance = r.platen_force_imbalance;
    k.bulge_at_peak[0] = r.bulge_at_peak_min;
    k.bulge_at_peak[1] = r.bulge_at_peak_max;
    k.bulge_at_end[0] = r.bulge_at_end_min;
    k.bulge_at_end[1] = r.bulge_at_end_max;
    k.work_steps_J = r.work_steps_J;
    k.work_curve_J = r.work_curve_J;
    k.work_piston_J = r.work_piston_J;
    k.wall_clamps = r.wall_clamps;
    runs_.push_back(k);
    grid_ = {r.cells_r, r.cells_z, r.cell_r_m, r.cell_z_m, r.particles, r.ramp_time_s};
  }

  json specimen_json(const CalibrationResult& r) const {
    const TriaxialSpecimen& size = spec_.test.specimen;
    if (spec_.specimen == SpecimenType::element)
      return {{"type", "element"}, {"height_m", size.height_m}, {"diameter_m", size.diameter_m},
              {"increments", spec_.test.increments}};
    const MpmTriaxialConfig& m = spec_.mpm;
    json s = {{"type", "mpm"},
              {"height_m", size.height_m},
              {"diameter_m", size.diameter_m},
              {"cell_m", m.cell_m},
              {"cells_r", grid_.cells_r},
              {"cells_z", grid_.cells_z},
              {"cell_r_m", grid_.cell_r_m},
              {"cell_z_m", grid_.cell_z_m},
              {"particles", grid_.particles},
              {"platens", to_string(m.platens)},
              {"platen_velocity_m_s", m.platen_velocity_m_s},
              {"ramp_time_s", grid_.ramp_time_s},
              {"shape_function", m.shape_function == mpm::ShapeFunction::gimp ? "gimp" : "linear"},
              {"courant", m.courant},
              {"flip_fraction", m.flip_fraction}};
    double seconds = 0.0, slowest = 0.0;
    long steps = 0;
    for (const MpmRunRecord& k : runs_) {
      seconds += k.wall_time_s;
      slowest = std::max(slowest, k.wall_time_s);
      steps += k.steps;
    }
    const double n = static_cast<double>(runs_.size());
    s["runs"] = {{"count", runs_.size()},
                 {"steps", steps},
                 {"wall_time_s", seconds},
                 {"seconds_per_run", seconds / n},
                 {"slowest_run_s", slowest}};
    // The fitted η's run: the calibration evaluates it last before the comparisons.
    const auto fitted = std::find_if(runs_.rbegin(), runs_.rend(), [&](const MpmRunRecord& k) { return k.eta == r.eta; });
    if (fitted != runs_.rend())
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
    s["specimen"] = specimen_json(r);
    if (spec_.specimen == SpecimenType::element) s["element_test_increments"] = spec_.test.increments;
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
  std::vector<MpmRunRecord> runs_;
  struct {
    int cells_r = 0, cells_z = 0;
    double cell_r_m = 0.0, cell_z_m = 0.0;
    std::size_t particles = 0;
    double ramp_time_s = 0.0;
  } grid_;
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
  spec.specimen = specimen.choice("type", {"element", "mpm"}, "element") == "mpm" ? SpecimenType::mpm
                                                                                 : SpecimenType::element;
  const bool mpm_specimen = spec.specimen == SpecimenType::mpm;
  spec.test.specimen.height_m = specimen.number("height_m", Range::positive(100.0, "m"), 0.15);
  spec.test.specimen.diameter_m = specimen.number("diameter_m", Range::positive(100.0, "m"), 0.07);
  spec.settings.specimen = spec.test.specimen;
  spec.test.axial_strain_max = spec.lab.axial_strain.back();  // the model covers the lab's range exactly
  if (mpm_specimen) {
    MpmTriaxialConfig& m = spec.mpm;
    m.specimen = spec.test.specimen;
    m.cell_pressure_Pa = spec.test.cell_pressure_Pa;
    m.axial_strain_max = spec.test.axial_strain_max;
    m.cell_m = specimen.number("cell_m", Range::positive(0.5 * m.specimen.height_m, "m (at most half the height)"), 0.01);
    m.platen_velocity_m_s = specimen.number("platen_velocity_m_s", Range::positive(10.0, "m/s"), 0.01);
    m.platens = specimen.choice("platens", {"rough", "smooth"}, "rough") == "rough" ? PlatenFriction::rough
                                                                                   : PlatenFriction::smooth;
    m.shape_function = specimen.choice("shape_function", {"gimp", "linear"}, "gimp") == "gimp"
                           ? mpm::ShapeFunction::gimp
                           : mpm::ShapeFunction::linear;
    m.courant = specimen.number("courant", Range::positive(1.0), 0.9);
    m.flip_fraction = specimen.number("flip_fraction", Range::closed(0.0, 1.0), 0.9);
    m.particles_per_cell = specimen.integer("particles_per_cell", 1, 8, 2);
    m.density_kg_m3 = specimen.number("density_kg_m3", Range::positive(1e5, "kg/m³"), 14.6e3 / 9.81);
    m.output_strain_step = specimen.number(
        "output_strain_step", Range::positive(0.5 * m.axial_strain_max, "(at most half the lab's last strain)"), 1e-3);
    m.radial_margin = specimen.number("radial_margin", Range::positive(10.0), 0.5);
    require_fits_in_memory(specimen_size(m), "specimen.cell_m",
                           "use a larger specimen.cell_m or fewer specimen.particles_per_cell");
    specimen.finish("an mpm specimen (type, height_m, diameter_m, cell_m, platen_velocity_m_s, platens, "
                    "shape_function, courant, flip_fraction, particles_per_cell, density_kg_m3, output_strain_step, "
                    "radial_margin)");
    for (const char* key : {"increments", "strain_rate_per_s"})
      if (scene.has(key))
        scene.fail(key, "belongs to the element test; an mpm specimen (specimen.type = mpm) is resolved by its "
                        "cell_m and time step, and strained by its platen_velocity_m_s");
  } else {
    specimen.finish("an element specimen (type, height_m, diameter_m; the MPM keys need \"type\": \"mpm\")");
    spec.test.increments = scene.integer("increments", 10, 1'000'000, 1000);
    spec.test.strain_rate_per_s = scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4);
  }
  // The second fit doubles the cost: on by default only for the (cheap) element test.
  spec.compare_modes = scene.boolean("compare_modes", !mpm_specimen);
  spec.settings.scan_points = scene.integer("scan_points", 2, 1000, 9);
  spec.settings.max_iterations = scene.integer("max_iterations", 1, 10000, 50);
  spec.settings.derivative_step =
      scene.number("derivative_step_ln_eta", Range::positive(0.5), mpm_specimen ? 0.1 : 1e-4);
  spec.settings.parameter_tolerance =
      scene.number("parameter_tolerance", Range::open(0.0, 1.0), mpm_specimen ? 1e-4 : 1e-8);
  spec.settings.work_tolerance =
      scene.number("work_tolerance", Range::half_open(0.0, 1.0), mpm_specimen ? 2e-4 : 0.0);

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
