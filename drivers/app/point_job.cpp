/// The `point` scene kind: one material point along a stress/strain path,
/// run by the point integrator (drivers/point_integrator.hpp). The keys are
/// read by point_scene.cpp; this file runs the scene and writes history.csv,
/// the summary figures and the plots, or on a failed step the reproducer.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <ostream>
#include <span>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/point_scene.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

constexpr int kAxial = 1;  // component 22: z in axisymmetry

class PointJob : public Job {
 public:
  explicit PointJob(PointScene scene)
      : name_(std::move(scene.name)),
        material_(std::move(scene.material)),
        config_(std::move(scene.config)),
        path_type_(std::move(scene.path_type)) {}

  void describe(std::ostream& out) const override {
    long increments = 0;
    for (const auto& s : config_.segments) increments += s.increments;
    out << "point: " << material_.model << " material, " << path_type_ << " path, " << config_.segments.size()
        << " segment(s), " << increments << " increments\n";
  }

  void run(RunContext& context) override {
    long total = 0;
    for (const auto& s : config_.segments) total += s.increments;
    Progress progress("point", static_cast<double>(total), context.show_progress);
    PointHistory history;
    try {
      history = integrate_point(config_, [&](long done, long) { progress.update(static_cast<double>(done), done); });
    } catch (const PointIntegrationFailure& failure) {
      throw RunFailure(failure.what(), reproducer(failure));
    }
    progress.finish();
    context.steps = history.increments;
    write_history(history, context);
  }

 private:
  json reproducer(const PointIntegrationFailure& f) const {
    json scene;
    scene["kind"] = "point";
    scene["name"] = name_ + "-failed-step-" + std::to_string(f.step);
    scene["description"] = std::string("repeats the failed increment: ") + f.what();
    scene["material"] = material_json(material_);
    std::vector<double> stress(6);
    for (int i = 0; i < 6; ++i) stress[i] = -1e-3 * f.stress_start[i];
    scene["initial_stress_kPa"] = stress;
    if (json state = initial_state_json(f.state_start); !state.is_null()) scene["initial_state"] = std::move(state);
    json control = json::array(), target = json::array();
    for (int i = 0; i < 6; ++i) {
      const bool strain = f.control[i] == Control::strain;
      control.push_back(strain ? "strain" : "stress");
      target.push_back(strain ? -f.prescribed_strain_increment[i] : -1e-3 * f.target_stress[i]);
    }
    scene["path"] = {
        {"type", "general"},
        {"segments",
         json::array({{{"control", control}, {"target", target}, {"increments", 1}, {"duration_s", f.dt_s}}})}};
    scene["newton"] = {{"max_iterations", config_.newton.max_iterations},
                       {"relative_tolerance", config_.newton.relative_tolerance}};
    return scene;
  }

  void write_history(const PointHistory& history, RunContext& context) const {
    const std::span<const StateOutput> outputs = state_outputs(config_.law);
    std::vector<std::string> columns = {"step",  "time_s", "axial_strain", "volumetric_strain", "shear_strain_12",
                                        "p_kPa", "q_kPa"};
    for (const char* c : kPointComponents) columns.push_back(std::string("stress_") + c + "_kPa");
    for (const char* c : kPointComponents) columns.push_back(std::string("strain_") + c);
    for (const char* c : {"return_region", "newton_iterations", "plastic_work_J_m3", "work_input_J_m3"})
      columns.emplace_back(c);
    for (StateOutput o : outputs) columns.push_back(output_column(o));
    CsvTable table(columns);

    double peak_q = -1.0;
    std::vector<double> axial, volumetric, q, shear, shear_stress;
    for (const PointRecord& r : history.records) {
      const double q_kPa = 1e-3 * deviatoric_stress(r.stress);
      const double axial_strain = -r.strain[kAxial];
      const double volumetric_strain = -trace(r.strain);
      std::vector<double> row = {
          static_cast<double>(r.step),    r.time_s, axial_strain, volumetric_strain, 2.0 * r.strain[3],
          1e-3 * mean_pressure(r.stress), q_kPa};
      for (int i = 0; i < 6; ++i) row.push_back(-1e-3 * r.stress[i]);
      for (int i = 0; i < 6; ++i) row.push_back(-r.strain[i]);
      row.push_back(static_cast<double>(r.region));
      row.push_back(r.newton_iterations);
      row.push_back(r.plastic_work_J_m3);
      row.push_back(r.work_input_J_m3);
      for (StateOutput o : outputs)
        row.push_back(output_value(o, state_output(config_.law, r.state, mean_pressure(r.stress), o)));
      table.add_row(row);
      peak_q = std::max(peak_q, q_kPa);
      axial.push_back(axial_strain);
      volumetric.push_back(volumetric_strain);
      q.push_back(q_kPa);
      shear.push_back(2.0 * r.strain[3]);
      shear_stress.push_back(-1e-3 * r.stress[3]);
    }
    table.write(context.out_dir / "history.csv");

    // On a perfectly plastic plateau q wanders by rounding: the peak is where
    // q first comes within 1e-8 of its maximum (the Newton tolerance is 1e-10).
    double strain_at_peak = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (q[i] >= peak_q * (1.0 - 1e-8)) {
        strain_at_peak = axial[i];
        break;
      }
    }
    const PointRecord& last = history.records.back();
    json& s = context.summary;
    s["peak_q_kPa"] = peak_q;
    s["axial_strain_at_peak"] = strain_at_peak;
    s["residual_q_kPa"] = q.back();
    s["dissipated_work_J_m3"] = last.plastic_work_J_m3;
    s["work_input_J_m3"] = last.work_input_J_m3;
    s["final_p_kPa"] = 1e-3 * mean_pressure(last.stress);
    s["final_axial_strain"] = axial.back();
    s["final_volumetric_strain"] = volumetric.back();
    s["increments"] = history.increments;
    s["max_newton_iterations"] = history.max_newton_iterations;
    if (has_state_output(config_.law, StateOutput::plastic_deviatoric_strain))
      s["final_plastic_deviatoric_strain"] =
          state_output(config_.law, last.state, mean_pressure(last.stress), StateOutput::plastic_deviatoric_strain);

    const fs::path plots = context.out_dir / "plots";
    fs::create_directories(plots);
    const bool shear_path = path_type_ == "simple_shear";
    const std::vector<double>& x = shear_path ? shear : axial;
    const std::string x_label = shear_path ? "shear strain γ_12" : "axial strain ε_a";
    Plot strength_plot{name_ + ": " + (shear_path ? "shear stress" : "deviatoric stress"),
                       x_label,
                       shear_path ? "τ_12 (kPa)" : "q (kPa)",
                       {{x, shear_path ? shear_stress : q, material_.model}}};
    Plot volume_plot{
        name_ + ": volumetric strain (compression positive)", x_label, "ε_v", {{x, volumetric, material_.model}}};
    write_png(strength_plot, plots / (shear_path ? "shear_stress_shear_strain.png" : "q_axial_strain.png"));
    write_png(volume_plot,
              plots / (shear_path ? "volumetric_strain_shear_strain.png" : "volumetric_strain_axial_strain.png"));
  }

  std::string name_;
  MaterialSpec material_;
  PointConfig config_;
  std::string path_type_;
};

}  // namespace

std::unique_ptr<Job> make_point_job(SceneReader& scene, const fs::path& scene_dir) {
  return std::make_unique<PointJob>(read_point_scene(scene, scene_dir));
}

}  // namespace ffp
