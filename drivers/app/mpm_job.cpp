/// The `mpm` scene kind: a generic axisymmetric MPM run for verification
/// scenes (wave column, geostatic column, colliding bodies, …).
///
/// Scene keys (SI unless the key says otherwise):
///   mesh        {r_nodes_m | r_min_m (0), r_max_m, cell_r_m;  z_nodes_m | z_min_m (0), z_max_m, cell_z_m}
///   gravity_m_s2          magnitude along −z; omitted: no gravity stage
///   bodies[]    {name, material (material_scene.hpp, density_kg_m3 required),
///                region {r_min_m, r_max_m, z_min_m, z_max_m} | {sphere_center_z_m, sphere_radius_m},
///                particles_per_cell [n_r, n_z], initial_velocity_m_s [v_r, v_z],
///                initial_stress {k0 (default Jaky / ν/(1−ν)), surface_z_m}}
///   boundaries  {axis (or inner when r_min > 0), outer, bottom, top}: free | roller | fixed
///   surface_pressures[]   {side: inner|outer, pressure_kPa, ramp_time_s, z_min_m, z_max_m}
///   solver      {shape_function: gimp|linear, transfer: musl|usl, flip_fraction, courant,
///                dt_s (fixed; refused above the CFL limit), strain_smoothing, local_damping}
///   end_time_s
///   output      {history_interval_s, history [quantities], field_times_s | field_interval_s,
///                probes [{name, r_m, z_m}]}
/// Writes history.csv, fields/particles_NNNN.vtu + fields/particles.pvd, plots/energy.png.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <ostream>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/mpm_scene.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "drivers/output/vtu_writer.hpp"
#include "mpm/diagnostics.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/app/thread_governor.hpp"
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

class MpmJob : public Job {
 public:
  MpmJob(MpmScene scene, std::string name)
      : scene_(std::move(scene)), name_(std::move(name)), simulation_(scene_.model), initial_dt_s_(simulation_.dt_s) {
    for (const MpmProbe& probe : scene_.output.probes) probe_particles_.push_back(nearest_particle(probe));
  }

  const mpm::Simulation& simulation() const { return simulation_; }
  mpm::ModelSize size;  ///< the estimate the scene was checked with (printed by ffp check)

  void describe(std::ostream& out) const override {
    const mpm::Simulation& s = simulation_;
    out << "grid: " << s.grid.r.nodes() << " × " << s.grid.z.nodes() << " nodes, h_min = " << s.grid.min_spacing()
        << " m; particles: " << s.particles.size() << "\n";
    describe_memory(out, size);
    out << "stages: " << s.stages.describe() << "\n";
    out << "CFL time step limit h_min/(c_p + |v|max): " << format_seconds(s.dt_limit_s) << "\n";
    out << "time step: " << format_seconds(s.dt_s)
        << (s.settings.fixed_dt_s ? " (fixed)" : " (Courant " + std::to_string(s.settings.courant) + ", recomputed every step)")
        << "\n";
    out << "steps to end_time_s (at this step): about " << static_cast<long>(std::ceil(scene_.end_time_s / s.dt_s)) << "\n";
    if (s.settings.transfer == mpm::Transfer::usl)
      out << "note: USL takes the strain rate from v_i^{n+1}, which nodes of small mass at cell crossings can blow up\n"
             "      (measured: a bouncing block went unstable at Courant 0.5); MUSL is the robust choice\n";
  }

  void run(RunContext& context) override;

 private:
  std::size_t nearest_particle(const MpmProbe& probe) const {
    const mpm::Particles& p = simulation_.particles;
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
  void write_fields(const fs::path& dir, int index, PvdIndex& pvd) const;

  MpmScene scene_;
  std::string name_;
  mpm::Simulation simulation_;
  double initial_dt_s_;
  std::vector<std::size_t> probe_particles_;
};

std::vector<std::string> MpmJob::columns() const {
  std::vector<std::string> c = {"time_s"};
  c.insert(c.end(), scene_.output.history.begin(), scene_.output.history.end());
  for (const MpmProbe& p : scene_.output.probes)
    for (const char* q : {"r_m", "z_m", "v_r_m_s", "v_z_m_s", "sigma_rr_kPa", "sigma_zz_kPa", "sigma_tt_kPa", "sigma_rz_kPa"})
      c.push_back(p.name + "_" + q);
  return c;
}

std::vector<double> MpmJob::row() const {
  const mpm::Simulation& s = simulation_;
  const mpm::Diagnostics all = mpm::measure(s);
  std::vector<double> r = {s.time_s};
  for (const std::string& q : scene_.output.history) {
    auto global = [&](const std::string& name, const mpm::Diagnostics& d) -> double {
      if (name == "kinetic_energy_J") return d.kinetic_energy_J;
      if (name == "strain_energy_J") return d.strain_energy_J;
      if (name == "gravity_energy_J") return d.gravity_energy_J;
      if (name == "total_energy_J") return d.total_energy_J();
      if (name == "momentum_z_N_s") return d.momentum_z_N_s;
      if (name == "mass_kg") return d.mass_kg;
      if (name == "max_speed_m_s") return d.max_speed_m_s;
      if (name == "mean_z_m") return d.mass_kg > 0 ? d.mass_z_kg_m / d.mass_kg : 0.0;
      if (name == "mean_v_z_m_s") return d.mass_kg > 0 ? d.momentum_z_N_s / d.mass_kg : 0.0;
      return std::numeric_limits<double>::quiet_NaN();
    };
    if (q == "dt_s") {
      r.push_back(s.dt_s);
      continue;
    }
    bool done = false;
    for (std::size_t b = 0; b < scene_.body_names.size() && !done; ++b) {
      const std::string prefix = scene_.body_names[b] + "_";
      if (q.rfind(prefix, 0) == 0) {
        r.push_back(global(q.substr(prefix.size()), mpm::measure_body(s, b)));
        done = true;
      }
    }
    if (!done) r.push_back(global(q, all));
  }
  for (std::size_t p : probe_particles_) {
    const Voigt& sig = s.particles.stress[p];
    r.insert(r.end(), {s.particles.r[p], s.particles.z[p], s.particles.vr[p], s.particles.vz[p], 1e-3 * sig[0],
                       1e-3 * sig[1], 1e-3 * sig[2], 1e-3 * sig[3]});
  }
  return r;
}

void MpmJob::write_fields(const fs::path& dir, int index, PvdIndex& pvd) const {
  const mpm::Simulation& s = simulation_;
  const mpm::Particles& P = s.particles;
  const std::size_t n = P.size();
  std::vector<double> body(n), dr(n), dz(n), srr(n), szz(n), stt(n), srz(n), p(n), q(n), ed(n), density(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Voigt& sig = P.stress[i];
    body[i] = P.body[i];
    dr[i] = P.r[i] - P.r0[i];
    dz[i] = P.z[i] - P.z0[i];
    srr[i] = 1e-3 * sig[0];
    szz[i] = 1e-3 * sig[1];
    stt[i] = 1e-3 * sig[2];
    srz[i] = 1e-3 * sig[3];
    p[i] = 1e-3 * mean_pressure(sig);
    q[i] = 1e-3 * deviatoric_stress(sig);
    ed[i] = deviatoric_strain(P.strain[i]);
    density[i] = P.mass[i] / P.volume[i];
  }
  VtuPointCloud cloud;
  cloud.x = P.r;
  cloud.y = P.z;
  cloud.scalars = {{"body", body},           {"sigma_rr_kPa", srr}, {"sigma_zz_kPa", szz},
                   {"sigma_tt_kPa", stt},    {"sigma_rz_kPa", srz}, {"p_kPa", p},
                   {"q_kPa", q},             {"deviatoric_strain", ed}, {"density_kg_m3", density}};
  cloud.vectors = {{"velocity_m_s", P.vr, P.vz, {}}, {"displacement_m", dr, dz, {}}};
  char file[64];
  std::snprintf(file, sizeof file, "particles_%04d.vtu", index);
  write_vtu(dir / file, cloud);
  pvd.add(s.time_s, file);
}

void MpmJob::run(RunContext& context) {
  mpm::Simulation& s = simulation_;
  const MpmOutput& output = scene_.output;
  if (context.show_progress) std::fprintf(stderr, "mpm stages: %s\n", s.stages.describe().c_str());
  const fs::path fields = context.out_dir / "fields";
  fs::create_directories(fields);
  fs::create_directories(context.out_dir / "plots");
  PvdIndex pvd;
  CsvTable history(columns());
  std::vector<double> t, kinetic, strain, gravity, total;
  auto record = [&] {
    history.add_row(row());
    const mpm::Diagnostics d = mpm::measure(s);
    t.push_back(s.time_s);
    kinetic.push_back(d.kinetic_energy_J);
    strain.push_back(d.strain_energy_J);
    gravity.push_back(d.gravity_energy_J);
    total.push_back(d.total_energy_J());
  };
  const mpm::Diagnostics initial = mpm::measure(s);
  std::size_t next_field = 0;
  int field_index = 0;
  auto fields_due = [&] {
    while (next_field < output.field_times_s.size() && s.time_s >= output.field_times_s[next_field] * (1 - 1e-12)) {
      ++next_field;
      if (next_field == output.field_times_s.size() || s.time_s < output.field_times_s[next_field]) {
        write_fields(fields, field_index++, pvd);
      }
    }
  };
  record();
  fields_due();
  double next_history = output.history_interval_s;
  Progress progress("mpm " + name_, scene_.end_time_s, context.show_progress);
  const double end = scene_.end_time_s;
  ThreadGovernor threads;
  try {
    while (s.time_s < end * (1.0 - 1e-12)) {
      if (s.time_s + s.dt_s > end) s.dt_s = end - s.time_s;  // land on end_time_s
      s.advance();
      if (s.time_s >= next_history * (1.0 - 1e-12) || s.time_s >= end * (1.0 - 1e-12)) {
        record();
        while (next_history <= s.time_s * (1.0 + 1e-12)) next_history += output.history_interval_s;
      }
      fields_due();
      progress.update(s.time_s, s.step);
      threads.poll();
    }
  } catch (const mpm::StepFailure& e) {
    throw RunFailure(std::string("mpm step ") + std::to_string(s.step) + ": " + e.what());
  }
  progress.finish();
  context.steps = s.step;
  history.write(context.out_dir / "history.csv");
  if (pvd.size() > 0) pvd.write(fields / "particles.pvd");

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
  sum["field_files"] = pvd.size();
}

}  // namespace

std::unique_ptr<Job> make_mpm_job(SceneReader& scene, const fs::path&) {
  const std::string name = scene.text("name", "mpm");
  MpmScene parsed = read_mpm_scene(scene);
  std::unique_ptr<MpmJob> job;
  try {
    const mpm::ModelSize size = mpm::estimate_model_size(parsed.model, memory_budget_bytes());
    require_fits_in_memory(size, "mesh",
                           "use larger mesh.cell_r_m / cell_z_m or fewer particles_per_cell in the bodies");
    job = std::make_unique<MpmJob>(std::move(parsed), name);
    job->size = size;
  } catch (const std::invalid_argument& e) {
    throw SceneError(std::string("mpm scene: ") + e.what());
  } catch (const mpm::StepFailure& e) {
    throw SceneError(std::string("mpm scene: ") + e.what());
  }
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
