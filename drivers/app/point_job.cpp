/// The `point` scene kind: one material point along a stress/strain path.
///
/// Scene (geotechnical units: kPa, compression positive for stress and strain):
///   material            see drivers/scene/material_scene.hpp (density not used)
///   initial_stress_kPa  [σ11, σ22, σ33, σ12, σ23, σ13], or initial_pressure_kPa
///                       (default: the path's confining stress, else 0)
///   initial_state       {plastic_deviatoric_strain, strain_rate_per_s} (ssmc only)
///   path.type           isotropic | oedometric | triaxial_compression |
///                       triaxial_extension | simple_shear | general
///   newton              {max_iterations, relative_tolerance}
///   output_every_increments
/// Axial is component 22 (z in axisymmetry); shear strains are tensor
/// components ε_ij except simple_shear's shear_strain_max (engineering γ).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>
#include <sstream>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/progress.hpp"
#include "drivers/point_integrator.hpp"
#include "drivers/scene/material_scene.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

constexpr double kMaxStress_kPa = 1e7;
constexpr long kMaxIncrements = 100'000'000;
constexpr std::array<const char*, 6> kComponents = {"11", "22", "33", "12", "23", "13"};
constexpr int kAxial = 1;

/// Scene values are compression positive in kPa; the integrator's are tension positive in Pa.
Voigt stress_from_kPa(const std::vector<double>& v) {
  Voigt s;
  for (int i = 0; i < 6; ++i) s[i] = -1e3 * v[i];
  return s;
}

ControlSet all(Control c) {
  ControlSet out;
  out.fill(c);
  return out;
}

/// The material as scene keys again (for the reproducer of a failed step).
json material_json(const MaterialSpec& spec) {
  json m;
  m["model"] = spec.model;
  const ElasticConstants& e = spec.elastic();
  m["E_kPa"] = 1e-3 * e.youngs_modulus_Pa;
  m["nu"] = e.poisson_ratio;
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&spec.parameters)) {
    m["phi_peak_deg"] = mc->friction_angle_rad / kDegree;
    m["psi_peak_deg"] = mc->dilatancy_angle_rad / kDegree;
    m["c_peak_kPa"] = 1e-3 * mc->cohesion_Pa;
  } else if (const auto* s = std::get_if<StrainSofteningParameters>(&spec.parameters)) {
    m["phi_peak_deg"] = s->friction_peak_rad / kDegree;
    m["phi_residual_deg"] = s->friction_residual_rad / kDegree;
    m["c_peak_kPa"] = 1e-3 * s->cohesion_peak_Pa;
    m["c_residual_kPa"] = 1e-3 * s->cohesion_residual_Pa;
    m["eta"] = s->softening_factor;
    if (s->relative_density) {
      m["relative_density"] = *s->relative_density;
    } else {
      m["psi_peak_deg"] = s->dilatancy_peak_rad / kDegree;
    }
    m["psi_residual_deg"] = s->dilatancy_residual_rad / kDegree;
    m["rate_dependence"] = {{"alpha_phi", s->rate.alpha_phi},
                            {"reference_strain_rate_per_s", s->rate.reference_strain_rate_per_s},
                            {"smoothing_increments", s->rate.smoothing_increments},
                            {"max_phi_deg", s->rate.max_friction_angle_rad / kDegree}};
  }
  return m;
}

struct PathSpec {
  std::string type;
  std::vector<PathSegment> segments;
  std::optional<Voigt> natural_initial_stress;  ///< what the path starts from unless the scene says otherwise
  /// A CSV path's first row for its stress-controlled components (Pa, tension
  /// positive), checked against the start stress once that is known.
  struct TableStart {
    std::string where;
    ControlSet control{};
    Voigt stress = Voigt::Zero();
  };
  std::optional<TableStart> table_start;
};

Control control_named(SceneReader& reader, const std::string& key, std::size_t index, const std::string& name) {
  if (name == "strain") return Control::strain;
  if (name == "stress") return Control::stress;
  reader.fail(key + "[" + std::to_string(index) + "]", "'" + name + "' must be \"strain\" or \"stress\"");
}

std::vector<PathSegment> read_segments(SceneReader& path) {
  std::vector<PathSegment> out;
  for (SceneReader& s : path.objects("segments", 1, 10000)) {
    PathSegment segment;
    const std::optional<json> control = s.raw("control");
    if (!control || !control->is_array() || control->size() != 6)
      s.fail("control", "must be a list of 6 entries, each \"strain\" or \"stress\" (order 11, 22, 33, 12, 23, 13)");
    for (std::size_t i = 0; i < 6; ++i) {
      if (!(*control)[i].is_string()) s.fail("control[" + std::to_string(i) + "]", "must be \"strain\" or \"stress\"");
      segment.control[i] = control_named(s, "control", i, (*control)[i].get<std::string>());
    }
    const std::vector<double> target = s.numbers("target", Range::closed(-kMaxStress_kPa, kMaxStress_kPa), 6, 6);
    for (int i = 0; i < 6; ++i) {
      // Strains dimensionless, stresses kPa; both compression positive.
      segment.target[i] = segment.control[i] == Control::strain ? -target[i] : -1e3 * target[i];
      if (segment.control[i] == Control::strain && std::abs(target[i]) > 10.0)
        s.fail("target[" + std::to_string(i) + "]", "a strain target must lie in [-10, 10]");
    }
    segment.increments = s.integer("increments", 1, kMaxIncrements, 100);
    segment.duration_s = s.number("duration_s", Range::positive(1e12, "s"), 1.0);
    s.finish("a path segment (control, target, increments, duration_s)");
    out.push_back(segment);
  }
  return out;
}

/// A CSV path: a column time_s and, per component ij, either strain_ij or
/// stress_ij_kPa (compression positive). Row 0 is the start: strains are
/// measured from it, and its stresses must be the start stress (checked by the
/// caller through `start`), so a lab record can be fed as it is. Every later
/// row is the target of one leg of `increments_per_row` increments.
std::vector<PathSegment> read_table(SceneReader& path, const fs::path& scene_dir,
                                    std::optional<PathSpec::TableStart>& start) {
  const std::string file = path.text("table_csv");
  const int per_row = path.integer("increments_per_row", 1, 1'000'000, 1);
  const fs::path resolved = fs::path(file).is_absolute() ? fs::path(file) : scene_dir / file;
  const CsvData table = read_numeric_csv(resolved);
  const std::string where = path.path() + ".table_csv (" + resolved.string() + ")";
  if (!table.has("time_s")) throw SceneError(where + ": needs a column time_s");
  std::array<const std::vector<double>*, 6> columns{};
  ControlSet control{};
  for (int i = 0; i < 6; ++i) {
    const std::string strain = std::string("strain_") + kComponents[i];
    const std::string stress = std::string("stress_") + kComponents[i] + "_kPa";
    if (table.has(strain) == table.has(stress))
      throw SceneError(where + ": needs exactly one of the columns " + strain + " or " + stress);
    control[i] = table.has(strain) ? Control::strain : Control::stress;
    columns[i] = &table.column(table.has(strain) ? strain : stress);
  }
  const std::vector<double>& time = table.column("time_s");
  if (time.size() < 2) throw SceneError(where + ": needs at least two rows (the start and one target)");
  PathSpec::TableStart first{where, control, Voigt::Zero()};
  for (int i = 0; i < 6; ++i)
    if (control[i] == Control::stress) first.stress[i] = -1e3 * (*columns[i])[0];
  start = first;
  std::vector<PathSegment> out;
  for (std::size_t row = 1; row < time.size(); ++row) {
    if (!(time[row] > time[row - 1]))
      throw SceneError(where + ": row " + std::to_string(row + 1) + ": time_s must increase");
    PathSegment segment;
    segment.control = control;
    for (int i = 0; i < 6; ++i)
      segment.target[i] = control[i] == Control::strain ? -((*columns[i])[row] - (*columns[i])[0])
                                                        : -1e3 * (*columns[i])[row];
    segment.increments = per_row;
    segment.duration_s = time[row] - time[row - 1];
    out.push_back(segment);
  }
  return out;
}

PathSpec read_path(SceneReader& path, const fs::path& scene_dir) {
  PathSpec spec;
  spec.type = path.choice("type", {"isotropic", "oedometric", "triaxial_compression", "triaxial_extension",
                                   "simple_shear", "general"});
  const std::string context = "a " + spec.type + " path";
  if (spec.type == "general") {
    if (path.has("segments") == path.has("table_csv"))
      path.fail("segments", "give either segments (a list of legs) or table_csv (a CSV file), exactly one");
    spec.segments = path.has("segments") ? read_segments(path) : read_table(path, scene_dir, spec.table_start);
    path.finish(context);
    return spec;
  }
  const int increments = path.integer("increments", 1, kMaxIncrements, 1000);
  PathSegment segment;
  segment.increments = increments;
  if (spec.type == "isotropic") {
    const double target = path.number("pressure_target_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"));
    segment.control = {Control::stress, Control::stress, Control::stress,
                       Control::strain, Control::strain, Control::strain};
    segment.target << -1e3 * target, -1e3 * target, -1e3 * target, 0, 0, 0;
    segment.duration_s = path.number("duration_s", Range::positive(1e12, "s"), 1.0);
  } else if (spec.type == "simple_shear") {
    const double normal = path.number("normal_stress_kPa", Range::non_negative(kMaxStress_kPa, "kPa"), 1.72);
    const double gamma = path.number("shear_strain_max", Range::open(0.0, 10.0), 0.2);
    const double rate = path.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4);
    segment.control = {Control::strain, Control::stress, Control::strain,
                       Control::strain, Control::strain, Control::strain};
    segment.target << 0, -1e3 * normal, 0, 0.5 * gamma, 0, 0;
    segment.duration_s = gamma / rate;
    Voigt start = Voigt::Zero();
    start[0] = start[1] = start[2] = -1e3 * normal;
    spec.natural_initial_stress = start;
  } else {
    const bool triaxial = spec.type != "oedometric";
    const bool extension = spec.type == "triaxial_extension";
    const double axial = path.number("axial_strain_max", Range::open(0.0, 10.0), triaxial ? 0.2 : 0.01);
    const double rate = path.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4);
    segment.duration_s = axial / rate;
    if (triaxial) {
      const double cell = path.number("cell_pressure_kPa", Range::non_negative(kMaxStress_kPa, "kPa"), 1.72);
      segment.control = {Control::stress, Control::strain, Control::stress,
                         Control::strain, Control::strain, Control::strain};
      segment.target << -1e3 * cell, extension ? axial : -axial, -1e3 * cell, 0, 0, 0;
      Voigt start = Voigt::Zero();
      start[0] = start[1] = start[2] = -1e3 * cell;
      spec.natural_initial_stress = start;
    } else {
      segment.control = all(Control::strain);
      segment.target << 0, -axial, 0, 0, 0, 0;
    }
  }
  spec.segments.push_back(segment);
  path.finish(context);
  return spec;
}

/// A table whose first row is not the start stress would jump to the second
/// row's stress in one leg without saying so; refuse it instead.
void check_table_start(const PathSpec::TableStart& table, const Voigt& initial_stress) {
  const double scale = std::max({1.0, table.stress.cwiseAbs().maxCoeff(), initial_stress.cwiseAbs().maxCoeff()});
  for (int i = 0; i < 6; ++i) {
    if (table.control[i] != Control::stress) continue;
    if (std::abs(table.stress[i] - initial_stress[i]) <= 1e-9 * scale) continue;
    std::ostringstream message;
    message << table.where << ": row 1: stress_" << kComponents[i] << "_kPa = " << -1e-3 * table.stress[i]
            << " is not the start stress " << -1e-3 * initial_stress[i]
            << " kPa; start the table at initial_stress_kPa/initial_pressure_kPa or change them";
    throw SceneError(message.str());
  }
}

class PointJob : public Job {
 public:
  PointJob(std::string name, MaterialSpec material, PointConfig config, std::string path_type)
      : name_(std::move(name)), material_(std::move(material)), config_(std::move(config)),
        path_type_(std::move(path_type)) {}

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
    if (const auto* s = std::get_if<StrainSofteningMohrCoulomb::State>(&f.state_start))
      scene["initial_state"] = {{"plastic_deviatoric_strain", s->plastic_deviatoric_strain},
                                {"strain_rate_per_s", s->strain_rate_per_s}};
    json control = json::array(), target = json::array();
    for (int i = 0; i < 6; ++i) {
      const bool strain = f.control[i] == Control::strain;
      control.push_back(strain ? "strain" : "stress");
      target.push_back(strain ? -f.prescribed_strain_increment[i] : -1e-3 * f.target_stress[i]);
    }
    scene["path"] = {{"type", "general"},
                     {"segments", json::array({{{"control", control},
                                                {"target", target},
                                                {"increments", 1},
                                                {"duration_s", f.dt_s}}})}};
    scene["newton"] = {{"max_iterations", config_.newton.max_iterations},
                       {"relative_tolerance", config_.newton.relative_tolerance}};
    return scene;
  }

  void write_history(const PointHistory& history, RunContext& context) const {
    const bool softening = std::holds_alternative<StrainSofteningMohrCoulomb>(config_.law);
    std::vector<std::string> columns = {"step", "time_s", "axial_strain", "volumetric_strain", "shear_strain_12",
                                        "p_kPa", "q_kPa"};
    for (const char* c : kComponents) columns.push_back(std::string("stress_") + c + "_kPa");
    for (const char* c : kComponents) columns.push_back(std::string("strain_") + c);
    for (const char* c : {"return_region", "newton_iterations", "plastic_work_J_m3", "work_input_J_m3"})
      columns.emplace_back(c);
    if (softening)
      for (const char* c : {"plastic_deviatoric_strain", "friction_angle_deg", "dilatancy_angle_deg", "strain_rate_per_s"})
        columns.emplace_back(c);
    CsvTable table(columns);

    double peak_q = -1.0;
    std::vector<double> axial, volumetric, q, shear, shear_stress;
    for (const PointRecord& r : history.records) {
      const double q_kPa = 1e-3 * deviatoric_stress(r.stress);
      const double axial_strain = -r.strain[kAxial];
      const double volumetric_strain = -trace(r.strain);
      std::vector<double> row = {static_cast<double>(r.step), r.time_s, axial_strain, volumetric_strain,
                                 2.0 * r.strain[3], 1e-3 * mean_pressure(r.stress), q_kPa};
      for (int i = 0; i < 6; ++i) row.push_back(-1e-3 * r.stress[i]);
      for (int i = 0; i < 6; ++i) row.push_back(-r.strain[i]);
      row.push_back(static_cast<double>(r.region));
      row.push_back(r.newton_iterations);
      row.push_back(r.plastic_work_J_m3);
      row.push_back(r.work_input_J_m3);
      if (softening) {
        const auto& law = std::get<StrainSofteningMohrCoulomb>(config_.law);
        const auto& state = std::get<StrainSofteningMohrCoulomb::State>(r.state);
        const MohrCoulombParameters strength = law.current_strength(state, mean_pressure(r.stress));
        row.push_back(state.plastic_deviatoric_strain);
        row.push_back(strength.friction_angle_rad / kDegree);
        row.push_back(strength.dilatancy_angle_rad / kDegree);
        row.push_back(state.strain_rate_per_s);
      }
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
    if (softening)
      s["final_plastic_deviatoric_strain"] =
          std::get<StrainSofteningMohrCoulomb::State>(last.state).plastic_deviatoric_strain;

    const fs::path plots = context.out_dir / "plots";
    fs::create_directories(plots);
    const bool shear_path = path_type_ == "simple_shear";
    const std::vector<double>& x = shear_path ? shear : axial;
    const std::string x_label = shear_path ? "shear strain γ_12" : "axial strain ε_a";
    Plot strength_plot{name_ + ": " + (shear_path ? "shear stress" : "deviatoric stress"), x_label,
                       shear_path ? "τ_12 (kPa)" : "q (kPa)", {{x, shear_path ? shear_stress : q, material_.model}}};
    Plot volume_plot{name_ + ": volumetric strain (compression positive)", x_label, "ε_v",
                     {{x, volumetric, material_.model}}};
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
  const std::string name = scene.text("name", "point");
  SceneReader material_reader = scene.object("material", true);
  MaterialSpec material = read_material(material_reader, DensityRule::not_used);

  PointConfig config;
  config.law = material.law();
  config.initial_state = initial_state_for(config.law);

  SceneReader path_reader = scene.object("path", true);
  PathSpec path = read_path(path_reader, scene_dir);
  config.segments = path.segments;

  if (scene.has("initial_stress_kPa") && scene.has("initial_pressure_kPa"))
    scene.fail("initial_pressure_kPa", "give either initial_stress_kPa or initial_pressure_kPa, not both");
  if (scene.has("initial_stress_kPa")) {
    config.initial_stress =
        stress_from_kPa(scene.numbers("initial_stress_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), 6, 6));
  } else {
    const double natural = path.natural_initial_stress ? -1e-3 * (*path.natural_initial_stress)[0] : 0.0;
    const double p = scene.number("initial_pressure_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), natural);
    config.initial_stress = stress_from_kPa({p, p, p, 0, 0, 0});
  }
  if (path.table_start) check_table_start(*path.table_start, config.initial_stress);

  if (scene.has("initial_state")) {
    if (!std::holds_alternative<StrainSofteningMohrCoulomb>(config.law))
      scene.fail("initial_state", "only an ssmc material has a state (plastic_deviatoric_strain, strain_rate_per_s)");
    SceneReader s = scene.object("initial_state");
    StrainSofteningMohrCoulomb::State state;
    state.plastic_deviatoric_strain = s.number("plastic_deviatoric_strain", Range::non_negative(1e6), 0.0);
    state.strain_rate_per_s = s.number("strain_rate_per_s", Range::non_negative(1e12, "1/s"), 0.0);
    s.finish("initial_state");
    config.initial_state = state;
  }

  SceneReader newton = scene.object("newton");
  config.newton.max_iterations = newton.integer("max_iterations", 1, 1000, 25);
  config.newton.relative_tolerance = newton.number("relative_tolerance", Range::closed(1e-15, 1e-2), 1e-10);
  newton.finish("newton");

  long total = 0;
  for (const auto& s : config.segments) total += s.increments;
  // Histories beyond ~20,000 rows only slow the plots down.
  config.record_every = scene.integer("output_every_increments", 1, kMaxIncrements, std::max(1L, total / 20000));
  scene.finish("a point scene");
  return std::make_unique<PointJob>(name, std::move(material), std::move(config), path.type);
}

}  // namespace ffp
