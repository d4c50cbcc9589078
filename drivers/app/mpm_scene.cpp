#include "drivers/app/mpm_scene.hpp"

#include <algorithm>
#include <cmath>

#include "drivers/scene/material_scene.hpp"
#include "models/math_constants.hpp"

namespace ffp {

namespace {

constexpr double kMaxLength_m = 1e4;
constexpr double kMaxSpeed_m_s = 1e5;
constexpr double kMaxTime_s = 1e6;
constexpr std::size_t kMaxNodesPerAxis = 100'000;

/// Node coordinates of one axis: an explicit list, or [min, max] cut into equal cells.
std::vector<double> read_axis(SceneReader& mesh, const std::string& axis, double default_min) {
  const std::string list_key = axis + "_nodes_m";
  if (mesh.has(list_key)) {
    for (const std::string& k : {axis + "_min_m", axis + "_max_m", "cell_" + axis + "_m"})
      if (mesh.has(k))
        mesh.fail(
            k, "give either " + list_key + " or " + axis + "_min_m/" + axis + "_max_m/cell_" + axis + "_m, not both");
    const Range range =
        axis == "r" ? Range::closed(0.0, kMaxLength_m, "m") : Range::closed(-kMaxLength_m, kMaxLength_m, "m");
    std::vector<double> nodes = mesh.numbers(list_key, range, 3, kMaxNodesPerAxis);
    for (std::size_t i = 1; i < nodes.size(); ++i)
      if (!(nodes[i] > nodes[i - 1]))
        mesh.fail(list_key + "[" + std::to_string(i) + "]", "node coordinates must increase strictly");
    return nodes;
  }
  const double lo = axis == "r"
                        ? mesh.number(axis + "_min_m", Range::closed(0.0, kMaxLength_m, "m"), default_min)
                        : mesh.number(axis + "_min_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"), default_min);
  const double hi = mesh.number(axis + "_max_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"));
  if (!(hi > lo)) mesh.fail(axis + "_max_m", "must be greater than " + axis + "_min_m");
  const double cell = mesh.number("cell_" + axis + "_m", Range::positive(kMaxLength_m, "m"));
  const double count = (hi - lo) / cell;
  const long n = std::lround(count);
  if (n < 2 || std::abs(count - static_cast<double>(n)) > 1e-6 * count)
    mesh.fail("cell_" + axis + "_m",
              "must cut [" + axis + "_min_m, " + axis + "_max_m] into a whole number (≥ 2) of cells");
  if (static_cast<std::size_t>(n) >= kMaxNodesPerAxis) mesh.fail("cell_" + axis + "_m", "gives too many cells");
  std::vector<double> nodes;
  for (long i = 0; i <= n; ++i) nodes.push_back(lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n));
  return nodes;
}

/// The symmetry axis keeps v_r = 0: it is a roller at least.
mpm::Fixity read_fixity(SceneReader& b, const std::string& key, mpm::Fixity fallback, bool axis) {
  using mpm::Fixity;
  return axis ? b.choice(key, mpm::kFixityNames, {Fixity::roller, Fixity::fixed}, fallback)
              : b.choice(key, mpm::kFixityNames, fallback);
}

mpm::Region read_region(SceneReader& region, const std::vector<double>& r, const std::vector<double>& z) {
  if (region.has("sphere_radius_m")) {
    mpm::SphereRegion s;
    s.center_z_m = region.number("sphere_center_z_m", Range::closed(z.front(), z.back(), "m (inside the grid)"));
    s.radius_m = region.number("sphere_radius_m", Range::positive(r.back(), "m"));
    region.finish("a sphere region (sphere_center_z_m, sphere_radius_m)");
    return s;
  }
  mpm::BoxRegion b;
  const Range rr = Range::closed(r.front(), r.back(), "m (inside the grid)");
  const Range zz = Range::closed(z.front(), z.back(), "m (inside the grid)");
  b.r_min_m = region.number("r_min_m", rr, r.front());
  b.r_max_m = region.number("r_max_m", rr);
  b.z_min_m = region.number("z_min_m", zz);
  b.z_max_m = region.number("z_max_m", zz);
  if (!(b.r_max_m > b.r_min_m)) region.fail("r_max_m", "must be greater than r_min_m");
  if (!(b.z_max_m > b.z_min_m)) region.fail("z_max_m", "must be greater than z_min_m");
  region.finish(
      "a box region (r_min_m, r_max_m, z_min_m, z_max_m) or a sphere on the axis (sphere_center_z_m, sphere_radius_m)");
  return b;
}

}  // namespace

std::vector<std::string> mpm_history_quantities(const std::vector<std::string>& body_names) {
  static const std::vector<std::string> global = {
      "kinetic_energy_J", "strain_energy_J", "gravity_energy_J", "total_energy_J",
      "momentum_z_N_s",   "mass_kg",         "max_speed_m_s",    "dt_s"};
  static const std::vector<std::string> per_body = {"kinetic_energy_J", "strain_energy_J", "momentum_z_N_s",
                                                    "mass_kg",          "mean_z_m",        "mean_v_z_m_s"};
  std::vector<std::string> out = global;
  for (const std::string& b : body_names)
    for (const std::string& q : per_body) out.push_back(b + "_" + q);
  return out;
}

/// solver.strain_smoothing: a mode name, or true/false as before the modes
/// (true: volumetric, false: off).
mpm::StrainSmoothing read_strain_smoothing(SceneReader& solver) {
  const std::optional<json> value = solver.raw("strain_smoothing");
  if (value && value->is_boolean())
    return value->get<bool>() ? mpm::StrainSmoothing::volumetric : mpm::StrainSmoothing::off;
  return solver.choice("strain_smoothing", mpm::kStrainSmoothingNames, mpm::StrainSmoothing::volumetric);
}

MpmScene read_mpm_scene(SceneReader& scene) {
  MpmScene out;
  mpm::ModelDescription& model = out.model;

  SceneReader mesh = scene.object("mesh", true);
  model.r_nodes_m = read_axis(mesh, "r", 0.0);
  model.z_nodes_m = read_axis(mesh, "z", 0.0);
  mesh.finish("mesh");
  const bool axis = model.r_nodes_m.front() == 0.0;

  if (scene.has("gravity_m_s2")) model.gravity_m_s2 = scene.number("gravity_m_s2", Range::positive(1e3, "m/s²"));

  std::vector<SceneReader> bodies = scene.objects("bodies", 1, 255);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    SceneReader& b = bodies[i];
    mpm::BodyDescription body{b.text("name", "body" + std::to_string(i)),
                              LinearElastic(ElasticConstants{1.0, 0.0}),
                              0.0,
                              mpm::BoxRegion{},
                              2,
                              2,
                              0.0,
                              0.0,
                              std::nullopt};
    for (const std::string& existing : out.body_names)
      if (existing == body.name) b.fail("name", "'" + body.name + "' is used by another body");
    SceneReader material = b.object("material", true);
    const MaterialSpec spec = read_material(material, DensityRule::required);
    body.law = spec.law();
    body.density_kg_m3 = *spec.density_kg_m3;
    SceneReader region = b.object("region", true);
    body.region = read_region(region, model.r_nodes_m, model.z_nodes_m);
    const std::vector<double> ppc = b.numbers("particles_per_cell", Range::closed(1, 8), 2, 2);
    if (ppc[0] != std::floor(ppc[0]) || ppc[1] != std::floor(ppc[1]))
      b.fail("particles_per_cell", "must be two whole numbers [n_r, n_z]");
    body.particles_per_cell_r = static_cast<int>(ppc[0]);
    body.particles_per_cell_z = static_cast<int>(ppc[1]);
    const auto velocity =
        b.optional_numbers("initial_velocity_m_s", Range::closed(-kMaxSpeed_m_s, kMaxSpeed_m_s, "m/s"), 2, 2);
    if (velocity) {
      body.initial_velocity_r_m_s = (*velocity)[0];
      body.initial_velocity_z_m_s = (*velocity)[1];
    }
    if (b.has("initial_stress")) {
      if (!model.gravity_m_s2) b.fail("initial_stress", "a K0 initial stress needs gravity_m_s2");
      SceneReader k0 = b.object("initial_stress");
      mpm::GeostaticStress g;
      g.k0 = k0.number("k0", Range::closed(0.0, 10.0), spec.at_rest_k0());
      g.surface_z_m = k0.number("surface_z_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"));
      k0.finish("initial_stress (k0, surface_z_m)");
      body.initial_stress = g;
    } else {
      b.allow("initial_stress");
    }
    b.finish("a body");
    out.body_names.push_back(body.name);
    model.bodies.push_back(std::move(body));
  }

  SceneReader bc = scene.object("boundaries");
  model.boundaries.inner = read_fixity(bc, axis ? "axis" : "inner", mpm::Fixity::roller, axis);
  model.boundaries.outer = read_fixity(bc, "outer", mpm::Fixity::roller, false);
  model.boundaries.bottom = read_fixity(bc, "bottom", mpm::Fixity::fixed, false);
  model.boundaries.top = read_fixity(bc, "top", mpm::Fixity::free, false);
  bc.finish(axis ? "boundaries (axis, outer, bottom, top)" : "boundaries (inner, outer, bottom, top)");

  std::vector<SceneReader> loads = scene.objects("surface_pressures", 0, 16);
  for (SceneReader& l : loads) {
    mpm::SurfacePressure p;
    p.side = l.choice("side", mpm::kSideNames);
    if (p.side == mpm::Side::inner && axis)
      l.fail("side", "the inner side is the symmetry axis: it carries no pressure");
    const double pressure = 1e3 * l.number("pressure_kPa", Range::closed(-1e9, 1e9, "kPa"));
    const double ramp = l.number("ramp_time_s", Range::non_negative(kMaxTime_s, "s"), 0.0);
    p.z_min_m = l.number("z_min_m", Range::closed(model.z_nodes_m.front(), model.z_nodes_m.back(), "m"));
    p.z_max_m = l.number("z_max_m", Range::closed(model.z_nodes_m.front(), model.z_nodes_m.back(), "m"));
    if (!(p.z_max_m > p.z_min_m)) l.fail("z_max_m", "must be greater than z_min_m");
    // A smooth (half-cosine) ramp excites the lowest modes the least.
    p.pressure_Pa = [pressure, ramp](double t) {
      return t >= ramp ? pressure : pressure * 0.5 * (1.0 - std::cos(kPi * t / ramp));
    };
    l.finish("a surface pressure (side, pressure_kPa, ramp_time_s, z_min_m, z_max_m)");
    model.pressures.push_back(std::move(p));
  }

  SceneReader solver = scene.object("solver");
  mpm::SolverSettings& s = model.solver;
  s.shape_function = solver.choice("shape_function", mpm::kShapeFunctionNames, mpm::ShapeFunction::gimp);
  s.transfer = solver.choice("transfer", mpm::kTransferNames, mpm::Transfer::musl);
  s.flip_fraction = solver.number("flip_fraction", Range::closed(0.0, 1.0), 0.99);
  s.courant = solver.number("courant", Range::positive(1.0), 0.5);
  if (solver.has("dt_s")) s.fixed_dt_s = solver.number("dt_s", Range::positive(kMaxTime_s, "s"));
  s.strain_smoothing = read_strain_smoothing(solver);
  s.local_damping = solver.number("local_damping", Range::half_open(0.0, 1.0), 0.0);
  solver.finish("solver");

  out.end_time_s = scene.number("end_time_s", Range::positive(kMaxTime_s, "s"));

  SceneReader output = scene.object("output");
  MpmOutput& o = out.output;
  o.history_interval_s = output.number("history_interval_s", Range::positive(kMaxTime_s, "s"), out.end_time_s / 200.0);
  const std::vector<std::string> allowed = mpm_history_quantities(out.body_names);
  if (auto history = output.raw("history")) {
    if (!history->is_array()) output.fail("history", "must be a list of quantity names");
    for (std::size_t i = 0; i < history->size(); ++i) {
      const json& q = (*history)[i];
      const std::string key = "history[" + std::to_string(i) + "]";
      if (!q.is_string()) output.fail(key, "must be a quantity name (a string)");
      const std::string name = q.get<std::string>();
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        const std::string guess = nearest(name, allowed);
        output.fail(key, "'" + name + "' is not a history quantity" +
                             (guess.empty() ? "" : " (did you mean '" + guess + "'?)") + "; allowed: " + list);
      }
      o.history.push_back(name);
    }
  } else {
    o.history = {"kinetic_energy_J", "strain_energy_J", "total_energy_J"};
  }
  if (output.has("field_times_s") && output.has("field_interval_s"))
    output.fail("field_interval_s", "give either field_times_s or field_interval_s, not both");
  if (output.has("field_times_s")) {
    o.field_times_s = output.numbers("field_times_s", Range::closed(0.0, out.end_time_s, "s"), 0, 10000);
    std::sort(o.field_times_s.begin(), o.field_times_s.end());
  } else {
    const double interval = output.number("field_interval_s", Range::positive(kMaxTime_s, "s"), out.end_time_s / 10.0);
    if (out.end_time_s / interval > 10000) output.fail("field_interval_s", "gives more than 10000 field files");
    for (long k = 0; static_cast<double>(k) * interval <= out.end_time_s * (1.0 + 1e-12); ++k)
      o.field_times_s.push_back(static_cast<double>(k) * interval);
  }
  for (SceneReader& p : output.objects("probes", 0, 100)) {
    MpmProbe probe;
    probe.name = p.text("name");
    probe.r_m = p.number("r_m", Range::closed(model.r_nodes_m.front(), model.r_nodes_m.back(), "m"));
    probe.z_m = p.number("z_m", Range::closed(model.z_nodes_m.front(), model.z_nodes_m.back(), "m"));
    p.finish("a probe (name, r_m, z_m)");
    o.probes.push_back(probe);
  }
  output.finish("output");
  scene.finish("an mpm scene");
  return out;
}

}  // namespace ffp
