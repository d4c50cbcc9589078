#include "drivers/app/calibration_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "drivers/app/memory_check.hpp"
#include "drivers/scene/material_scene.hpp"

namespace ffp {

namespace fs = std::filesystem;

std::string to_string(SpecimenType type) {
  return std::string(std::ranges::find(kSpecimenTypeNames, type, &SpecimenTypeName::first)->second);
}

std::string to_string(FitStart start) {
  return std::string(std::ranges::find(kFitStartNames, start, &FitStartName::first)->second);
}

std::string format_significant(double v, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

/// The grid spans the specimen and its radial margin (plus a platen cell above
/// and below), the particles fill the specimen at particles_per_cell² per cell.
mpm::ModelSize specimen_size(const MpmTriaxialConfig& m) {
  const double radius = 0.5 * m.specimen.diameter_m;
  const double cells_r = std::ceil(radius * (1.0 + m.radial_margin) / m.cell_m) + 1.0;
  const double cells_z = std::ceil(m.specimen.height_m / m.cell_m) + 2.0;
  const double specimen_cells = std::ceil(radius / m.cell_m) * std::ceil(m.specimen.height_m / m.cell_m);
  mpm::ModelSize size;
  size.nodes = static_cast<std::size_t>(std::min(1e15, (cells_r + 1.0) * (cells_z + 1.0)));
  size.particles =
      static_cast<std::size_t>(std::min(1e15, specimen_cells * m.particles_per_cell * m.particles_per_cell));
  return size;
}

namespace {

/// The meshed specimen's own keys (specimen.type = mpm).
void read_mpm_specimen(SceneReader& specimen, MpmTriaxialConfig& m) {
  const std::string mpm = "type = mpm";
  // 0.01 m, the paper's FFP mesh; a platen at 0.01 m/s, as halving it moves W by < 1 %.
  m.cell_m = specimen.number("cell_m", Range::positive(0.5 * m.specimen.height_m, "m", "at most half the height"), 0.01,
                             Doc("the nominal cell size").within("(0, height_m / 2]").only_with(mpm));
  m.platen_velocity_m_s = specimen.number("platen_velocity_m_s", Range::positive(10.0, "m/s"), 0.01,
                                          Doc("the platens' speed after the start-up ramp").only_with(mpm));
  m.platens = specimen.choice("platens", kPlatenFrictionNames, PlatenFriction::rough,
                              Doc("the platen–soil friction").only_with(mpm));
  m.shape_function = specimen.choice("shape_function", mpm::kShapeFunctionNames,
                                     {mpm::ShapeFunction::gimp, mpm::ShapeFunction::linear}, mpm::ShapeFunction::gimp,
                                     Doc("the particle–grid shape functions").only_with(mpm));
  m.courant = specimen.number("courant", Range::positive(1.0), 0.9,
                              Doc("the time step as a fraction of the CFL limit").only_with(mpm));
  m.flip_fraction = specimen.number("flip_fraction", Range::closed(0.0, 1.0), 0.9,
                                    Doc("the FLIP share of the particle velocity update").only_with(mpm));
  m.particles_per_cell =
      specimen.integer("particles_per_cell", 1, 8, 2, Doc("particles per cell along each direction").only_with(mpm));
  m.density_kg_m3 = specimen.number("density_kg_m3", Range::positive(1e5, "kg/m³"), 14.6e3 / 9.81,
                                    Doc("sets the time scale only (the specimen is weightless)")
                                        .by_default("14.6 kN/m³ / g = 1488.28")
                                        .only_with(mpm));
  m.output_strain_step = specimen.number(
      "output_strain_step", Range::positive(0.5 * m.axial_strain_max, "", "at most half the lab's last strain"), 1e-3,
      Doc("ε_a between the points of the model curve").within("(0, half the lab curve's last strain]").only_with(mpm));
  m.radial_margin = specimen.number("radial_margin", Range::positive(10.0), 0.5,
                                    Doc("empty grid beyond the radius, as a fraction of it").only_with(mpm));
  require_fits_in_memory(specimen_size(m), "specimen.cell_m",
                         "use a larger specimen.cell_m or fewer specimen.particles_per_cell");
  specimen.finish(
      "an mpm specimen (type, height_m, diameter_m, cell_m, platen_velocity_m_s, platens, "
      "shape_function, courant, flip_fraction, particles_per_cell, density_kg_m3, output_strain_step, "
      "radial_margin)");
}

/// A default that differs between the element test and the meshed specimen, in words.
std::string by_specimen(const std::string& element, const std::string& mpm) {
  return element + " (element), " + mpm + " (mpm)";
}

}  // namespace

CalibrationScene read_calibration_scene(SceneReader& scene, const fs::path& scene_dir) {
  CalibrationScene spec;
  spec.lab_file = scene.file("lab_curve_csv", scene_dir,
                             Doc("the lab curve: a CSV with axial_strain, deviatoric_stress_kPa and optionally "
                                 "volumetric_strain, compression positive (data/lab/README.md)"));
  try {
    spec.lab = read_lab_curve(spec.lab_file);
  } catch (const SceneError& e) {
    throw SceneError(std::string("lab_curve_csv: ") + e.what());
  }

  SceneReader material_reader = scene.required_object(
      "material", Doc("an ssmc material (weightless); its eta is where the fit starts with fit_start = material_eta, "
                      "within [eta_min, eta_max]"));
  const MaterialSpec material = read_material(material_reader, DensityRule::not_used);
  if (material.model != "ssmc")
    scene.fail("material.model", "must be ssmc: the calibration fits its softening factor eta");
  spec.material = std::get<StrainSofteningParameters>(material.parameters);

  spec.settings.mode = scene.choice("mode", kCalibrationModeNames, CalibrationMode::dissipated_work,
                                    Doc("the fit's criterion: the lab's dissipated work W = ∫F dδ (the paper's), or "
                                        "least squares on q ([theory](../theory.md#calibration))"));
  spec.settings.eta_min = scene.number("eta_min", Range::positive(1e4), 0.1, Doc("the lower bound of η"));
  spec.settings.eta_max =
      scene.number("eta_max", Range::positive(1e4), 500.0, Doc("the upper bound of η").within("(eta_min, 1e4]"));
  if (!(spec.settings.eta_max > spec.settings.eta_min))
    scene.fail("eta_max", "must be above eta_min (" + format_significant(spec.settings.eta_min) + ")");
  spec.eta_start = spec.material.softening_factor;
  if (!(spec.eta_start >= spec.settings.eta_min && spec.eta_start <= spec.settings.eta_max))
    scene.fail("material.eta", "is where the fit starts: must lie in [eta_min, eta_max] = [" +
                                   format_significant(spec.settings.eta_min) + ", " +
                                   format_significant(spec.settings.eta_max) + "]");
  spec.compare_eta =
      scene
          .optional_numbers(
              "compare_eta", Range::positive(1e4), 0, 5,
              Doc("η of the extra curves in the figure (their runs serve the scan too)").by_default("[2.5, 15]"))
          .value_or(std::vector<double>{2.5, 15.0});

  spec.test.cell_pressure_Pa =
      1e3 * scene.number("cell_pressure_kPa", Range::positive(1e7, "kPa"), 1.72, Doc("the cell pressure σ3"));
  SceneReader specimen = scene.object("specimen", Doc("the numerical triaxial the fit runs"));
  spec.specimen = specimen.choice("type", kSpecimenTypeNames, SpecimenType::element,
                                  Doc("the single-point element test, or a meshed axisymmetric MPM specimen; each "
                                      "takes only its own keys"));
  const bool mpm_specimen = spec.specimen == SpecimenType::mpm;
  spec.test.specimen.height_m =
      specimen.number("height_m", Range::positive(100.0, "m"), 0.15, Doc("the specimen's height H"));
  spec.test.specimen.diameter_m =
      specimen.number("diameter_m", Range::positive(100.0, "m"), 0.07, Doc("the specimen's diameter D"));
  spec.settings.specimen = spec.test.specimen;
  spec.test.axial_strain_max = spec.lab.axial_strain.back();  // the model covers the lab's range exactly
  if (mpm_specimen) {
    MpmTriaxialConfig& m = spec.mpm;
    m.specimen = spec.test.specimen;
    m.cell_pressure_Pa = spec.test.cell_pressure_Pa;
    m.axial_strain_max = spec.test.axial_strain_max;
    read_mpm_specimen(specimen, m);
    for (const char* key : {"increments", "strain_rate_per_s"})
      if (scene.has(key))
        scene.fail(key,
                   "belongs to the element test; an mpm specimen (specimen.type = mpm) is resolved by its "
                   "cell_m and time step, and strained by its platen_velocity_m_s");
  } else {
    specimen.finish("an element specimen (type, height_m, diameter_m; the MPM keys need \"type\": \"mpm\")");
    const std::string element = "specimen.type = element";
    spec.test.increments = scene.integer("increments", 10, 1'000'000, 1000,
                                         Doc("increments over the lab curve's strain range").only_with(element));
    spec.test.strain_rate_per_s =
        scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4,
                     Doc("the axial strain rate, which only the rate law sees").only_with(element));
  }
  // The second fit doubles the cost: on by default only for the (cheap) element test.
  spec.compare_modes = scene.boolean(
      "compare_modes", !mpm_specimen,
      Doc("also fit by the other criterion (reported as other_mode)").by_default(by_specimen("`true`", "`false`")));
  // A meshed specimen's run costs seconds to minutes: by default it scans the bounds, their
  // geometric mean and the compare_eta (run anyway), starts where that scan crosses W_lab
  // and takes its slopes from runs already made (one run per Ceres iteration).
  spec.settings.scan = scene.choice("scan", kWorkScanNames, WorkScan::bounds,
                                    Doc("the W(η) check before the fit: scan_points log-spaced η over the bounds, or "
                                        "bracket: from material.eta outward until two runs straddle W_lab (with mode "
                                        "dissipated_work)"));
  if (spec.settings.scan == WorkScan::bracket) {
    if (spec.settings.mode != CalibrationMode::dissipated_work)
      scene.fail("scan", "'bracket' brackets W_lab: it needs mode dissipated_work");
    if (scene.has("scan_points")) scene.fail("scan_points", "belongs to scan 'bounds' (the bracket widens as needed)");
    spec.settings.bracket_start_eta = spec.eta_start;
  } else {  // read only where it applies, so that the echoed scene runs again as it is
    spec.settings.scan_points =
        scene.integer("scan_points", 2, 1000, mpm_specimen ? 3 : 9,
                      Doc("log-spaced η of the W(η) check, the bounds included (the compare_eta are scanned too)")
                          .by_default(by_specimen("9", "3"))
                          .only_with("scan = bounds"));
  }
  spec.fit_start = scene.choice("fit_start", kFitStartNames, mpm_specimen ? FitStart::scan : FitStart::material_eta,
                                Doc("where Ceres starts: material.eta, or where the scan's W crosses W_lab")
                                    .by_default(by_specimen("`material_eta`", "`scan`")));
  if (spec.fit_start == FitStart::material_eta) spec.settings.eta_start = spec.eta_start;
  spec.settings.scan_extra_eta = spec.compare_eta;
  spec.settings.derivative =
      scene.choice("derivative", kFitDerivativeNames, mpm_specimen ? FitDerivative::secant : FitDerivative::central,
                   Doc("the fit's slope in ln η: central differences (two runs a point), or the secant through the "
                       "nearest run already made")
                       .by_default(by_specimen("`central`", "`secant`")));
  spec.settings.max_iterations = scene.integer("max_iterations", 1, 10000, 50, Doc("Ceres iterations, at most"));
  // A meshed specimen's W jitters by up to ±0.2 % between neighbouring η at 0.5 cm: its
  // slope's step (0.1 in ln η) must stand above that, and a trial η within 0.005 of a run made
  // (below the jitter) takes that run. Its work tolerance sits near the jitter: tighter costs
  // runs, looser costs η where W is flat in η (at 2 cm, 1e-3 of W is ±20 % of η).
  spec.settings.derivative_step = scene.number(
      "derivative_step_ln_eta", Range::positive(0.5), mpm_specimen ? 0.1 : 1e-4,
      Doc("the central difference's step in ln η (the secant's least span)").by_default(by_specimen("1e-4", "0.1")));
  spec.settings.parameter_tolerance =
      scene.number("parameter_tolerance", Range::open(0.0, 1.0), mpm_specimen ? 1e-4 : 1e-8,
                   Doc("the fit stops when ln η changes by less (relative)").by_default(by_specimen("1e-8", "1e-4")));
  spec.settings.work_tolerance =
      scene.number("work_tolerance", Range::half_open(0.0, 1.0), mpm_specimen ? 2e-4 : 0.0,
                   Doc("with dissipated_work, the fit stops once |W_model/W_lab − 1| is below this (0: off)")
                       .by_default(by_specimen("0", "2e-4")));
  spec.settings.reuse_radius_ln_eta =
      scene.number("reuse_radius_ln_eta", Range::closed(0.0, 0.5), mpm_specimen ? 0.005 : 0.0,
                   Doc("a trial η this close in ln η to a run already made takes that run (0: only the same η)")
                       .by_default(by_specimen("0", "0.005")));

  spec.fitted_peak_friction =
      scene.boolean("fit_peak_friction", false,
                    Doc("replace phi_peak_deg by the lab peak's asin((N − 1)/(N + 1)), N = 1 + q_peak/σ3 (c' = 0 "
                        "only)"));
  if (spec.fitted_peak_friction) {
    if (spec.material.cohesion_peak_Pa != 0.0)
      scene.fail("fit_peak_friction", "assumes c' = 0 (q_peak = σ3 (Nφ − 1)); the material has c_peak_kPa > 0");
    const double phi = peak_friction_from_peak_q(spec.lab.peak_q_Pa(), spec.test.cell_pressure_Pa);
    if (!(phi > spec.material.friction_residual_rad))
      scene.fail("fit_peak_friction", "the lab peak q = " + format_significant(1e-3 * spec.lab.peak_q_Pa()) +
                                          " kPa implies φ'_p = " + format_significant(phi / kDegree) +
                                          "°, not above phi_residual_deg = " +
                                          format_significant(spec.material.friction_residual_rad / kDegree) + "°");
    spec.material.friction_peak_rad = phi;
  }
  scene.finish("a calibration scene");
  return spec;
}

}  // namespace ffp
