#include "drivers/app/point_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

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
  const fs::path resolved = path.file("table_csv", scene_dir);
  const int per_row = path.integer("increments_per_row", 1, 1'000'000, 1);
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

PathSpec read_path(SceneReader& path, const fs::path& scene_dir) {
  PathSpec spec;
  spec.type = path.choice(
      "type", {"isotropic", "oedometric", "triaxial_compression", "triaxial_extension", "simple_shear", "general"});
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
    message << table.where << ": row 1: stress_" << kPointComponents[i] << "_kPa = " << -1e-3 * table.stress[i]
            << " is not the start stress " << -1e-3 * initial_stress[i]
            << " kPa; start the table at initial_stress_kPa/initial_pressure_kPa or change them";
    throw SceneError(message.str());
  }
}

}  // namespace

NewtonSettings read_newton_settings(SceneReader& scene) {
  SceneReader newton = scene.object("newton");
  NewtonSettings settings;
  settings.max_iterations = newton.integer("max_iterations", 1, 1000, 25);
  settings.relative_tolerance = newton.number("relative_tolerance", Range::closed(1e-15, 1e-2), 1e-10);
  newton.finish("newton");
  return settings;
}

PointScene read_point_scene(SceneReader& scene, const fs::path& scene_dir) {
  PointScene out;
  out.name = scene.text("name", "point");
  SceneReader material_reader = scene.object("material", true);
  out.material = read_material(material_reader, DensityRule::not_used);

  PointConfig& config = out.config;
  config.law = out.material.law();

  SceneReader path_reader = scene.object("path", true);
  PathSpec path = read_path(path_reader, scene_dir);
  config.segments = path.segments;

  if (scene.has("initial_stress_kPa") && scene.has("initial_pressure_kPa"))
    scene.fail("initial_pressure_kPa", "give either initial_stress_kPa or initial_pressure_kPa, not both");
  if (scene.has("initial_stress_kPa")) {
    config.initial_stress = stress_from_kPa(
        scene.numbers("initial_stress_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), 6, 6));
  } else {
    const double natural = path.natural_initial_stress ? -1e-3 * (*path.natural_initial_stress)[0] : 0.0;
    const double p =
        scene.number("initial_pressure_kPa", Range::closed(-kMaxStress_kPa, kMaxStress_kPa, "kPa"), natural);
    config.initial_stress = stress_from_kPa({p, p, p, 0, 0, 0});
  }
  if (path.table_start) check_table_start(*path.table_start, config.initial_stress);

  config.initial_state = read_initial_state(scene, config.law);

  config.newton = read_newton_settings(scene);

  long total = 0;
  for (const auto& s : config.segments) total += s.increments;
  // Histories beyond ~20,000 rows only slow the plots down.
  config.record_every = scene.integer("output_every_increments", 1, kMaxIncrements, std::max(1L, total / 20000));
  scene.finish("a point scene");
  out.path_type = path.type;
  return out;
}

}  // namespace ffp
