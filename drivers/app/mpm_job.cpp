/// The `mpm` scene kind: a generic axisymmetric MPM run for verification
/// scenes (wave column, geostatic column, colliding bodies, …).
///
/// Its keys are read in mpm_scene.cpp, each declared where it is read: `ffp keys mpm`.
/// Writes history.csv, fields/particles_NNNN.vtu + fields/particles.pvd, plots/energy.png.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/app/mpm_run_loop.hpp"
#include "drivers/app/mpm_scene.hpp"
#include "drivers/app/particle_fields.hpp"
#include "drivers/output/csv_writer.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/parallel.hpp"
#include "mpm/simulation.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

std::string format_seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g s", s);
  return buffer;
}

/// A history column after time_s, its name resolved once: a figure of the diagnostics
/// of one body or of all, or the time step.
using DiagnosticFigure = double (*)(const mpm::Diagnostics&);

struct HistoryQuantity {
  DiagnosticFigure of = nullptr;    ///< unused for dt_s; an unknown name gives NaN
  std::optional<std::size_t> body;  ///< the body measured; none: all
  bool is_dt = false;
};

DiagnosticFigure diagnostic_named(const std::string& name) {
  using D = const mpm::Diagnostics&;
  if (name == "kinetic_energy_J") return [](D d) { return d.kinetic_energy_J; };
  if (name == "strain_energy_J") return [](D d) { return d.strain_energy_J; };
  if (name == "gravity_energy_J") return [](D d) { return d.gravity_energy_J; };
  if (name == "total_energy_J") return [](D d) { return d.total_energy_J(); };
  if (name == "momentum_z_N_s") return [](D d) { return d.momentum_z_N_s; };
  if (name == "mass_kg") return [](D d) { return d.mass_kg; };
  if (name == "max_speed_m_s") return [](D d) { return d.max_speed_m_s; };
  if (name == "mean_z_m") return [](D d) { return d.mass_kg > 0 ? d.mass_z_kg_m / d.mass_kg : 0.0; };
  if (name == "mean_v_z_m_s") return [](D d) { return d.mass_kg > 0 ? d.momentum_z_N_s / d.mass_kg : 0.0; };
  return [](D) { return std::numeric_limits<double>::quiet_NaN(); };
}

/// `dt_s`, `<body>_<quantity>` (the first body whose name prefixes it) or `<quantity>` of all bodies.
HistoryQuantity resolve_quantity(const std::string& q, const std::vector<std::string>& body_names) {
  if (q == "dt_s") return {nullptr, std::nullopt, true};
  for (std::size_t b = 0; b < body_names.size(); ++b) {
    const std::string prefix = body_names[b] + "_";
    if (q.rfind(prefix, 0) == 0) return {diagnostic_named(q.substr(prefix.size())), b};
  }
  return {diagnostic_named(q), std::nullopt};
}

class MpmJob : public Job {
 public:
  MpmJob(MpmScene scene, std::string name)
      : scene_(std::move(scene)),
        name_(std::move(name)),
        simulation_(std::make_unique<mpm::Simulation>(scene_.model)),
        initial_dt_s_(simulation_->dt_s) {
    for (const MpmProbe& probe : scene_.output.probes) probe_particles_.push_back(nearest_particle(probe));
    for (const std::string& q : scene_.output.history) quantities_.push_back(resolve_quantity(q, scene_.body_names));
  }

  const mpm::Simulation& simulation() const { return *simulation_; }
  mpm::ModelSize size;  ///< the estimate the scene was checked with (printed by ffp check)

  void describe(std::ostream& out) const override {
    const mpm::Simulation& s = *simulation_;
    out << "grid: " << s.grid.r.nodes() << " × " << s.grid.z.nodes() << " nodes, h_min = " << s.grid.min_spacing()
        << " m; particles: " << s.particles.size() << "\n";
    describe_memory(out, size);
    out << "stages: " << s.stages.describe() << "\n";
    if (s.two_phase) {
      out << "CFL time step limit h_min/(c_p + |v|max): " << format_seconds(mpm::cfl_time_step_limit(s)) << "\n";
      out << "two-phase time step limit (Mieremet 2015, L = h_min): "
          << format_seconds(mpm::two_phase_time_step_limit(s)) << "\n";
    } else {
      out << "CFL time step limit h_min/(c_p + |v|max): " << format_seconds(s.dt_limit_s) << "\n";
    }
    out << "time step: " << format_seconds(s.dt_s)
        << (s.settings.fixed_dt_s ? " (fixed)"
                                  : " (Courant " + std::to_string(s.settings.courant) + ", recomputed every step)")
        << "\n";
    if (s.settings.transfer == mpm::Transfer::usl)
      out << "note: USL takes the strain rate from v_i^{n+1}, which nodes of small mass at cell crossings can blow up\n"
             "      (measured: a bouncing block went unstable at Courant 0.5); MUSL is the robust choice\n";
  }

  std::optional<RunCost> cost(bool measure) override {
    if (!measure) return plan_mpm_cost(*simulation_, scene_.end_time_s);
    const RunCost measured = measure_mpm_cost(*simulation_, scene_.end_time_s);
    simulation_.reset();  // one model in memory at a time
    simulation_ = std::make_unique<mpm::Simulation>(scene_.model);
    return measured;
  }

  void run(RunContext& context) override;

 private:
  std::size_t nearest_particle(const MpmProbe& probe) const {
    const mpm::Particles& p = simulation_->particles;
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double d = std::hypot(p.r[i] - probe.r_m, p.z[i] - probe.z_m);
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    return best;
  }

  std::vector<std::string> columns() const;
  std::vector<double> row() const;

  MpmScene scene_;
  std::string name_;
  std::unique_ptr<mpm::Simulation> simulation_;  ///< rebuilt after a cost probe
  double initial_dt_s_;
  std::vector<std::size_t> probe_particles_;
  std::vector<HistoryQuantity> quantities_;  ///< scene_.output.history resolved
};

std::vector<std::string> MpmJob::columns() const {
  std::vector<std::string> c = {"time_s"};
  c.insert(c.end(), scene_.output.history.begin(), scene_.output.history.end());
  for (const MpmProbe& p : scene_.output.probes) {
    for (const char* q :
         {"r_m", "z_m", "v_r_m_s", "v_z_m_s", "sigma_rr_kPa", "sigma_zz_kPa", "sigma_tt_kPa", "sigma_rz_kPa"})
      c.push_back(p.name + "_" + q);
    if (simulation_->two_phase)  // σ above is the effective stress σ'; σ = σ' − p I
      for (const char* q : {"pore_pressure_kPa", "excess_pore_pressure_kPa"}) c.push_back(p.name + "_" + q);
  }
  return c;
}

std::vector<double> MpmJob::row() const {
  const mpm::Simulation& s = *simulation_;
  const mpm::Diagnostics all = mpm::measure(s);
  std::vector<double> r = {s.time_s};
  for (const HistoryQuantity& q : quantities_) {
    if (q.is_dt)
      r.push_back(s.dt_s);
    else
      r.push_back(q.of(q.body ? mpm::measure_body(s, *q.body) : all));
  }
  for (std::size_t p : probe_particles_) {
    const Voigt& sig = s.particles.stress[p];
    r.insert(r.end(), {s.particles.r[p], s.particles.z[p], s.particles.vr[p], s.particles.vz[p], 1e-3 * sig[0],
                       1e-3 * sig[1], 1e-3 * sig[2], 1e-3 * sig[3]});
    if (s.two_phase)
      r.insert(r.end(), {1e-3 * s.two_phase->pore_pressure[p], 1e-3 * s.two_phase->excess_pressure(s.particles, p)});
  }
  return r;
}

void MpmJob::run(RunContext& context) {
  mpm::Simulation& s = *simulation_;
  ParticleFieldSeries fields(context.out_dir / "fields");
  fs::create_directories(context.out_dir / "plots");
  CsvTable history(columns());
  std::vector<double> t, kinetic, strain, gravity, total;
  MpmRunCallbacks callbacks;
  callbacks.record_row = [&] {
    history.add_row(row());
    const mpm::Diagnostics d = mpm::measure(s);
    t.push_back(s.time_s);
    kinetic.push_back(d.kinetic_energy_J);
    strain.push_back(d.strain_energy_J);
    gravity.push_back(d.gravity_energy_J);
    total.push_back(d.total_energy_J());
  };
  callbacks.write_fields = [&] {
    std::vector<std::pair<std::string, std::vector<double>>> extra = micropolar_columns(s.micropolar);
    for (auto& column : pore_fluid_columns(s)) extra.push_back(std::move(column));
    fields.write(s.particles, s.time_s, {.stress_components = true, .extra = std::move(extra)});
  };
  const mpm::Diagnostics initial = mpm::measure(s);
  const MpmOutputTimes times{scene_.end_time_s, scene_.output.history_interval_s, scene_.output.field_times_s};
  context.steps = run_mpm(s, times, callbacks, "mpm", name_, context.show_progress).steps;
  history.write(context.out_dir / "history.csv");
  fields.finish();

  Plot energy;
  energy.title = name_ + ": energy";
  energy.x_label = "time (s)";
  energy.y_label = "energy (J)";
  energy.series = {{t, kinetic, "kinetic"}, {t, strain, "elastic strain"}, {t, total, "total"}};
  if (s.gravity_m_s2) energy.series.push_back({t, gravity, "gravity (m g z)"});
  write_png(energy, context.out_dir / "plots" / "energy.png");

  const mpm::Diagnostics final_state = mpm::measure(s);
  json& sum = context.summary;
  sum["particles"] = s.particles.size();
  sum["dt_s"] = initial_dt_s_;
  sum["dt_limit_s"] = s.dt_limit_s;
  sum["stages"] = s.stages.names();
  sum["mpm_threads"] = mpm::thread_count();
  sum["initial_total_energy_J"] = initial.total_energy_J();
  sum["final_total_energy_J"] = final_state.total_energy_J();
  sum["final_kinetic_energy_J"] = final_state.kinetic_energy_J;
  sum["mass_kg"] = final_state.mass_kg;
  sum["wall_clamps"] = s.wall_clamps;
  sum["field_files"] = fields.size();
  if (s.two_phase) sum["two_phase_dt_limit_s"] = mpm::two_phase_time_step_limit(s);
}

}  // namespace

std::unique_ptr<Job> make_mpm_job(SceneReader& scene, const fs::path&) {
  const std::string name = read_scene_name(scene, "mpm");
  MpmScene parsed = read_mpm_scene(scene);
  std::unique_ptr<MpmJob> job = build_mpm_model("mpm", [&] {
    const mpm::ModelSize size = mpm::estimate_model_size(parsed.model, memory_budget_bytes());
    require_fits_in_memory(size, "mesh",
                           "use larger mesh.cell_r_m / cell_z_m or fewer particles_per_cell in the bodies");
    auto made = std::make_unique<MpmJob>(std::move(parsed), name);
    made->size = size;
    return made;
  });
  const mpm::Simulation& s = job->simulation();
  if (s.settings.fixed_dt_s && *s.settings.fixed_dt_s > s.dt_limit_s) {
    char message[256];
    std::snprintf(message, sizeof message,
                  "solver.dt_s: = %.6g s is above the CFL limit %.6g s (h_min/(c_p + |v|max)); use dt_s ≤ %.6g s or "
                  "omit dt_s for courant × limit",
                  *s.settings.fixed_dt_s, s.dt_limit_s, s.dt_limit_s);
    throw SceneError(message);
  }
  return job;
}

}  // namespace ffp
