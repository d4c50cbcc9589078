/// The `triaxial` scene kind: drained triaxial element test on the paper's
/// weightless specimen (drivers/triaxial_test.hpp).
///
/// Scene (geotechnical units, compression positive):
///   material             see drivers/scene/material_scene.hpp (no density: weightless)
///   cell_pressure_kPa    σ3 (default 1.72, the paper's)
///   axial_strain_max     default 0.2
///   increments           equal axial-strain increments (default 2000)
///   strain_rate_per_s    only the rate law sees it (default 1e-4, quasi-static)
///   specimen             {height_m: 0.15, diameter_m: 0.07}
///   newton               {max_iterations, relative_tolerance}
///   output_every_increments  rows of history.csv (the work integral uses every increment)
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "drivers/scene/material_scene.hpp"
#include "drivers/triaxial_test.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

constexpr long kMaxIncrements = 1'000'000;  // every increment is kept for the work integral (~160 B each)

class TriaxialJob : public Job {
 public:
  TriaxialJob(std::string name, MaterialSpec material, TriaxialTestConfig config, long output_every)
      : name_(std::move(name)), material_(std::move(material)), config_(std::move(config)),
        output_every_(output_every) {}

  void describe(std::ostream& out) const override {
    out << "triaxial: drained, " << material_.model << " material, σ3 = " << 1e-3 * config_.cell_pressure_Pa
        << " kPa, ε_a to " << config_.axial_strain_max << " in " << config_.increments << " increments, specimen "
        << config_.specimen.height_m << " m × " << config_.specimen.diameter_m << " m\n";
  }

  void run(RunContext& context) override {
    Progress progress("triaxial", config_.increments, context.show_progress);
    TriaxialResult result;
    try {
      result = run_triaxial_test(config_, [&](long done, long) { progress.update(static_cast<double>(done), done); });
    } catch (const PointIntegrationFailure& failure) {
      throw RunFailure(failure.what());
    }
    progress.finish();
    context.steps = result.history.increments;
    write_history(result, context);
    write_summary(result, context);
    write_plots(result, context);
  }

 private:
  void write_history(const TriaxialResult& r, RunContext& context) const {
    const auto* law = std::get_if<StrainSofteningMohrCoulomb>(&config_.law);
    std::vector<std::string> columns = {"step",           "axial_strain",    "volumetric_strain",
                                        "q_kPa",          "p_kPa",           "axial_displacement_m",
                                        "axial_force_N",  "dissipated_work_J", "plastic_work_J"};
    if (law)
      for (const char* c : {"plastic_deviatoric_strain", "friction_angle_deg", "dilatancy_angle_deg"})
        columns.emplace_back(c);
    CsvTable table(columns);
    const std::size_t n = r.axial_strain.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (i % static_cast<std::size_t>(output_every_) != 0 && i + 1 != n) continue;
      const PointRecord& record = r.history.records[i];
      std::vector<double> row = {static_cast<double>(record.step), r.axial_strain[i], r.volumetric_strain[i],
                                 1e-3 * r.deviatoric_stress_Pa[i], 1e-3 * r.mean_stress_Pa[i],
                                 r.axial_displacement_m[i], r.axial_force_N[i], r.dissipated_work_J[i],
                                 r.plastic_work_J[i]};
      if (law) {
        const auto& state = std::get<StrainSofteningMohrCoulomb::State>(record.state);
        const MohrCoulombParameters strength = law->current_strength(state, r.mean_stress_Pa[i]);
        row.push_back(state.plastic_deviatoric_strain);
        row.push_back(strength.friction_angle_rad / kDegree);
        row.push_back(strength.dilatancy_angle_rad / kDegree);
      }
      table.add_row(row);
    }
    table.write(context.out_dir / "history.csv");
  }

  void write_summary(const TriaxialResult& r, RunContext& context) const {
    json& s = context.summary;
    s["peak_q_kPa"] = 1e-3 * r.peak_q_Pa;
    s["axial_strain_at_peak"] = r.axial_strain_at_peak;
    s["residual_q_kPa"] = 1e-3 * r.residual_q_Pa;
    s["residual_q_is"] = "q at the last increment (axial_strain_max)";
    s["dissipated_work_J"] = r.dissipated_work_J_total;
    s["dissipated_work_integration"] =
        "W = ∫F dδ, F = q·A, δ = ε_a·H, trapezoid rule on every increment (not only the history.csv rows)";
    s["plastic_work_J"] = r.plastic_work_J_total;
    s["elastic_energy_change_J"] = r.elastic_energy_change_J;
    s["cell_pressure_work_J"] = r.cell_work_J;
    s["work_balance_error_J"] =
        r.dissipated_work_J_total - (r.plastic_work_J_total + r.elastic_energy_change_J - r.cell_work_J);
    s["work_note"] =
        "dissipated_work_J is the piston's deviatoric work; it equals plastic_work_J (what the law dissipates) "
        "+ elastic_energy_change_J (stored, recoverable) - cell_pressure_work_J (σ3·V·ε_v, the cell's work on "
        "the volume change, negative when the specimen dilates)";
    s["specimen_area_m2"] = config_.specimen.area_m2();
    s["specimen_volume_m3"] = config_.specimen.volume_m3();
    s["final_axial_strain"] = r.axial_strain.back();
    s["final_volumetric_strain"] = r.volumetric_strain.back();
    s["increments"] = r.history.increments;
    s["max_newton_iterations"] = r.history.max_newton_iterations;
  }

  void write_plots(const TriaxialResult& r, RunContext& context) const {
    const fs::path plots = context.out_dir / "plots";
    fs::create_directories(plots);
    std::vector<double> axial_percent, q_kPa, volumetric_percent, displacement_mm, force_N;
    const std::size_t n = r.axial_strain.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (i % static_cast<std::size_t>(output_every_) != 0 && i + 1 != n) continue;  // the history.csv rows
      force_N.push_back(r.axial_force_N[i]);
      axial_percent.push_back(100.0 * r.axial_strain[i]);
      q_kPa.push_back(1e-3 * r.deviatoric_stress_Pa[i]);
      volumetric_percent.push_back(100.0 * r.volumetric_strain[i]);
      displacement_mm.push_back(1e3 * r.axial_displacement_m[i]);
    }
    const std::string model = material_.model;
    const std::string title = name_;
    char work[96];
    std::snprintf(work, sizeof work, "∫F dδ = %.4g J (plastic work %.4g J)", r.dissipated_work_J_total,
                  r.plastic_work_J_total);
    const std::vector<Plot> panels = {
        Plot{title + ": deviatoric stress", "axial strain ε_a (%)", "q (kPa)", {{axial_percent, q_kPa, model}}},
        Plot{title + ": volumetric strain (compression positive)", "axial strain ε_a (%)", "ε_v (%)",
             {{axial_percent, volumetric_percent, model}}},
        Plot{title + ": axial force against displacement, " + work, "axial displacement δ (mm)", "F = q·A (N)",
             {{displacement_mm, force_N, model}}}};
    write_png(panels[0], plots / "q_axial_strain.png");
    write_png(panels[1], plots / "volumetric_strain_axial_strain.png");
    write_png(panels[2], plots / "force_displacement.png");
  }

  std::string name_;
  MaterialSpec material_;
  TriaxialTestConfig config_;
  long output_every_;
};

}  // namespace

std::unique_ptr<Job> make_triaxial_job(SceneReader& scene, const fs::path&) {
  const std::string name = scene.text("name", "triaxial");
  SceneReader material_reader = scene.object("material", true);
  MaterialSpec material = read_material(material_reader, DensityRule::not_used);

  TriaxialTestConfig config;
  config.law = material.law();
  config.cell_pressure_Pa = 1e3 * scene.number("cell_pressure_kPa", Range::positive(1e7, "kPa"), 1.72);
  config.axial_strain_max = scene.number("axial_strain_max", Range::half_open(0.0, 1.0), 0.2);
  if (!(config.axial_strain_max > 0.0)) scene.fail("axial_strain_max", "must be > 0 (compression positive)");
  config.increments = scene.integer("increments", 1, kMaxIncrements, 2000);
  config.strain_rate_per_s = scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4);
  SceneReader specimen = scene.object("specimen");
  config.specimen.height_m = specimen.number("height_m", Range::positive(100.0, "m"), 0.15);
  config.specimen.diameter_m = specimen.number("diameter_m", Range::positive(100.0, "m"), 0.07);
  specimen.finish("specimen (height_m, diameter_m)");
  SceneReader newton = scene.object("newton");
  config.newton.max_iterations = newton.integer("max_iterations", 1, 1000, 25);
  config.newton.relative_tolerance = newton.number("relative_tolerance", Range::closed(1e-15, 1e-2), 1e-10);
  newton.finish("newton");
  // Histories beyond ~20,000 rows only slow the plots down.
  const long output_every =
      scene.integer("output_every_increments", 1, kMaxIncrements, std::max(1L, config.increments / 20000L));
  scene.finish("a triaxial scene");
  return std::make_unique<TriaxialJob>(name, std::move(material), std::move(config), output_every);
}

}  // namespace ffp
