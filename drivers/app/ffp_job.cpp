/// The `ffp` scene kind: a free-fall penetrometer impacting sand (the paper's
/// sections 4–5), axisymmetric MPM with a rigid (section 4.1) or linear
/// elastic (section 5.1) penetrometer, frictional contact and a moving mesh.
///
/// Scene keys (geotechnical units where the key says so; z up, sand surface z = 0):
///   end_time_s, gravity_m_s2 (9.81)
///   material   {model mohr_coulomb | ssmc | linear_elastic, E_kPa, nu, phi_peak_deg, …, density_kg_m3}
///   soil       {depth_m 0.4, radius_m 0.4, k0 (Jaky 1 − sin φ'_p), particles_per_cell_near [3,3] (per
///               min_cell², same spacing in larger cells), particles_per_cell_far [2,2] (per cell),
///               near_radius_m 0.15, near_depth_m (depth_m)}
///   ffp        {mass_kg, impact_velocity_m_s (+ down), cone_apex_angle_deg 60, base_radius_m 0.04375,
///               edge_radius_m 0.005, body_length_m 0.5,
///               rigid: rigid_body_force contact_impulse | soil_internal_force, external_force_N (+ up);
///               elastic: deformable {E_kPa, nu, particles_per_cell [2,2]}}
///   contact    {delta_deg | rough: true, velocity_scaling 0.75 (a cap on a correction's strain per step,
///               Bardenhagen 2001 as the paper's code applies it), detection_cells 0.5 (nodes this many
///               min cells outside the outline also touch: the contact surface centred on the outline)}
///   mesh       {min_cell_m 0.01, max_cell_m 3·min, below_cell_m 2·min, fine_radius_m 0.15,
///               band_below_m 0.05, fine_above_m 0.3, air_above_m 0.1, growth 1.2}
///   solver     {shape_function gimp | linear, transfer usl | musl | musl_remapped, flip_fraction 0.99,
///               pic_blend per_soil_step | per_step (the PIC share 1 − flip_fraction per soil CFL step
///               at Courant 0.5, scaled by Δt/Δt_soil; or per step whatever Δt: mpm/ffp_model.hpp),
///               courant 0.5, strain_smoothing true}
///   output     {history_interval_s 2e-4, field_times_s [0.04, 0.06, end], strain_colour_max 0.5}
/// Writes history.csv (time_s, penetration_m (+ down), velocity_m_s (+ down), deceleration_g
/// ((R − Mg)/Mg, + when slowing a downward motion), reaction_N (soil on FFP, + up), contact_nodes,
/// soil_kinetic_energy_J, dt_s, impulse_N_s, soil_intrusion_m). reaction_N on a row is the mean over
/// the interval since the previous row (impulse difference / time difference), so Σ reaction·Δt over
/// the rows is the exact impulse; deceleration_g uses the same mean. fields/particles_NNNN.vtu + .pvd,
/// plots/time_histories.png (Fig. 7 style), plots/depth_profiles.png (Fig. 8b,c style),
/// plots/deviatoric_strain_tT.TTT.png (Fig. 9 style), and summary figures (see run()). An ffp (not a
/// cpt) run also writes record.csv and plots/record_profiles.png: its deceleration interpreted as a
/// measured drop is (record_output.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <ostream>

#include "drivers/app/ffp_scene.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/app/record_output.hpp"
#include "drivers/app/thread_governor.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "drivers/output/vtu_writer.hpp"
#include "models/voigt.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/parallel.hpp"
#include "reports/plot.hpp"
#include "models/math_constants.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

class PenetrometerJob : public Job {
 public:
  PenetrometerJob(FfpScene scene, std::string name, mpm::ModelSize size)
      : scene_(std::move(scene)), name_(std::move(name)), size_(size),
        run_(std::make_unique<mpm::FfpRun>(scene_.model)), initial_dt_s_(run_->simulation().dt_s) {}

  void describe(std::ostream& out) const override {
    const mpm::Simulation& s = run_->simulation();
    const mpm::FfpGridLayout& g = run_->layout();
    out << "grid: " << s.grid.r.nodes() << " × " << s.grid.z.nodes() << " nodes, h_min = " << s.grid.min_spacing()
        << " m; moving band rows " << g.band_first << "–" << g.band_last << " (z = " << g.z_nodes_m[g.band_first]
        << " … " << g.z_nodes_m[g.band_last] << " m)\n";
    out << "particles: " << s.particles.size() << " (soil " << run_->soil_particles() << ")\n";
    describe_memory(out, size_);
    if (cpt()) {
      out << "penetrometer: rigid (exact outline, no particles), pushed at " << -scene_.model.velocity_m_s
          << " m/s to " << -scene_.model.velocity_m_s * scene_.end_time_s << " m\n";
    } else {
      out << "penetrometer: " << (run_->deformable() ? "linear elastic particles" : "rigid (exact outline, no particles)")
          << ", mass " << run_->penetrometer_mass_kg() << " kg\n";
    }
    out << "stages: " << s.stages.describe() << "\n";
    out << "CFL limit h_min/(c_p + |v|max): " << s.dt_limit_s << " s; time step " << s.dt_s << " s (Courant "
        << s.settings.courant << ", recomputed every step)\n";
    out << "steps to end_time_s (at the initial step): about " << static_cast<long>(std::ceil(scene_.end_time_s / s.dt_s))
        << "\n";
  }

  void run(RunContext& context) override;

 private:
  bool cpt() const { return scene_.kind == PenetrometerKind::cpt; }
  void write_fields(const fs::path& fields, const fs::path& plots, int index, PvdIndex& pvd) const;
  void write_record(const std::vector<double>& time_s, const std::vector<double>& deceleration_g,
                    const fs::path& out_dir, const fs::path& plots) const;

  FfpScene scene_;
  std::string name_;
  mpm::ModelSize size_;
  std::unique_ptr<mpm::FfpRun> run_;
  double initial_dt_s_;
};

/// The outline as a polyline in (r, z), from the tip up to z_max.
Series outline(const mpm::FfpRun& run, double z_max) {
  Series s;
  s.title = "penetrometer";
  s.style = "lines";
  const double tip = run.tip_z_m(), length = run.geometry().shape().total_length_m();
  const double top = std::min(length, z_max - tip);
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double h = top * k / n;
    s.x.push_back(run.geometry().radius_at(std::min(h, length)));
    s.y.push_back(tip + h);
  }
  return s;
}

void PenetrometerJob::write_fields(const fs::path& fields, const fs::path& plots, int index, PvdIndex& pvd) const {
  const mpm::Simulation& s = run_->simulation();
  const mpm::Particles& P = s.particles;
  const std::size_t n = P.size();
  std::vector<double> body(n), dr(n), dz(n), p(n), q(n), ed(n), ep(n, 0.0), density(n);
  for (std::size_t i = 0; i < n; ++i) {
    body[i] = P.body[i];
    dr[i] = P.r[i] - P.r0[i];
    dz[i] = P.z[i] - P.z0[i];
    p[i] = 1e-3 * mean_pressure(P.stress[i]);
    q[i] = 1e-3 * deviatoric_stress(P.stress[i]);
    ed[i] = deviatoric_strain(P.strain[i]);
    density[i] = P.mass[i] / P.volume[i];
  }
  const mpm::MaterialGroup& soil = s.groups[0];
  soil.state_output(StateOutput::plastic_deviatoric_strain, P.stress, ep);  // zero where the law has no such state
  VtuPointCloud cloud;
  cloud.x = P.r;
  cloud.y = P.z;
  cloud.scalars = {{"body", body},           {"p_kPa", p},           {"q_kPa", q},
                   {"deviatoric_strain", ed}, {"plastic_deviatoric_strain", ep}, {"density_kg_m3", density}};
  cloud.vectors = {{"velocity_m_s", P.vr, P.vz, {}}, {"displacement_m", dr, dz, {}}};
  char file[64];
  std::snprintf(file, sizeof file, "particles_%04d.vtu", index);
  write_vtu(fields / file, cloud);
  pvd.add(s.time_s, file);

  // Fig. 9: the soil's accumulated deviatoric strain, the outline on top.
  ColourMap map;
  char title[160];
  std::snprintf(title, sizeof title, "%s: deviatoric strain at t = %.3f s (penetration %.3f m)", name_.c_str(), s.time_s,
                run_->penetration_m());
  map.title = title;
  map.x_label = "r (m)";
  map.y_label = "z (m)";
  map.colour_label = "deviatoric strain";
  for (std::size_t i = soil.begin; i < soil.end; ++i) {
    map.x.push_back(P.r[i]);
    map.y.push_back(P.z[i]);
    map.value.push_back(ed[i]);
  }
  double z_top = 0.0;
  for (double z : map.y) z_top = std::max(z_top, z);
  map.overlays.push_back(outline(*run_, z_top + 0.05));
  map.colour_min = 0.0;
  map.colour_max = scene_.output.strain_colour_max;
  map.point_size = 0.3;
  std::snprintf(file, sizeof file, "deviatoric_strain_t%.3f.png", s.time_s);
  write_png(map, plots / file);
}

/// The run's deceleration read as a measured record would be (the `record` kind's
/// interpretation, impact at t = 0 with the known impact velocity): record.csv and
/// plots/record_profiles.png, so a simulation and a drop compare column for column.
void PenetrometerJob::write_record(const std::vector<double>& time_s, const std::vector<double>& deceleration_g,
                                   const fs::path& out_dir, const fs::path& plots) const {
  RecordSettings settings;
  settings.mass_kg = run_->penetrometer_mass_kg();
  settings.gravity_m_s2 = scene_.model.gravity_m_s2;
  settings.tip = {scene_.model.shape.base_radius_m, scene_.model.shape.cone_height_m()};
  settings.impact_velocity_m_s = -scene_.model.velocity_m_s;
  settings.impact_time_s = 0.0;
  settings.rate_laws = default_rate_laws();
  const InterpretedRecord record = interpret_record(time_s, deceleration_g, settings);
  record_table(record, settings).write(out_dir / "record.csv");
  write_record_plots(record, settings, name_, plots / "record_profiles.png");
}

void PenetrometerJob::run(RunContext& context) {
  mpm::FfpRun& ffp = *run_;
  mpm::Simulation& s = ffp.simulation();
  const FfpOutput& output = scene_.output;
  const double M = ffp.penetrometer_mass_kg(), g = scene_.model.gravity_m_s2, weight = M * g;
  const double h = scene_.model.mesh.min_cell_m;
  if (context.show_progress) std::fprintf(stderr, "%s stages: %s\n", cpt() ? "cpt" : "ffp", s.stages.describe().c_str());
  const fs::path fields = context.out_dir / "fields", plots = context.out_dir / "plots";
  fs::create_directories(fields);
  fs::create_directories(plots);

  std::vector<std::string> columns = {"time_s", "penetration_m", "velocity_m_s"};
  if (!cpt()) columns.push_back("deceleration_g");
  for (const char* c : {"reaction_N", "contact_nodes", "soil_kinetic_energy_J", "dt_s", "impulse_N_s", "soil_intrusion_m"})
    columns.emplace_back(c);
  // The reaction over the base area πR²: a cone's q_c (shaft friction included), a punch's mean pressure.
  const double base_area_m2 = kPi * std::pow(scene_.model.shape.base_radius_m, 2);
  if (cpt()) columns.emplace_back("mean_pressure_kPa");
  CsvTable history(columns);
  std::vector<double> t_row, depth_row, velocity_row, deceleration_row, reaction_row, impulse_row;
  double last_t = 0.0, last_impulse = 0.0;
  auto record = [&] {
    const mpm::PenetrometerState& st = ffp.state();
    const double interval = s.time_s - last_t;
    const double reaction = interval > 0.0 ? (st.impulse_N_s - last_impulse) / interval : 0.0;
    last_t = s.time_s;
    last_impulse = st.impulse_N_s;
    const double deceleration = (reaction - weight) / weight;
    std::vector<double> row = {s.time_s, ffp.penetration_m(), ffp.velocity_down_m_s()};
    if (!cpt()) row.push_back(deceleration);
    row.insert(row.end(), {reaction, static_cast<double>(st.contact_nodes), mpm::measure_body(s, ffp.soil_body()).kinetic_energy_J,
                           s.dt_s, st.impulse_N_s, ffp.soil_intrusion_m()});
    if (cpt()) row.push_back(1e-3 * reaction / base_area_m2);
    history.add_row(row);
    t_row.push_back(s.time_s);
    depth_row.push_back(ffp.penetration_m());
    velocity_row.push_back(ffp.velocity_down_m_s());
    deceleration_row.push_back(deceleration);
    reaction_row.push_back(reaction);
    impulse_row.push_back(st.impulse_N_s);
  };

  PvdIndex pvd;
  std::size_t next_field = 0;
  int field_index = 0;
  auto fields_due = [&] {
    bool due = false;
    while (next_field < output.field_times_s.size() && s.time_s >= output.field_times_s[next_field] * (1 - 1e-12)) {
      ++next_field;
      due = true;
    }
    if (due) write_fields(fields, plots, field_index++, pvd);
  };

  record();
  fields_due();
  double next_history = output.history_interval_s;
  double max_penetration = 0.0, intrusion = 0.0, dt_min = s.dt_s, peak_step = -std::numeric_limits<double>::infinity();
  std::size_t most_contact_nodes = 0, most_disconnected = 0, most_inflated = 0, most_projected = 0;
  double projection_depth = 0.0;
  double max_volume_ratio = 1.0;
  const double end = scene_.end_time_s;
  Progress progress(std::string(cpt() ? "cpt " : "ffp ") + name_, end, context.show_progress);
  ThreadGovernor threads;
  try {
    while (s.time_s < end * (1.0 - 1e-12)) {
      if (s.time_s + s.dt_s > end) s.dt_s = end - s.time_s;  // land on end_time_s
      dt_min = std::min(dt_min, s.dt_s);
      s.advance();
      max_penetration = std::max(max_penetration, ffp.penetration_m());
      intrusion = std::max(intrusion, ffp.soil_intrusion_m());
      peak_step = std::max(peak_step, (ffp.state().reaction_N - weight) / weight);
      most_contact_nodes = std::max(most_contact_nodes, ffp.state().contact_nodes);
      most_projected = std::max(most_projected, ffp.state().projected_particles);
      projection_depth = std::max(projection_depth, ffp.state().projection_depth_m);
      if (s.time_s >= next_history * (1.0 - 1e-12) || s.time_s >= end * (1.0 - 1e-12)) {
        record();
        most_disconnected = std::max(most_disconnected, ffp.disconnected_soil_particles());
        const mpm::FfpRun::VolumeRatios ratios = ffp.soil_volume_ratios();
        max_volume_ratio = std::max(max_volume_ratio, ratios.max);
        most_inflated = std::max(most_inflated, ratios.inflated);
        while (next_history <= s.time_s * (1.0 + 1e-12)) next_history += output.history_interval_s;
      }
      fields_due();
      progress.update(s.time_s, s.step);
      threads.poll();
    }
  } catch (const mpm::StepFailure& e) {
    throw RunFailure(std::string(cpt() ? "cpt" : "ffp") + " step " + std::to_string(s.step) + ": " + e.what());
  }
  progress.finish();
  context.steps = s.step;
  history.write(context.out_dir / "history.csv");
  if (!cpt() && weight > 0.0) write_record(t_row, deceleration_row, context.out_dir, plots);
  if (pvd.size() > 0) pvd.write(fields / "particles.pvd");

  // Figures.
  const std::size_t rows = t_row.size();
  std::size_t peak_row = 0, peak_reaction_row = 0;
  for (std::size_t k = 1; k < rows; ++k) {
    if (deceleration_row[k] > deceleration_row[peak_row]) peak_row = k;
    if (reaction_row[k] > reaction_row[peak_reaction_row]) peak_reaction_row = k;
  }
  // "Final" reaction: the mean over the last 10 ms (or tenth of the run), read from the exact impulse.
  const double window = std::min(0.01, 0.1 * end);
  std::size_t from = rows - 1;
  while (from > 0 && t_row[from] > s.time_s - window) --from;
  const double final_reaction =
      s.time_s > t_row[from] ? (ffp.state().impulse_N_s - impulse_row[from]) / (s.time_s - t_row[from]) : 0.0;
  const double v0 = -scene_.model.velocity_m_s;  // + down
  const double v_end = ffp.velocity_down_m_s();
  // M(v0 − v) = ∫(R − Mg) dt for the penetrometer; zero up to round-off when the impulse drives it exactly.
  const double balance = M * (v0 - v_end) - (ffp.state().impulse_N_s - weight * s.time_s);

  // The peak of the 2 ms running mean (centred), from the exact impulse: the cell-crossing
  // ripple (~1.5 ms at 1 cm and 4 m/s) averaged out, as an accelerometer's filter would.
  auto impulse_at = [&](double time) {
    const auto it = std::lower_bound(t_row.begin(), t_row.end(), time);
    if (it == t_row.begin()) return impulse_row.front();
    if (it == t_row.end()) return impulse_row.back();
    const std::size_t k = static_cast<std::size_t>(it - t_row.begin());
    return impulse_row[k - 1] + (impulse_row[k] - impulse_row[k - 1]) * (time - t_row[k - 1]) / (t_row[k] - t_row[k - 1]);
  };
  double peak_2ms = -std::numeric_limits<double>::infinity();
  for (double centre : t_row) {
    const double a = std::max(0.0, centre - 0.001), b = std::min(s.time_s, centre + 0.001);
    if (b - a < 0.0019) continue;
    peak_2ms = std::max(peak_2ms, ((impulse_at(b) - impulse_at(a)) / (b - a) - weight) / weight);
  }

  json& sum = context.summary;
  if (!cpt()) {
    sum["peak_deceleration_g"] = deceleration_row[peak_row];
    if (std::isfinite(peak_2ms)) sum["peak_deceleration_2ms_g"] = peak_2ms;
    sum["time_of_peak_s"] = t_row[peak_row];
    sum["depth_of_peak_m"] = depth_row[peak_row];
    sum["peak_deceleration_step_g"] = peak_step;
    sum["momentum_balance_error"] = v0 > 0.0 ? std::abs(balance) / (M * v0) : std::abs(balance) / weight;
    sum["impact_velocity_m_s"] = v0;
    sum["final_velocity_m_s"] = v_end;
    sum["penetrometer_mass_kg"] = M;
  } else {
    sum["push_velocity_m_s"] = v0;
    sum["time_of_peak_s"] = t_row[peak_reaction_row];
    if (scene_.bearing) {
      // The plateau mean pressure: the mean over the settlement window, from the exact impulse.
      const BearingPlateau& b = *scene_.bearing;
      const double R = scene_.model.shape.base_radius_m;
      const double t1 = b.from_ratio * R / v0, t2 = b.to_ratio * R / v0;
      const double pressure_Pa = (impulse_at(t2) - impulse_at(t1)) / (t2 - t1) / base_area_m2;
      sum["plateau_mean_pressure_kPa"] = 1e-3 * pressure_Pa;
      sum["plateau_settlement_ratio"] = {b.from_ratio, b.to_ratio};
      sum["bearing_factor"] = pressure_Pa / b.cohesion_Pa;
      sum["cohesion_kPa"] = 1e-3 * b.cohesion_Pa;
    }
  }
  sum["peak_reaction_N"] = reaction_row[peak_reaction_row];
  sum["depth_of_peak_reaction_m"] = depth_row[peak_reaction_row];
  sum["max_penetration_m"] = max_penetration;
  sum["final_penetration_m"] = ffp.penetration_m();
  sum["rebound_m"] = max_penetration - ffp.penetration_m();
  sum["final_reaction_N"] = final_reaction;
  sum["final_reaction_window_s"] = s.time_s - t_row[from];
  // The part of that mean that decelerates the body, M Δv/Δt over the window: at rest it is 0
  // and the mean reaction is the weight; a body still bouncing at the end carries it too.
  if (!cpt() && s.time_s > t_row[from])
    sum["final_reaction_inertia_N"] = M * (velocity_row[from] - v_end) / (s.time_s - t_row[from]);
  sum["penetrometer_weight_N"] = weight;
  sum["particles"] = s.particles.size();
  sum["soil_particles"] = ffp.soil_particles();
  sum["dt_s"] = initial_dt_s_;
  sum["dt_min_s"] = dt_min;
  sum["max_soil_intrusion_m"] = intrusion;
  sum["max_soil_intrusion_cells"] = intrusion / h;
  // contact.project_particles: the most particles put back onto the outline in one step, and the
  // deepest one of them before it was (the intrusion of one step; 0 without the projection).
  sum["projected_particles_max"] = most_projected;
  sum["max_projection_depth_m"] = projection_depth;
  sum["max_projection_depth_cells"] = projection_depth / h;
  sum["contact_nodes_max"] = most_contact_nodes;
  sum["disconnected_particles_max"] = most_disconnected;  // at the history rows
  sum["max_volume_ratio"] = max_volume_ratio;            // largest V/V0 of a soil particle, at the history rows
  sum["inflated_particles_max"] = most_inflated;         // most soil particles with V/V0 > 2 at one history row
  sum["grid_nodes"] = {s.grid.r.nodes(), s.grid.z.nodes()};
  sum["min_cell_m"] = h;
  sum["penetrometer"] = ffp.deformable() ? "linear_elastic" : "rigid";
  sum["stages"] = s.stages.names();
  sum["mpm_threads"] = mpm::thread_count();
  sum["wall_clamps"] = s.wall_clamps;
  sum["field_files"] = pvd.size();

  // Plots: time histories (Fig. 7) and profiles against depth (Fig. 8b,c).
  auto plot = [&](const std::vector<double>& x, const std::vector<double>& y, const std::string& x_label,
                  const std::string& y_label, const std::string& title) {
    Plot p;
    p.title = title;
    p.x_label = x_label;
    p.y_label = y_label;
    p.series = {{x, y, name_}};
    p.key_position = "off";
    return p;
  };
  if (cpt() && scene_.bearing) {
    // Pressure–settlement curve, normalised: p/c' against s/R, the plateau window marked.
    const double R = scene_.model.shape.base_radius_m, c = scene_.bearing->cohesion_Pa;
    std::vector<double> ratio(rows), factor(rows);
    for (std::size_t k = 0; k < rows; ++k) {
      ratio[k] = depth_row[k] / R;
      factor[k] = reaction_row[k] / base_area_m2 / c;
    }
    Plot p = plot(ratio, factor, "settlement / radius s/R", "mean pressure / c'", name_ + ": pressure–settlement");
    const double n = sum["bearing_factor"].get<double>();
    p.series.push_back({{scene_.bearing->from_ratio, scene_.bearing->to_ratio}, {n, n}, "plateau mean"});
    p.key_position = "bottom right";
    write_png(p, plots / "pressure_settlement.png");
  } else if (cpt()) {
    Plot p = plot(depth_row, reaction_row, "penetration (m)", "reaction F_0 (N)", name_ + ": static reaction profile");
    write_png(p, plots / "reaction_profile.png");
  } else {
    Plot depth = plot(t_row, depth_row, "time (s)", "penetration (m)", name_ + ": penetration");
    depth.reverse_y = true;
    write_png_stack({depth, plot(t_row, velocity_row, "time (s)", "velocity (m/s)", "velocity"),
                     plot(t_row, deceleration_row, "time (s)", "deceleration (g)", "deceleration"),
                     plot(t_row, reaction_row, "time (s)", "reaction (N)", "reaction")},
                    plots / "time_histories.png");
    write_png_stack({plot(depth_row, velocity_row, "penetration (m)", "velocity (m/s)", name_ + ": velocity profile"),
                     plot(depth_row, deceleration_row, "penetration (m)", "deceleration (g)", "deceleration profile")},
                    plots / "depth_profiles.png");
  }
}

}  // namespace

std::unique_ptr<Job> make_penetrometer_job(FfpScene scene, std::string name) {
  try {
    const mpm::ModelSize size = mpm::estimate_ffp_size(scene.model, memory_budget_bytes());
    require_fits_in_memory(size, "mesh.min_cell_m",
                           "use a coarser mesh.min_cell_m (the particle count grows as 1/h²), fewer "
                           "soil.particles_per_cell_near or a smaller soil.near_radius_m");
    return std::make_unique<PenetrometerJob>(std::move(scene), std::move(name), size);
  } catch (const std::invalid_argument& e) {
    throw SceneError(std::string("ffp scene: ") + e.what());
  } catch (const mpm::StepFailure& e) {
    throw SceneError(std::string("ffp scene: ") + e.what());
  }
}

std::unique_ptr<Job> make_ffp_job(SceneReader& scene, const fs::path&) {
  std::string name = scene.text("name", "ffp");
  return make_penetrometer_job(read_ffp_scene(scene, PenetrometerKind::ffp), std::move(name));
}

}  // namespace ffp
