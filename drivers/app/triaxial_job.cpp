/// The `triaxial` scene kind: drained triaxial element test on the paper's
/// weightless specimen (drivers/triaxial_test.hpp). The keys are read by
/// triaxial_scene.cpp; this file runs the test and writes history.csv, the
/// summary (peak, residual, the work balance) and the plots.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <span>
#include <vector>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/triaxial_scene.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

/// The outputs of the law's state that are columns: all but rates (the scene's
/// constant strain_rate_per_s drives the test; the point kind prints them).
std::vector<StateOutput> state_columns(const MaterialLaw& law) {
  std::vector<StateOutput> out;
  for (StateOutput o : state_outputs(law))
    if (unit(o) != OutputUnit::per_second) out.push_back(o);
  return out;
}

class TriaxialJob : public Job {
 public:
  explicit TriaxialJob(TriaxialScene scene)
      : name_(std::move(scene.name)),
        material_(std::move(scene.material)),
        config_(std::move(scene.config)),
        output_every_(scene.output_every) {}

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
    const std::vector<StateOutput> outputs = state_columns(config_.law);
    std::vector<std::string> columns = {
        "step",          "axial_strain",      "volumetric_strain", "q_kPa", "p_kPa", "axial_displacement_m",
        "axial_force_N", "dissipated_work_J", "plastic_work_J"};
    for (StateOutput o : outputs) columns.push_back(output_column(o));
    CsvTable table(columns);
    const std::size_t n = r.axial_strain.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (i % static_cast<std::size_t>(output_every_) != 0 && i + 1 != n) continue;
      const PointRecord& record = r.history.records[i];
      std::vector<double> row = {static_cast<double>(record.step),
                                 r.axial_strain[i],
                                 r.volumetric_strain[i],
                                 1e-3 * r.deviatoric_stress_Pa[i],
                                 1e-3 * r.mean_stress_Pa[i],
                                 r.axial_displacement_m[i],
                                 r.axial_force_N[i],
                                 r.dissipated_work_J[i],
                                 r.plastic_work_J[i]};
      for (StateOutput o : outputs)
        row.push_back(output_value(o, state_output(config_.law, record.state, r.mean_stress_Pa[i], o)));
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
        Plot{title + ": volumetric strain (compression positive)",
             "axial strain ε_a (%)",
             "ε_v (%)",
             {{axial_percent, volumetric_percent, model}}},
        Plot{title + ": axial force against displacement, " + work,
             "axial displacement δ (mm)",
             "F = q·A (N)",
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
  return std::make_unique<TriaxialJob>(read_triaxial_scene(scene));
}

}  // namespace ffp
