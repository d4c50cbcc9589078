/// The `ffp` scene kind: a free-fall penetrometer impacting sand (the paper's
/// sections 4–5), axisymmetric MPM with a rigid (section 4.1) or linear
/// elastic (section 5.1) penetrometer, frictional contact and a moving mesh.
///
/// Its keys are read in ffp_scene.cpp, each declared where it is read: `ffp keys ffp`
/// (docs/reference/scenes.md). z points up, with the sand surface at z = 0.
/// Writes history.csv (time_s, penetration_m (+ down), velocity_m_s (+ down), deceleration_g
/// ((R − Mg)/Mg, + when slowing a downward motion), reaction_N (soil on FFP, + up), contact_nodes,
/// soil_kinetic_energy_J, dt_s, impulse_N_s, soil_intrusion_m). reaction_N on a row is the mean over
/// the interval since the previous row (impulse difference / time difference), so Σ reaction·Δt over
/// the rows is the exact impulse; deceleration_g uses the same mean. fields/particles_NNNN.vtu + .pvd,
/// plots/time_histories.png (Fig. 7 style), plots/depth_profiles.png (Fig. 8b,c style),
/// plots/deviatoric_strain_tT.TTT.png (Fig. 9 style) and plots/mean_stress_tT.TTT.png (ffp_output.hpp), and summary
/// figures (ffp_summary.hpp). An ffp (not a cpt) run also writes record.csv and plots/record_profiles.png: its
/// deceleration interpreted as a measured drop is (record_output.hpp).
/// With output.localisation: history columns localised_fraction (the share of the soil particles
/// on a face or an edge of the yield surface whose tangent has lost ellipticity),
/// yield_face_particles, yield_edge_particles, yield_apex_particles (not evaluated),
/// localised_face_particles and localised_edge_particles; fields localised (0/1) and
/// band_angle_deg (band normal from the r axis); summary localised_fraction_max and
/// localised_time_s (the row where it is reached, among the rows where at least
/// localised_fraction_min_yielding particles yield); plots/localisation.png (share and counts
/// against time) and plots/localisation_tT.TTT.png (the map). Evaluated at the rows and fields only.
/// On a saturated sand (soil.saturated): history columns u1_kPa, u1_excess_kPa, u1_particles,
/// u2_kPa, u2_excess_kPa, u2_particles (mpm/cone_pore_pressure.hpp), pore_water_impulse_N_s and
/// buoyancy_N; fields pore_pressure_kPa, excess_pore_pressure_kPa and porosity; record.csv's
/// pore_pressure_kPa is u2; summary u1/u2 extremes and u2's dissipation (pore_pressure_summary.hpp),
/// two_phase_dt_limit_s and time_step_limited_by; plots/pore_pressure.png (u1, u2, hydrostatic).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>

#include "drivers/app/ffp_output.hpp"
#include "drivers/app/ffp_scene.hpp"
#include "drivers/app/ffp_summary.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/app/mpm_run_loop.hpp"
#include "drivers/app/particle_fields.hpp"
#include "drivers/app/pore_pressure_summary.hpp"
#include "drivers/output/csv_writer.hpp"
#include "models/math_constants.hpp"
#include "models/voigt.hpp"
#include "mpm/cone_pore_pressure.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/localisation_map.hpp"
#include "mpm/parallel.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

/// The soil's accumulated plastic deviatoric strain ε_d^p for the fields (0 for the other particles).
std::vector<double> plastic_deviatoric_strain(const mpm::Simulation& s) {
  std::vector<double> ep(s.particles.size(), 0.0);
  s.groups[0].state_output(StateOutput::plastic_deviatoric_strain, s.particles.stress, ep);  // 0 where the law has none
  return ep;
}

/// The deviatoric strain that counts a particle as sheared: 5 %, past what the loose sand's
/// stiffness carries elastically away from the cone (q/3G ≈ 1 % at q = 30 kPa).
constexpr double kShearedZoneStrain = 0.05;

/// The largest radius of a soil particle whose deviatoric strain is at least `threshold`: how far
/// the sheared zone reaches from the axis (a local failure keeps it within a few body radii, a
/// general one spreads it towards the wall). 0 where nothing has sheared that far.
double sheared_zone_radius_m(const mpm::Simulation& s, double threshold) {
  const mpm::MaterialGroup& soil = s.groups[0];
  double reach = 0.0;
  for (std::size_t i = soil.begin; i < soil.end; ++i)
    if (deviatoric_strain(s.particles.strain[i]) >= threshold) reach = std::max(reach, s.particles.r[i]);
  return reach;
}

/// Extremes over every step, and over the history rows, that the samples alone do not hold.
struct Extremes {
  // every step
  double penetration_m = 0.0, intrusion_m = 0.0, deceleration_step_g = -std::numeric_limits<double>::infinity();
  std::size_t contact_nodes = 0, projected_particles = 0;
  double contact_residual_m_s = 0.0;
  double projection_depth_m = 0.0;
  // history rows
  std::size_t disconnected = 0, inflated = 0;
  double volume_ratio = 1.0;
  double localised_fraction = 0.0, localised_time_s = 0.0;  // with output.localisation
  double u1_max_kPa = -std::numeric_limits<double>::infinity(), u1_min_kPa = std::numeric_limits<double>::infinity();
};

class PenetrometerJob : public Job {
 public:
  PenetrometerJob(FfpScene scene, std::string name, mpm::ModelSize size)
      : scene_(std::move(scene)),
        name_(std::move(name)),
        size_(size),
        run_(std::make_unique<mpm::FfpRun>(scene_.model)),
        initial_dt_s_(run_->simulation().dt_s),
        initial_energy_(mpm::measure(run_->simulation())) {
    if (saturated())
      initial_two_phase_step_ = two_phase_step(), initial_cfl_s_ = mpm::cfl_time_step_limit(run_->simulation());
    if (run_->deformable()) initial_penetrometer_energy_ = mpm::measure_body(run_->simulation(), 1);
  }

  void describe(std::ostream& out) const override {
    const mpm::Simulation& s = run_->simulation();
    const mpm::FfpGridLayout& g = run_->layout();
    out << "grid: " << s.grid.r.nodes() << " × " << s.grid.z.nodes() << " nodes, h_min = " << s.grid.min_spacing()
        << " m; moving band rows " << g.band_first << "–" << g.band_last << " (z = " << g.z_nodes_m[g.band_first]
        << " … " << g.z_nodes_m[g.band_last] << " m)\n";
    out << "particles: " << s.particles.size() << " (soil " << run_->soil_particles() << ")\n";
    describe_memory(out, size_);
    if (cpt()) {
      out << "penetrometer: rigid (exact outline, no particles), pushed at " << -scene_.model.velocity_m_s << " m/s to "
          << -scene_.model.velocity_m_s * scene_.end_time_s << " m\n";
    } else {
      out << "penetrometer: "
          << (run_->deformable() ? "linear elastic particles" : "rigid (exact outline, no particles)") << ", mass "
          << run_->penetrometer_mass_kg() << " kg\n";
    }
    out << "stages: " << s.stages.describe() << "\n";
    if (s.two_phase) {
      const TwoPhaseStep& step = *initial_two_phase_step_;
      out << "CFL limit h_min/(c_p + |v|max) of the sand's skeleton: " << initial_cfl_s_ << " s\n";
      out << "two-phase limit (Mieremet 2015, L = h_min): " << step.limit_s << " s, limited by "
          << (step.bounds.drag_limited() ? "the drag 2ρ̃k/(ρ_w g) = " : "the undrained wave L/c_1 = ")
          << (step.bounds.drag_limited() ? step.bounds.drag_s : step.bounds.undrained_wave_s)
          << " s (the other: " << (step.bounds.drag_limited() ? "the undrained wave " : "the drag ")
          << (step.bounds.drag_limited() ? step.bounds.undrained_wave_s : step.bounds.drag_s) << " s)\n";
    }
    out << "CFL limit h_min/(c_p + |v|max): " << s.dt_limit_s << " s; time step " << s.dt_s << " s (Courant "
        << s.settings.courant << ", recomputed every step)\n";
  }

  std::optional<RunCost> cost(bool measure) override {
    if (!measure) return plan_mpm_cost(run_->simulation(), scene_.end_time_s);
    const RunCost measured = measure_mpm_cost(run_->simulation(), scene_.end_time_s);
    run_.reset();  // one model in memory at a time
    run_ = std::make_unique<mpm::FfpRun>(scene_.model);
    return measured;
  }

  void run(RunContext& context) override;

 private:
  bool cpt() const { return scene_.kind == PenetrometerKind::cpt; }
  double weight_N() const { return run_->penetrometer_mass_kg() * scene_.model.gravity_m_s2; }
  /// The reaction over the base area πR²: a cone's q_c (shaft friction included), a punch's mean pressure.
  double base_area_m2() const { return kPi * std::pow(scene_.model.shape.base_radius_m, 2); }
  CsvTable history_table() const;
  void record_row(CsvTable& history, Extremes& e);
  mpm::LocalisationMap soil_localisation() const {
    const mpm::Simulation& s = run_->simulation();
    return mpm::map_localisation(s.groups[0], s.particles.stress);
  }
  void observe_step(Extremes& e) const;
  void observe_row(Extremes& e) const;
  void write_summary(json& sum, const MpmRunResult& result, const Extremes& e, std::size_t field_files) const;
  void write_pore_pressure_summary(json& sum, const Extremes& e) const;
  /// A flat punch's plateau: the mean pressure over its settlement window, from the exact impulse.
  double plateau_pressure_Pa() const {
    const BearingPlateau& b = *scene_.bearing;
    const double R = scene_.model.shape.base_radius_m, v0 = -scene_.model.velocity_m_s;
    return mean_reaction(samples_, b.from_ratio * R / v0, b.to_ratio * R / v0) / base_area_m2();
  }
  void write_plots(const fs::path& plots) const;
  bool saturated() const { return run_->simulation().two_phase.has_value(); }
  /// The saturated sand's two-phase step at the start: Mieremet's limit at its initial state and
  /// Anura3D's two simpler bounds, the smaller of which names the limiting term.
  struct TwoPhaseStep {
    double limit_s = 0.0;
    mpm::TwoPhaseStepBounds bounds;
  };
  TwoPhaseStep two_phase_step() const {
    const mpm::Simulation& s = run_->simulation();
    const mpm::TwoPhase& t = *s.two_phase;
    const mpm::PoreSpace& pores = t.bodies[run_->soil_body()];
    const mpm::TwoPhaseWave wave{pores.initial_porosity, pores.initial_permeability_m_s,    pores.grain_density_kg_m3,
                                 t.fluid.density_kg_m3,  s.groups[0].constrained_modulus(), t.fluid.bulk_modulus_Pa};
    return {mpm::two_phase_time_step_limit(s), mpm::two_phase_step_bounds(wave, s.grid.min_spacing())};
  }

  FfpScene scene_;
  std::string name_;
  mpm::ModelSize size_;
  std::unique_ptr<mpm::FfpRun> run_;
  double initial_dt_s_;
  mpm::Diagnostics initial_energy_, initial_penetrometer_energy_;
  std::vector<FfpSample> samples_;
  std::vector<LocalisationRow> localisation_rows_;      ///< with output.localisation
  std::vector<ShoulderPressureRow> shoulder_rows_;      ///< saturated sand
  std::optional<TwoPhaseStep> initial_two_phase_step_;  ///< saturated sand, at t = 0
  double initial_cfl_s_ = 0.0;                          ///< saturated sand: the skeleton's CFL limit at t = 0
};

CsvTable PenetrometerJob::history_table() const {
  std::vector<std::string> columns = {"time_s", "penetration_m", "velocity_m_s"};
  if (!cpt()) columns.push_back("deceleration_g");
  for (const char* c :
       {"reaction_N", "contact_nodes", "soil_kinetic_energy_J", "dt_s", "impulse_N_s", "soil_intrusion_m"})
    columns.emplace_back(c);
  if (cpt()) columns.emplace_back("mean_pressure_kPa");
  if (!run_->deformable())  // the rigid body's impulse split by where it is taken (PenetrometerState)
    for (const char* c : {"cone_impulse_N_s", "cone_normal_impulse_N_s", "shaft_impulse_N_s"}) columns.emplace_back(c);
  if (scene_.output.localisation)
    for (const char* c : {"localised_fraction", "yield_face_particles", "yield_edge_particles", "yield_apex_particles",
                          "localised_face_particles", "localised_edge_particles"})
      columns.emplace_back(c);
  if (saturated())
    for (const char* c : {"u1_kPa", "u1_excess_kPa", "u1_particles", "u2_kPa", "u2_excess_kPa", "u2_particles",
                          "pore_water_impulse_N_s", "buoyancy_N"})
      columns.emplace_back(c);
  return CsvTable(columns);
}

void PenetrometerJob::record_row(CsvTable& history, Extremes& e) {
  const mpm::FfpRun& ffp = *run_;
  const mpm::Simulation& s = ffp.simulation();
  const mpm::PenetrometerState& st = ffp.state();
  const FfpSample sample = next_ffp_sample(samples_.empty() ? nullptr : &samples_.back(), s.time_s, ffp.penetration_m(),
                                           ffp.velocity_down_m_s(), st.impulse_N_s, weight_N());
  std::vector<double> row = {sample.time_s, sample.penetration_m, sample.velocity_m_s};
  if (!cpt()) row.push_back(sample.deceleration_g);
  row.insert(row.end(), {sample.reaction_N, static_cast<double>(st.contact_nodes),
                         mpm::kinetic_energy_body(s, ffp.soil_body()), s.dt_s, st.impulse_N_s, ffp.soil_intrusion_m()});
  if (cpt()) row.push_back(1e-3 * sample.reaction_N / base_area_m2());
  if (!ffp.deformable()) row.insert(row.end(), {st.cone_impulse_N_s, st.cone_normal_impulse_N_s, st.shaft_impulse_N_s});
  if (scene_.output.localisation) {
    const mpm::LocalisationMap map = soil_localisation();
    const double fraction = map.localised_fraction();
    const LocalisationRow counts{s.time_s,
                                 fraction,
                                 static_cast<double>(map.on_face),
                                 static_cast<double>(map.on_edge),
                                 static_cast<double>(map.at_apex),
                                 static_cast<double>(map.localised_on_face),
                                 static_cast<double>(map.localised_on_edge)};
    row.insert(row.end(),
               {fraction, counts.face, counts.edge, counts.apex, counts.localised_face, counts.localised_edge});
    localisation_rows_.push_back(counts);
    const bool enough = map.on_face + map.on_edge >= mpm::minimum_yielding_for_share(ffp.soil_particles());
    if (enough && fraction > e.localised_fraction) e.localised_fraction = fraction, e.localised_time_s = s.time_s;
  }
  if (saturated()) {
    const mpm::ConePorePressure u = mpm::cone_pore_pressure(ffp);
    row.insert(row.end(), {1e-3 * u.u1.pressure_Pa, 1e-3 * u.u1.excess_Pa, static_cast<double>(u.u1.particles),
                           1e-3 * u.u2.pressure_Pa, 1e-3 * u.u2.excess_Pa, static_cast<double>(u.u2.particles),
                           st.pore_water_impulse_N_s, st.buoyancy_N});
    shoulder_rows_.push_back({s.time_s, sample.velocity_m_s, 1e-3 * u.u2.pressure_Pa, 1e-3 * u.u2.excess_Pa});
    e.u1_max_kPa = std::max(e.u1_max_kPa, 1e-3 * u.u1.pressure_Pa);
    e.u1_min_kPa = std::min(e.u1_min_kPa, 1e-3 * u.u1.pressure_Pa);
  }
  history.add_row(row);
  samples_.push_back(sample);
}

void PenetrometerJob::observe_step(Extremes& e) const {
  const mpm::FfpRun& ffp = *run_;
  const mpm::PenetrometerState& st = ffp.state();
  const double weight = weight_N();
  e.penetration_m = std::max(e.penetration_m, ffp.penetration_m());
  e.intrusion_m = std::max(e.intrusion_m, ffp.soil_intrusion_m());
  e.deceleration_step_g = std::max(e.deceleration_step_g, (st.reaction_N - weight) / weight);
  e.contact_nodes = std::max(e.contact_nodes, st.contact_nodes);
  e.contact_residual_m_s = std::max(e.contact_residual_m_s, st.contact_residual_m_s);
  e.projected_particles = std::max(e.projected_particles, st.projected_particles);
  e.projection_depth_m = std::max(e.projection_depth_m, st.projection_depth_m);
}

void PenetrometerJob::observe_row(Extremes& e) const {
  e.disconnected = std::max(e.disconnected, run_->disconnected_soil_particles());
  const mpm::FfpRun::VolumeRatios ratios = run_->soil_volume_ratios();
  e.volume_ratio = std::max(e.volume_ratio, ratios.max);
  e.inflated = std::max(e.inflated, ratios.inflated);
}

void PenetrometerJob::run(RunContext& context) {
  mpm::Simulation& s = run_->simulation();
  const fs::path plots = context.out_dir / "plots";
  ParticleFieldSeries fields(context.out_dir / "fields");
  fs::create_directories(plots);
  CsvTable history = history_table();
  samples_.clear();
  localisation_rows_.clear();
  shoulder_rows_.clear();
  Extremes extremes;
  MpmRunCallbacks callbacks;
  callbacks.record_row = [&] { record_row(history, extremes); };
  callbacks.after_step = [&] { observe_step(extremes); };
  callbacks.after_step_row = [&] { observe_row(extremes); };
  callbacks.write_fields = [&] {
    ParticleFieldColumns columns{.stress_components = true,
                                 .extra = {{"plastic_deviatoric_strain", plastic_deviatoric_strain(s)}}};
    if (scene_.output.localisation) {
      mpm::LocalisationMap map = soil_localisation();
      write_localisation_map(*run_, name_, map, plots);
      columns.extra.emplace_back("localised", std::move(map.localised));
      columns.extra.emplace_back("band_angle_deg", std::move(map.band_angle_deg));
    }
    for (auto& column : micropolar_columns(s.micropolar)) columns.extra.push_back(std::move(column));
    for (auto& column : pore_fluid_columns(s)) columns.extra.push_back(std::move(column));
    fields.write(s.particles, s.time_s, columns);
    write_strain_map(*run_, name_, scene_.output.strain_colour_max, plots);
    write_pressure_map(*run_, name_, plots);
    if (saturated()) write_excess_pore_pressure_map(*run_, name_, plots);
  };
  const MpmOutputTimes times{scene_.end_time_s, scene_.output.history_interval_s, scene_.output.field_times_s};
  const MpmRunResult result = run_mpm(s, times, callbacks, cpt() ? "cpt" : "ffp", name_, context.show_progress);
  context.steps = result.steps;
  history.write(context.out_dir / "history.csv");
  if (!cpt() && weight_N() > 0.0)
    write_simulated_record(samples_, scene_.model, run_->penetrometer_mass_kg(), name_, context.out_dir, plots,
                           shoulder_rows_);
  fields.finish();
  write_summary(context.summary, result, extremes, fields.size());
  write_plots(plots);
}

void PenetrometerJob::write_summary(json& sum, const MpmRunResult& result, const Extremes& e,
                                    std::size_t field_files) const {
  const mpm::FfpRun& ffp = *run_;
  const mpm::Simulation& s = ffp.simulation();
  const double M = ffp.penetrometer_mass_kg(), weight = weight_N(), h = scene_.model.mesh.min_cell_m;
  const double v0 = -scene_.model.velocity_m_s;  // + down
  const FfpFigures f = ffp_figures(samples_, {M, weight, v0, scene_.end_time_s, e.penetration_m});
  if (!cpt()) {
    sum["peak_deceleration_g"] = f.peak_deceleration_g;
    if (std::isfinite(f.peak_deceleration_2ms_g)) sum["peak_deceleration_2ms_g"] = f.peak_deceleration_2ms_g;
    sum["time_of_peak_s"] = f.time_of_peak_s;
    sum["depth_of_peak_m"] = f.depth_of_peak_m;
    sum["peak_deceleration_step_g"] = e.deceleration_step_g;
    sum["momentum_balance_error"] = f.momentum_balance_error;
    sum["impact_velocity_m_s"] = v0;
    sum["final_velocity_m_s"] = f.final_velocity_m_s;
    sum["penetrometer_mass_kg"] = M;
  } else {
    sum["push_velocity_m_s"] = v0;
    sum["time_of_peak_s"] = f.time_of_peak_reaction_s;
    if (scene_.bearing) {
      const BearingPlateau& b = *scene_.bearing;
      const double pressure_Pa = plateau_pressure_Pa();
      sum["plateau_mean_pressure_kPa"] = 1e-3 * pressure_Pa;
      sum["plateau_settlement_ratio"] = {b.from_ratio, b.to_ratio};
      sum["bearing_factor"] = pressure_Pa / b.cohesion_Pa;
      sum["cohesion_kPa"] = 1e-3 * b.cohesion_Pa;
    }
  }
  sum["peak_reaction_N"] = f.peak_reaction_N;
  sum["depth_of_peak_reaction_m"] = f.depth_of_peak_reaction_m;
  sum["max_penetration_m"] = f.max_penetration_m;
  sum["final_penetration_m"] = f.final_penetration_m;
  sum["rebound_m"] = f.rebound_m;
  sum["final_reaction_N"] = f.final_reaction_N;
  sum["final_reaction_window_s"] = f.final_reaction_window_s;
  // At rest the inertia part is 0 and the mean reaction is the weight; a body still bouncing carries it too.
  if (!cpt() && f.final_reaction_window_s > 0.0) sum["final_reaction_inertia_N"] = f.final_reaction_inertia_N;
  sum["penetrometer_weight_N"] = weight;
  sum["particles"] = s.particles.size();
  sum["soil_particles"] = ffp.soil_particles();
  sum["dt_s"] = initial_dt_s_;
  sum["dt_min_s"] = result.dt_min_s;
  sum["max_soil_intrusion_m"] = e.intrusion_m;
  sum["max_soil_intrusion_cells"] = e.intrusion_m / h;
  // contact.project_particles: the most particles put back onto the outline in one step, and the
  // deepest one of them before it was (the intrusion of one step; 0 without the projection).
  sum["projected_particles_max"] = e.projected_particles;
  sum["max_projection_depth_m"] = e.projection_depth_m;
  sum["max_projection_depth_cells"] = e.projection_depth_m / h;
  sum["contact_nodes_max"] = e.contact_nodes;
  // contact.surface particles: the largest velocity change of a step's last Gauss–Seidel sweep
  // (the solver stops at 200 sweeps; 0 with the nodes' contact, which needs no iteration).
  sum["max_contact_residual_m_s"] = e.contact_residual_m_s;
  sum["disconnected_particles_max"] = e.disconnected;  // at the history rows
  sum["max_volume_ratio"] = e.volume_ratio;            // largest V/V0 of a soil particle, at the history rows
  sum["inflated_particles_max"] = e.inflated;          // most soil particles with V/V0 > 2 at one history row
  if (scene_.output.localisation) {
    sum["localised_fraction_max"] = e.localised_fraction;  // at the history rows
    sum["localised_time_s"] = e.localised_time_s;
    sum["localised_fraction_min_yielding"] = mpm::minimum_yielding_for_share(ffp.soil_particles());
  }
  sum["sheared_zone_radius_m"] = sheared_zone_radius_m(s, kShearedZoneStrain);  // at the end
  sum["sheared_zone_strain"] = kShearedZoneStrain;
  if (saturated()) write_pore_pressure_summary(sum, e);
  sum["grid_nodes"] = {s.grid.r.nodes(), s.grid.z.nodes()};
  sum["min_cell_m"] = h;
  sum["penetrometer"] = ffp.deformable() ? "linear_elastic" : "rigid";
  if (ffp.deformable()) {
    // Energy (kinetic + recoverable elastic + m g z, full 2π) of the whole model and of the
    // penetrometer at the start and the end: what the soil's plasticity, the contact friction
    // and the transfers dissipated, and no energy from nowhere.
    const mpm::Diagnostics end = mpm::measure(s), body = mpm::measure_body(s, 1);
    sum["energy_initial_J"] = initial_energy_.total_energy_J();
    sum["energy_final_J"] = end.total_energy_J();
    sum["penetrometer_energy_initial_J"] = initial_penetrometer_energy_.total_energy_J();
    sum["penetrometer_energy_final_J"] = body.total_energy_J();
    sum["penetrometer_strain_energy_final_J"] = body.strain_energy_J;
    sum["subcycled"] = ffp.subcycle() != nullptr;
    if (const mpm::BodySubcycle* sub = ffp.subcycle()) {
      sum["penetrometer_substeps"] = sub->total_substeps();
      sum["penetrometer_substeps_last_step"] = sub->last_substeps();
      // Work of the soil's contact forces on the body's nodes: its energy change but for
      // what the transfers (FLIP/PIC) lose; relative to the impact energy.
      sum["penetrometer_contact_work_J"] = sub->contact_work_J();
      const double impact = initial_penetrometer_energy_.kinetic_energy_J;
      sum["penetrometer_energy_balance_error"] =
          (body.total_energy_J() - initial_penetrometer_energy_.total_energy_J() - sub->contact_work_J()) / impact;
    }
  }
  sum["stages"] = s.stages.names();
  sum["mpm_threads"] = mpm::thread_count();
  sum["wall_clamps"] = s.wall_clamps;
  sum["field_files"] = field_files;
}

void PenetrometerJob::write_pore_pressure_summary(json& sum, const Extremes& e) const {
  const ShoulderPressureFigures u2 = shoulder_pressure_figures(shoulder_rows_);
  sum["u1_max_kPa"] = e.u1_max_kPa;  // at the history rows, as every u figure
  sum["u1_min_kPa"] = e.u1_min_kPa;
  sum["u2_peak_kPa"] = u2.peak_kPa;
  sum["u2_time_of_peak_s"] = u2.time_of_peak_s;
  sum["u2_min_kPa"] = u2.min_kPa;
  sum["u2_time_of_min_s"] = u2.time_of_min_s;
  sum["rest_time_s"] = u2.rest_time_s ? json(*u2.rest_time_s) : json(nullptr);
  sum["u2_excess_at_rest_kPa"] = u2.excess_at_rest_kPa;
  sum["u2_dissipation_time_s"] = u2.dissipation_time_s ? json(*u2.dissipation_time_s) : json(nullptr);
  if (!u2.dissipation_time_s) sum["u2_dissipation_note"] = u2.dissipation_note;
  // At the start, as dt_s.
  const TwoPhaseStep& step = *initial_two_phase_step_;
  sum["two_phase_dt_limit_s"] = step.limit_s;
  sum["time_step_limited_by"] = step.limit_s < initial_cfl_s_
                                    ? (step.bounds.drag_limited() ? "two-phase: drag" : "two-phase: undrained wave")
                                    : "CFL of the skeleton";
  // Particles whose porosity was held at the closed-pore floor (mpm/two_phase.hpp), the most at one step.
  sum["closed_pore_particles_max"] = run_->simulation().two_phase->closed_pores_max;
  sum["water_depth_m"] = scene_.model.soil.water_depth_m;
  sum["buoyancy_final_N"] = run_->state().buoyancy_N;
}

void PenetrometerJob::write_plots(const fs::path& plots) const {
  if (cpt() && scene_.bearing) {
    const BearingPlateau& b = *scene_.bearing;
    write_pressure_settlement_plot(samples_, name_,
                                   {scene_.model.shape.base_radius_m, base_area_m2(), b.cohesion_Pa, b.from_ratio,
                                    b.to_ratio, plateau_pressure_Pa() / b.cohesion_Pa},
                                   plots);
  } else if (cpt()) {
    write_cpt_plot(samples_, name_, plots);
  } else {
    write_ffp_plots(samples_, name_, plots);
  }
  if (scene_.output.localisation) write_localisation_plot(localisation_rows_, name_, plots);
  if (saturated()) write_pore_pressure_plot(shoulder_rows_, name_, plots);
}

}  // namespace

std::unique_ptr<Job> make_penetrometer_job(FfpScene scene, std::string name) {
  return build_mpm_model("ffp", [&]() -> std::unique_ptr<Job> {
    const mpm::ModelSize size = mpm::estimate_ffp_size(scene.model, memory_budget_bytes());
    require_fits_in_memory(size, "mesh.min_cell_m",
                           "use a coarser mesh.min_cell_m (the particle count grows as 1/h²), fewer "
                           "soil.particles_per_cell_near or a smaller soil.near_radius_m");
    return std::make_unique<PenetrometerJob>(std::move(scene), std::move(name), size);
  });
}

std::unique_ptr<Job> make_ffp_job(SceneReader& scene, const fs::path&) {
  std::string name = read_scene_name(scene, "ffp");
  return make_penetrometer_job(read_ffp_scene(scene, PenetrometerKind::ffp), std::move(name));
}

}  // namespace ffp
