#include "drivers/app/mpm_scene.hpp"

#include <algorithm>
#include <cmath>

#include "drivers/app/pore_fluid_scene.hpp"
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
  const std::string direction = axis == "r" ? "radial" : "vertical";
  const std::string uniform = "no " + list_key;
  if (mesh.has(list_key)) {
    for (const std::string& k : {axis + "_min_m", axis + "_max_m", "cell_" + axis + "_m"})
      if (mesh.has(k))
        mesh.fail(
            k, "give either " + list_key + " or " + axis + "_min_m/" + axis + "_max_m/cell_" + axis + "_m, not both");
    const Range range =
        axis == "r" ? Range::closed(0.0, kMaxLength_m, "m") : Range::closed(-kMaxLength_m, kMaxLength_m, "m");
    std::vector<double> nodes =
        mesh.numbers(list_key, range, 3, kMaxNodesPerAxis,
                     Doc(direction + " node coordinates, strictly increasing").by_default("none: a uniform grid"));
    for (std::size_t i = 1; i < nodes.size(); ++i)
      if (!(nodes[i] > nodes[i - 1]))
        mesh.fail(list_key + "[" + std::to_string(i) + "]", "node coordinates must increase strictly");
    return nodes;
  }
  const Doc first =
      Doc("the first " + direction + " node" + (axis == "r" ? " (0: the symmetry axis)" : "")).only_with(uniform);
  const double lo =
      axis == "r" ? mesh.number(axis + "_min_m", Range::closed(0.0, kMaxLength_m, "m"), default_min, first)
                  : mesh.number(axis + "_min_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"), default_min, first);
  const double hi =
      mesh.number(axis + "_max_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"),
                  Doc("the last " + direction + " node").within("(" + axis + "_min_m, 1e4]").only_with(uniform));
  if (!(hi > lo)) mesh.fail(axis + "_max_m", "must be greater than " + axis + "_min_m");
  const double cell = mesh.number("cell_" + axis + "_m", Range::positive(kMaxLength_m, "m"),
                                  Doc("the " + direction + " cell size: a whole number (at least 2) of cells from " +
                                      axis + "_min_m to " + axis + "_max_m")
                                      .only_with(uniform));
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

/// A side of the grid; the symmetry axis keeps v_r = 0: it is a roller at least.
mpm::Fixity read_fixity(SceneReader& b, const std::string& key, mpm::Fixity fallback, bool axis) {
  using mpm::Fixity;
  if (axis)
    return b.choice(key, mpm::kFixityNames, {Fixity::roller, Fixity::fixed}, fallback,
                    Doc("the symmetry axis").only_with("mesh from r = 0"));
  const std::string side = key == "inner" ? "the inner side" : key == "outer" ? "the outer side" : "the " + key;
  return b.choice(key, mpm::kFixityNames, fallback,
                  Doc(side + "; absorbing: dashpots with the first body's impedance "
                             "([theory](../theory.md#absorbing-walls))")
                      .only_with(key == "inner" ? "mesh from r > 0" : ""));
}

mpm::Region read_region(SceneReader& region, const std::vector<double>& r, const std::vector<double>& z) {
  if (region.has("sphere_radius_m")) {
    mpm::SphereRegion s;
    s.center_z_m = region.number(
        "sphere_center_z_m", Range::closed(z.front(), z.back(), "m", "inside the grid"),
        Doc("height of the sphere's centre, on the axis").within("inside the grid").only_with("sphere_radius_m"));
    s.radius_m = region.number("sphere_radius_m", Range::positive(r.back(), "m"),
                               Doc("radius of a sphere on the axis (instead of a box)")
                                   .by_default("none: a box")
                                   .within("(0, the grid's last radial node]"));
    region.finish("a sphere region (sphere_center_z_m, sphere_radius_m)");
    return s;
  }
  mpm::BoxRegion b;
  const Range rr = Range::closed(r.front(), r.back(), "m", "inside the grid");
  const Range zz = Range::closed(z.front(), z.back(), "m", "inside the grid");
  const std::string box = "no sphere_radius_m";
  b.r_min_m = region.number("r_min_m", rr, r.front(),
                            Doc("inner radius of the box")
                                .by_default("the grid's first radial node")
                                .within("inside the grid")
                                .only_with(box));
  b.r_max_m =
      region.number("r_max_m", rr, Doc("outer radius of the box").within("inside the grid, > r_min_m").only_with(box));
  b.z_min_m = region.number("z_min_m", zz, Doc("bottom of the box").within("inside the grid").only_with(box));
  b.z_max_m = region.number("z_max_m", zz, Doc("top of the box").within("inside the grid, > z_min_m").only_with(box));
  if (!(b.r_max_m > b.r_min_m)) region.fail("r_max_m", "must be greater than r_min_m");
  if (!(b.z_max_m > b.z_min_m)) region.fail("z_max_m", "must be greater than z_min_m");
  region.finish(
      "a box region (r_min_m, r_max_m, z_min_m, z_max_m) or a sphere on the axis (sphere_center_z_m, sphere_radius_m)");
  return b;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "`" : ", `") + w + "`";
  return out;
}

/// The history quantities in words: the global ones, then each body's, `<name>_<quantity>`.
std::string history_quantities_in_words() {
  const std::vector<std::string> global = mpm_history_quantities({});
  const std::vector<std::string> with_body = mpm_history_quantities({"<name>"});
  return joined(global) + "; per body " +
         joined({with_body.begin() + static_cast<long>(global.size()), with_body.end()});
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

mpm::ShapeFunction read_shape_function(SceneReader& solver) {
  return solver.choice("shape_function", mpm::kShapeFunctionNames, mpm::ShapeFunction::gimp,
                       Doc("the particle–grid shape functions"));
}

mpm::Transfer read_transfer(SceneReader& solver, mpm::Transfer fallback) {
  return solver.choice("transfer", mpm::kTransferNames, fallback,
                       Doc("the particle update: usl (positions and strains from the grid update), musl (Sulsky et al. "
                           "1995: strains from the remapped velocities) or musl_remapped (the paper's code: both from "
                           "them) ([verification](../verification.md#transfer))"));
}

double read_flip_fraction(SceneReader& solver) {
  return solver.number("flip_fraction", Range::closed(0.0, 1.0), 0.99,
                       Doc("the FLIP share α of the particle velocity update (1 − α is PIC)"));
}

double read_courant(SceneReader& solver) {
  return solver.number("courant", Range::positive(1.0), 0.5,
                       Doc("the time step as a fraction of the CFL limit, recomputed every step"));
}

double read_local_damping(SceneReader& solver) {
  return solver.number("local_damping", Range::half_open(0.0, 1.0), 0.0, Doc("Cundall's local damping coefficient"));
}

/// solver.strain_smoothing: a mode name, or true/false as before the modes
/// (true: volumetric, false: off).
mpm::StrainSmoothing read_strain_smoothing(SceneReader& solver) {
  const Doc doc = Doc("which part of the strain increment, and of the stress in the internal force, each cell "
                      "averages over its particles: volumetric (B-bar, against locking), full, or off "
                      "([theory](../theory.md#strain-smoothing))")
                      .by_default("`volumetric`")
                      .within("`off`, `volumetric`, `full`; `true` / `false` read as `volumetric` / `off`");
  const std::optional<json> value = solver.raw("strain_smoothing", doc);
  if (value && value->is_boolean())
    return value->get<bool>() ? mpm::StrainSmoothing::volumetric : mpm::StrainSmoothing::off;
  return solver.choice("strain_smoothing", mpm::kStrainSmoothingNames, mpm::StrainSmoothing::volumetric, doc);
}

MpmScene read_mpm_scene(SceneReader& scene) {
  MpmScene out;
  mpm::ModelDescription& model = out.model;

  SceneReader mesh =
      scene.required_object("mesh", Doc("the grid: node coordinates along r (from the axis, or off it) and z (up)"));
  model.r_nodes_m = read_axis(mesh, "r", 0.0);
  model.z_nodes_m = read_axis(mesh, "z", 0.0);
  mesh.finish("mesh");
  const bool axis = model.r_nodes_m.front() == 0.0;

  model.gravity_m_s2 = scene.optional_number("gravity_m_s2", Range::positive(1e3, "m/s²"),
                                             Doc("gravity, along −z").by_default("none: no gravity"));

  std::vector<SceneReader> bodies =
      scene.objects("bodies", 1, 255, Doc("the bodies: each a material filling a region with particles"));
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    SceneReader& b = bodies[i];
    mpm::BodyDescription body{
        b.text("name", "body" + std::to_string(i),
               Doc("names the body's history columns; unique").by_default("`body<i>`, i its place in the list")),
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
    SceneReader material = b.required_object("material", Doc("the body's material"));
    const MaterialSpec spec = read_material(material, DensityRule::required, MicropolarRule::allowed);
    body.law = spec.law();
    body.micropolar = spec.micropolar;
    body.density_kg_m3 = *spec.density_kg_m3;
    SceneReader region = b.required_object("region", Doc("where its particles start: a box, or a sphere on the axis"));
    body.region = read_region(region, model.r_nodes_m, model.z_nodes_m);
    const std::vector<double> ppc =
        b.numbers("particles_per_cell", Range::closed(1, 8), 2, 2,
                  Doc("[n_r, n_z] particles per cell").within("2 whole numbers, each in [1, 8]"));
    if (ppc[0] != std::floor(ppc[0]) || ppc[1] != std::floor(ppc[1]))
      b.fail("particles_per_cell", "must be two whole numbers [n_r, n_z]");
    body.particles_per_cell_r = static_cast<int>(ppc[0]);
    body.particles_per_cell_z = static_cast<int>(ppc[1]);
    const auto velocity =
        b.optional_numbers("initial_velocity_m_s", Range::closed(-kMaxSpeed_m_s, kMaxSpeed_m_s, "m/s"), 2, 2,
                           Doc("[v_r, v_z] at the start").by_default("[0, 0]"));
    if (velocity) {
      body.initial_velocity_r_m_s = (*velocity)[0];
      body.initial_velocity_z_m_s = (*velocity)[1];
    }
    const Doc geostatic = Doc("a geostatic start: σ'_v from gravity below surface_z_m, σ'_h = K0 σ'_v")
                              .by_default("none: stress-free")
                              .within("object")
                              .only_with("gravity_m_s2");
    if (b.has("initial_stress")) {
      if (!model.gravity_m_s2) b.fail("initial_stress", "a K0 initial stress needs gravity_m_s2");
      SceneReader k0 = b.object("initial_stress", geostatic);
      mpm::GeostaticStress g;
      g.k0 = k0.number("k0", Range::closed(0.0, 10.0), spec.at_rest_k0(),
                       Doc("K0, σ'_h / σ'_v").by_default(std::string(kAtRestK0Words)));
      g.surface_z_m = k0.number("surface_z_m", Range::closed(-kMaxLength_m, kMaxLength_m, "m"),
                                Doc("height of the free surface the stress grows from"));
      k0.finish("initial_stress (k0, surface_z_m)");
      body.initial_stress = g;
    } else {
      b.allow("initial_stress", geostatic);
    }
    body.saturated = read_saturation(b);
    b.finish("a body");
    out.body_names.push_back(body.name);
    model.bodies.push_back(std::move(body));
  }

  const bool saturated =
      std::ranges::any_of(model.bodies, [](const mpm::BodyDescription& d) { return d.saturated.has_value(); });
  model.fluid = read_pore_fluid(scene, saturated);

  SceneReader bc = scene.object("boundaries", Doc("what holds each side of the grid"));
  model.boundaries.inner = read_fixity(bc, axis ? "axis" : "inner", mpm::Fixity::roller, axis);
  model.boundaries.outer = read_fixity(bc, "outer", mpm::Fixity::roller, false);
  model.boundaries.bottom = read_fixity(bc, "bottom", mpm::Fixity::fixed, false);
  model.boundaries.top = read_fixity(bc, "top", mpm::Fixity::free, false);
  model.drainage = read_drainage(bc, model.boundaries, axis, saturated);
  bc.finish(axis ? "boundaries (axis, outer, bottom, top)" : "boundaries (inner, outer, bottom, top)");

  const Range band = Range::closed(model.z_nodes_m.front(), model.z_nodes_m.back(), "m");
  const Range ring = Range::closed(model.r_nodes_m.front(), model.r_nodes_m.back(), "m");
  std::vector<SceneReader> loads = scene.objects(
      "surface_pressures", 0, 16, Doc("pressures on bands of the inner or outer side, or on rings of the top"));
  for (SceneReader& l : loads) {
    mpm::SurfacePressure p;
    p.side = l.choice("side", mpm::kSideNames,
                      Doc("the loaded side (not inner on the symmetry axis); top: the grid's top line z = z_max"));
    if (p.side == mpm::Side::inner && axis)
      l.fail("side", "the inner side is the symmetry axis: it carries no pressure");
    const double pressure =
        1e3 * l.number("pressure_kPa", Range::closed(-1e9, 1e9, "kPa"), Doc("the pressure, compression positive"));
    const double ramp = l.number("ramp_time_s", Range::non_negative(kMaxTime_s, "s"), 0.0,
                                 Doc("the pressure rises from 0 along a half cosine over this time"));
    if (p.side == mpm::Side::top) {
      p.r_min_m = l.number("r_min_m", ring, model.r_nodes_m.front(),
                           Doc("inner radius of the loaded ring")
                               .by_default("the grid's first radial node")
                               .within("inside the grid")
                               .only_with("side top"));
      p.r_max_m = l.number("r_max_m", ring, model.r_nodes_m.back(),
                           Doc("outer radius of the loaded ring")
                               .by_default("the grid's last radial node")
                               .within("inside the grid, > r_min_m")
                               .only_with("side top"));
      if (!(p.r_max_m > p.r_min_m)) l.fail("r_max_m", "must be greater than r_min_m");
    } else {
      p.z_min_m = l.number("z_min_m", band,
                           Doc("bottom of the loaded band").within("inside the grid").only_with("side inner or outer"));
      p.z_max_m =
          l.number("z_max_m", band,
                   Doc("top of the loaded band").within("inside the grid, > z_min_m").only_with("side inner or outer"));
      if (!(p.z_max_m > p.z_min_m)) l.fail("z_max_m", "must be greater than z_min_m");
    }
    // A smooth (half-cosine) ramp excites the lowest modes the least.
    p.pressure_Pa = [pressure, ramp](double t) {
      return t >= ramp ? pressure : pressure * 0.5 * (1.0 - std::cos(kPi * t / ramp));
    };
    l.finish(p.side == mpm::Side::top ? "a top pressure (side, pressure_kPa, ramp_time_s, r_min_m, r_max_m)"
                                      : "a surface pressure (side, pressure_kPa, ramp_time_s, z_min_m, z_max_m)");
    model.pressures.push_back(std::move(p));
  }

  SceneReader solver = scene.object("solver", Doc("the time integration"));
  mpm::SolverSettings& s = model.solver;
  s.shape_function = read_shape_function(solver);
  s.transfer = read_transfer(solver, mpm::Transfer::musl);
  s.flip_fraction = read_flip_fraction(solver);
  s.courant = read_courant(solver);
  s.fixed_dt_s = solver.optional_number(
      "dt_s", Range::positive(kMaxTime_s, "s"),
      Doc("a fixed time step instead (refused above the CFL limit)").by_default("none: courant × the CFL limit"));
  s.strain_smoothing = read_strain_smoothing(solver);
  s.local_damping = read_local_damping(solver);
  solver.finish("solver");

  out.end_time_s = scene.number("end_time_s", Range::positive(kMaxTime_s, "s"), Doc("the simulated time"));

  SceneReader output = scene.object("output", Doc("what the run writes besides the summary"));
  MpmOutput& o = out.output;
  o.history_interval_s = output.number("history_interval_s", Range::positive(kMaxTime_s, "s"), out.end_time_s / 200.0,
                                       Doc("time between history.csv rows").by_default("end_time_s / 200"));
  const std::vector<std::string> allowed = mpm_history_quantities(out.body_names);
  if (auto history = output.raw("history", Doc("the columns of history.csv after time_s")
                                               .by_default("`kinetic_energy_J`, `strain_energy_J`, `total_energy_J`")
                                               .within("a list of " + history_quantities_in_words()))) {
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
    o.field_times_s = output.numbers("field_times_s", Range::closed(0.0, out.end_time_s, "s"), 0, 10000,
                                     Doc("times of the particle fields (VTU)")
                                         .by_default("none: every field_interval_s")
                                         .within("0 to 10000 numbers, each in [0, end_time_s]"));
    std::sort(o.field_times_s.begin(), o.field_times_s.end());
  } else {
    const double interval = output.number("field_interval_s", Range::positive(kMaxTime_s, "s"), out.end_time_s / 10.0,
                                          Doc("time between particle fields (VTU)")
                                              .by_default("end_time_s / 10")
                                              .within("(0, 1e6], at most 10000 fields")
                                              .only_with("no field_times_s"));
    if (out.end_time_s / interval > 10000) output.fail("field_interval_s", "gives more than 10000 field files");
    for (long k = 0; static_cast<double>(k) * interval <= out.end_time_s * (1.0 + 1e-12); ++k)
      o.field_times_s.push_back(static_cast<double>(k) * interval);
  }
  for (SceneReader& p : output.objects("probes", 0, 100,
                                       Doc("points whose nearest particle at the start history.csv follows "
                                           "(position, velocity, stress)"))) {
    MpmProbe probe;
    probe.name = p.text("name", Doc("names the probe's columns"));
    probe.r_m = p.number("r_m", Range::closed(model.r_nodes_m.front(), model.r_nodes_m.back(), "m"),
                         Doc("radius of the point").within("inside the grid"));
    probe.z_m = p.number("z_m", Range::closed(model.z_nodes_m.front(), model.z_nodes_m.back(), "m"),
                         Doc("height of the point").within("inside the grid"));
    p.finish("a probe (name, r_m, z_m)");
    o.probes.push_back(probe);
  }
  output.finish("output");
  scene.finish("an mpm scene");
  return out;
}

}  // namespace ffp
