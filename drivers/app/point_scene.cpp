#include "drivers/app/point_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "drivers/app/job.hpp"
#include "drivers/output/csv_writer.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

constexpr double kMaxStress_kPa = 1e7;
constexpr long kMaxIncrements = 100'000'000;

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
  for (SceneReader& s : path.objects("segments", 1, 10000,
                                     Doc("the legs, run one after another (instead of table_csv)")
                                         .by_default("none: table_csv")
                                         .only_with("type = general"))) {
    PathSegment segment;
    const std::optional<json> control =
        s.raw("control", Doc("what each component follows, in the order 11, 22, 33, 12, 23, 13")
                             .by_default("required")
                             .within("6 of `strain`, `stress`"));
    if (!control || !control->is_array() || control->size() != 6)
      s.fail("control", "must be a list of 6 entries, each \"strain\" or \"stress\" (order 11, 22, 33, 12, 23, 13)");
    for (std::size_t i = 0; i < 6; ++i) {
      if (!(*control)[i].is_string()) s.fail("control[" + std::to_string(i) + "]", "must be \"strain\" or \"stress\"");
      segment.control[i] = control_named(s, "control", i, (*control)[i].get<std::string>());
    }
    const std::vector<double> target =
        s.numbers("target", Range::closed(-kMaxStress_kPa, kMaxStress_kPa), 6, 6,
                  Doc("the leg's end values, compression positive: total strain since the path's start, or stress "
                      "(kPa)")
                      .within("6 numbers, each in [-1e7, 1e7]; strains in [-10, 10]"));
    for (int i = 0; i < 6; ++i) {
      // Strains dimensionless, stresses kPa; both compression positive.
      segment.target[i] = segment.control[i] == Control::strain ? -target[i] : -1e3 * target[i];
      if (segment.control[i] == Control::strain && std::abs(target[i]) > 10.0)
        s.fail("target[" + std::to_string(i) + "]", "a strain target must lie in [-10, 10]");
    }
    segment.increments = s.integer("increments", 1, kMaxIncrements, 100, Doc("equal increments of the leg"));
    segment.duration_s = s.number("duration_s", Range::positive(1e12, "s"), 1.0, Doc("the leg's time"));
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
  const fs::path resolved =
      path.file("table_csv", scene_dir,
                Doc("a CSV file: time_s and, for each ij, strain_ij or stress_ij_kPa; the first row is the start "
                    "(its stresses the start stress), each later row the target of one leg")
                    .by_default("none: segments")
                    .only_with("type = general"));
  const int per_row =
      path.integer("increments_per_row", 1, 1'000'000, 1, Doc("increments per leg").only_with("table_csv"));
  const CsvData table = read_numeric_csv(resolved);
  const std::string where = path.path() + ".table_csv (" + resolved.string() + ")";
  if (!table.has("time_s")) throw SceneError(where + ": needs a column time_s");
  std::array<const std::vector<double>*, 6> columns{};
  ControlSet control{};
  for (int i = 0; i < 6; ++i) {
    const std::string strain = std::string("strain_") + kPointComponents[i];
    const std::string stress = std::string("stress_") + kPointComponents[i] + "_kPa";
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
      segment.target[i] =
          control[i] == Control::strain ? -((*columns[i])[row] - (*columns[i])[0]) : -1e3 * (*columns[i])[row];
    segment.increments = per_row;
    segment.duration_s = time[row] - time[row - 1];
    out.push_back(segment);
  }
  return out;
}

/// The strain rate of the paths driven by a strain (oedometric, triaxial_*, simple_shear).
double read_strain_rate(SceneReader& path) {
  return path.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4,
                     Doc("it sets the path's time (strain / rate), which only the rate law sees")
                         .only_with("type = oedometric, triaxial_* or simple_shear"));
}

PathSpec read_path(SceneReader& path, const fs::path& scene_dir) {
  PathSpec spec;
  spec.type = path.choice(
      "type", {"isotropic", "oedometric", "triaxial_compression", "triaxial_extension", "simple_shear", "general"},
      Doc("the path: which components are strain- and which stress-controlled; each type takes only its own keys"));
  const std::string context = "a " + spec.type + " path";
  if (spec.type == "general") {
    if (path.has("segments") == path.has("table_csv"))
      path.fail("segments", "give either segments (a list of legs) or table_csv (a CSV file), exactly one");
    spec.segments = path.has("segments") ? read_segments(path) : read_table(path, scene_dir, spec.table_start);
    path.finish(context);
    return spec;
  }
  const int increments =
      path.integer("increments", 1, kMaxIncrements, 1000, Doc("equal increments").only_with("type ≠ general"));
  PathSegment segment;
  segment.increments = increments;
  if (spec.type == "isotropic") {
    const double target =
        path.number("pressure_target_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"),
                    Doc("σ11 = σ22 = σ33 at the end (shear strains stay 0)").only_with("type = isotropic"));
    segment.control = {Control::stress, Control::stress, Control::stress,
                       Control::strain, Control::strain, Control::strain};
    segment.target << -1e3 * target, -1e3 * target, -1e3 * target, 0, 0, 0;
    segment.duration_s = path.number("duration_s", Range::positive(1e12, "s"), 1.0,
                                     Doc("the path's time").only_with("type = isotropic"));
  } else if (spec.type == "simple_shear") {
    const std::string shear = "type = simple_shear";
    const double normal = path.number("normal_stress_kPa", Range::non_negative(kMaxStress_kPa, "kPa"), 1.72,
                                      Doc("σ22, held (ε11 = ε33 = 0)").only_with(shear));
    const double gamma = path.number("shear_strain_max", Range::open(0.0, 10.0), 0.2,
                                     Doc("the engineering shear strain γ12 = 2 ε12 at the end").only_with(shear));
    const double rate = read_strain_rate(path);
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
    const double axial = path.number("axial_strain_max", Range::open(0.0, 10.0), triaxial ? 0.2 : 0.01,
                                     Doc("ε22 at the end: shortened (compression) or stretched (extension)")
                                         .by_default("0.2 (triaxial_*), 0.01 (oedometric)")
                                         .only_with("type = oedometric or triaxial_*"));
    const double rate = read_strain_rate(path);
    segment.duration_s = axial / rate;
    if (triaxial) {
      const double cell = path.number("cell_pressure_kPa", Range::non_negative(kMaxStress_kPa, "kPa"), 1.72,
                                      Doc("σ11 = σ33 = σ3, held").only_with("type = triaxial_*"));
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
    message << table.where << ": row 1: stress_" << kPointComponents[i] << "_kPa = " << -1e-3 * table.stress[i]
            << " is not the start stress " << -1e-3 * initial_stress[i]
            << " kPa; start the table at initial_stress_kPa/initial_pressure_kPa or change them";
    throw SceneError(message.str());
  }
}

}  // namespace

NewtonSettings read_newton_settings(SceneReader& scene) {
  SceneReader newton = scene.object("newton", Doc("the Newton iteration on the stress-controlled components"));
  NewtonSettings settings;
  settings.max_iterations = newton.integer("max_iterations", 1, 1000, 25, Doc("iterations per increment, at most"));
  settings.relative_tolerance =
      newton.number("relative_tolerance", Range::closed(1e-15, 1e-2), 1e-10, Doc("its tolerance, relative"));
  newton.finish("newton");
  return settings;
}

PointScene read_point_scene(SceneReader& scene, const fs::path& scene_dir) {
  PointScene out;
  out.name = read_scene_name(scene, "point");
  SceneReader material_reader = scene.required_object("material", Doc("the material point's law (weightless)"));
  out.material = read_material(material_reader, DensityRule::not_used);

  PointConfig& config = out.config;
  config.law = out.material.law();

  SceneReader path_reader = scene.required_object("path", Doc("the loading path"));
  PathSpec path = read_path(path_reader, scene_dir);
  config.segments = path.segments;

  if (scene.has("initial_stress_kPa") && scene.has("initial_pressure_kPa"))
    scene.fail("initial_pressure_kPa", "give either initial_stress_kPa or initial_pressure_kPa, not both");
  if (scene.has("initial_stress_kPa")) {
    config.initial_stress =
        stress_from_kPa(scene.numbers("initial_stress_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), 6, 6,
                                      Doc("[σ11, σ22, σ33, σ12, σ23, σ13] at the start, compression positive")
                                          .by_default("none: initial_pressure_kPa")));
  } else {
    const double natural = path.natural_initial_stress ? -1e-3 * (*path.natural_initial_stress)[0] : 0.0;
    const double p =
        scene.number("initial_pressure_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), natural,
                     Doc("the isotropic stress at the start")
                         .by_default("path.cell_pressure_kPa (triaxial_*), path.normal_stress_kPa "
                                     "(simple_shear), else 0")
                         .only_with("no initial_stress_kPa"));
    config.initial_stress = stress_from_kPa({p, p, p, 0, 0, 0});
  }
  if (path.table_start) check_table_start(*path.table_start, config.initial_stress);

  config.initial_state = read_initial_state(scene, config.law);

  config.newton = read_newton_settings(scene);

  long total = 0;
  for (const auto& s : config.segments) total += s.increments;
  // Histories beyond ~20,000 rows only slow the plots down.
  config.record_every =
      scene.integer("output_every_increments", 1, kMaxIncrements, std::max(1L, total / 20000),
                    Doc("a history.csv row every this many increments").by_default("max(1, all increments / 20000)"));
  scene.finish("a point scene");
  out.path_type = path.type;
  return out;
}

}  // namespace ffp
