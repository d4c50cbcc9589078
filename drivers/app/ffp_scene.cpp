#include "drivers/app/ffp_scene.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "drivers/app/mpm_scene.hpp"
#include "drivers/app/pore_fluid_scene.hpp"
#include "drivers/scene/material_scene.hpp"
#include "models/math_constants.hpp"

namespace ffp {

namespace {

constexpr double kMaxLength_m = 100.0;
constexpr double kMaxTime_s = 1e4;

std::pair<int, int> particles_per_cell(SceneReader& r, const std::string& key, int fallback, const Doc& doc) {
  const std::string n = std::to_string(fallback);
  const auto read =
      r.optional_numbers(key, Range::closed(1, 8), 2, 2,
                         doc.by_default("[" + n + ", " + n + "]").within("2 whole numbers, each in [1, 8]"));
  if (!read) return {fallback, fallback};
  const std::vector<double>& ppc = *read;
  if (ppc[0] != std::floor(ppc[0]) || ppc[1] != std::floor(ppc[1])) r.fail(key, "must be two whole numbers [n_r, n_z]");
  return {static_cast<int>(ppc[0]), static_cast<int>(ppc[1])};
}

/// Returns the material's cohesion c' (Pa; 0 for a sand or an elastic soil).
double read_soil(SceneReader& scene, mpm::FfpDescription& d) {
  SceneReader material = scene.required_object("material", Doc("the sand: its law and density"));
  const MaterialSpec spec = read_material(material, DensityRule::required, MicropolarRule::allowed);
  const double cohesion_Pa = spec.peak_cohesion_Pa();
  d.soil.law = spec.law();
  d.soil.micropolar = spec.micropolar;
  d.soil.density_kg_m3 = *spec.density_kg_m3;
  SceneReader soil = scene.object("soil", Doc("the sand chamber and its particles"));
  d.soil.depth_m = soil.number("depth_m", Range::positive(kMaxLength_m, "m"), 0.4, Doc("depth of the sand"));
  d.soil.radius_m = soil.number("radius_m", Range::positive(kMaxLength_m, "m"), 0.4, Doc("radius of the chamber"));
  d.soil.walls = soil.choice("walls", mpm::kChamberWallsNames, mpm::ChamberWalls::rigid,
                             Doc("the chamber's base and wall: rigid (base fixed, wall on rollers: the paper's) or "
                                 "absorbing (viscous-spring dashpots: the waves leave as into more sand) "
                                 "([theory](../theory.md#absorbing-walls), "
                                 "[verification](../verification.md#chamber-echo))"));
  d.soil.k0 = soil.number("k0", Range::closed(0.0, 10.0), spec.at_rest_k0(),
                          Doc("K0 of the geostatic start, σ'_h = K0 σ'_v ([theory](../theory.md#k0))")
                              .by_default(std::string(kAtRestK0Words)));
  if (soil.has("near_spacing_m")) {
    // A spacing in metres, the same at every mesh size; checked against mesh.min_cell_m in read_mesh.
    if (soil.has("particles_per_cell_near"))
      soil.fail("near_spacing_m",
                "give either near_spacing_m (a length) or particles_per_cell_near (per min cell), not both");
    d.soil.near_spacing_m = soil.number("near_spacing_m", Range::positive(1.0, "m"),
                                        Doc("the near zone's particle spacing as a length, the same at every mesh size")
                                            .by_default("none: particles_per_cell_near")
                                            .within("(0, mesh.min_cell_m]"));
  } else {
    std::tie(d.soil.near_ppc_r, d.soil.near_ppc_z) =
        particles_per_cell(soil, "particles_per_cell_near", 3,
                           Doc("[n_r, n_z] per min_cell_m square in the near zone (the same spacing in larger cells)")
                               .only_with("no near_spacing_m"));
  }
  std::tie(d.soil.far_ppc_r, d.soil.far_ppc_z) =
      particles_per_cell(soil, "particles_per_cell_far", 2, Doc("[n_r, n_z] per grid cell outside the near zone"));
  d.soil.near_radius_m = soil.number(
      "near_radius_m", Range::closed(0.0, d.soil.radius_m, "m", "≤ radius_m"), std::min(0.15, d.soil.radius_m),
      Doc("radius of the near zone").by_default("min(0.15, radius_m)").within("[0, radius_m]"));
  d.soil.near_depth_m =
      soil.number("near_depth_m", Range::closed(0.0, d.soil.depth_m, "m", "≤ depth_m"), d.soil.depth_m,
                  Doc("depth of the near zone").by_default("depth_m").within("[0, depth_m]"));
  d.soil.disconnected_density_ratio =
      soil.number("disconnected_density_ratio", Range::half_open(0.0, 1.0), 0.5,
                  Doc("a particle whose density falls below this fraction of its initial one has lost grain contact: "
                      "no stress, its volume held (Dunatunga & Kamrin 2015; 0: off) "
                      "([theory](../theory.md#disconnection))"));
  d.soil.saturated = read_saturation(soil);
  const ChamberDrainage drainage = read_chamber_drainage(soil, d.soil.saturated.has_value());
  d.soil.wall_drainage = drainage.wall;
  d.soil.base_drainage = drainage.base;
  if (d.soil.saturated && d.soil.walls == mpm::ChamberWalls::absorbing)
    soil.fail("walls", "a saturated sand takes rigid walls (the pore water has no absorbing boundary)");
  soil.finish(
      "soil (depth_m, radius_m, walls, k0, particles_per_cell_near or near_spacing_m, particles_per_cell_far, "
      "near_radius_m, near_depth_m, disconnected_density_ratio, saturated, porosity, permeability_m_s, "
      "permeability_law, drainage)");
  d.soil.fluid = read_pore_fluid(scene, d.soil.saturated.has_value(),
                                 d.soil.saturated ? &d.soil.water_depth_m : nullptr, "soil.saturated");
  return cohesion_Pa;
}

/// Returns the push velocity (cpt) or the impact velocity (ffp), + down.
double read_penetrometer(SceneReader& scene, mpm::FfpDescription& d, PenetrometerKind kind) {
  SceneReader f = scene.required_object(
      "ffp", Doc(kind == PenetrometerKind::cpt ? "the penetrometer, pushed at a constant speed" : "the penetrometer"));
  mpm::PenetrometerShape& shape = d.shape;
  // A flat tip is the rigid circular punch of the bearing-capacity benchmarks (punch_smooth/rough.json).
  if (f.choice("tip", {"cone", "flat"}, "cone", Doc("a cone, or a flat circular base (a punch)")) == "flat") {
    if (f.has("cone_apex_angle_deg")) f.fail("cone_apex_angle_deg", "a flat tip has no cone (give tip: cone for one)");
    shape.cone_apex_angle_rad = kPi;
  } else {
    shape.cone_apex_angle_rad = f.number("cone_apex_angle_deg", Range::open(0.0, 180.0, "degrees"), 60.0,
                                         Doc("full apex angle of the cone").only_with("tip = cone")) *
                                kDegree;
  }
  shape.base_radius_m =
      f.number("base_radius_m", Range::positive(kMaxLength_m, "m"), 0.04375, Doc("radius R of the body"));
  shape.edge_radius_m =
      f.number("edge_radius_m", Range::half_open(0.0, shape.base_radius_m, "m", "< base_radius_m"), 0.005,
               Doc("fillet between the tip and the body (0: a sharp edge)").within("[0, base_radius_m)"));
  shape.body_length_m = f.number("body_length_m", Range::non_negative(kMaxLength_m, "m"), 0.5,
                                 Doc("length of the cylinder above the tip"));
  double speed = 0.0;
  if (kind == PenetrometerKind::cpt) {
    for (const char* key : {"mass_kg", "impact_velocity_m_s", "deformable", "rigid_body_force", "external_force_N"})
      if (f.has(key))
        f.fail(key,
               "a cpt scene pushes a rigid penetrometer at push_velocity_m_s: it has no mass, impact or "
               "rigid-body force (use kind ffp)");
    speed = f.number("push_velocity_m_s", Range::positive(100.0, "m/s", "downward"), Doc("the constant push speed"));
    d.prescribed = true;
    d.velocity_m_s = -speed;
    f.finish(
        "the ffp of a cpt scene (tip, cone_apex_angle_deg, base_radius_m, edge_radius_m, body_length_m, "
        "push_velocity_m_s)");
    return speed;
  }
  if (f.has("push_velocity_m_s"))
    f.fail("push_velocity_m_s", "a prescribed push is kind cpt; an ffp falls freely from impact_velocity_m_s");
  d.mass_kg = f.number("mass_kg", Range::positive(1e6, "kg"), Doc("mass M of the penetrometer"));
  speed = f.number("impact_velocity_m_s", Range::non_negative(1000.0, "m/s", "downward"),
                   Doc("its speed at t = 0, when the tip touches the sand surface"));
  d.velocity_m_s = -speed;
  if (f.has("deformable")) {
    if (d.soil.saturated)
      f.fail("deformable",
             "a saturated sand takes a rigid penetrometer (the pore water's contact is the rigid body's)");
    for (const char* key : {"rigid_body_force", "external_force_N"})
      if (f.has(key)) f.fail(key, "applies to a rigid penetrometer only (this one is deformable)");
    SceneReader e = f.object("deformable", Doc("a linear elastic penetrometer instead of the rigid body; its density "
                                               "is mass_kg over its volume "
                                               "([theory](../theory.md#deformable-penetrometer))")
                                               .by_default("none: rigid")
                                               .within("object"));
    mpm::DeformableFfp body;
    body.youngs_modulus_Pa = 1e3 * e.number("E_kPa", Range::positive(1e9, "kPa"), Doc("its Young's modulus"));
    body.poisson_ratio = e.number("nu", Range::half_open(0.0, 0.5), Doc("its Poisson's ratio"));
    std::tie(body.ppc_r, body.ppc_z) = particles_per_cell(e, "particles_per_cell", 2, Doc("its [n_r, n_z] per cell"));
    e.finish("ffp.deformable (E_kPa, nu, particles_per_cell)");
    d.deformable = body;
  } else {
    for (const char* key : {"E_kPa", "nu", "density_kg_m3", "particles_per_cell"})
      if (f.has(key))
        f.fail(key,
               "a rigid penetrometer has no stiffness or particles: give ffp.deformable {E_kPa, nu, "
               "particles_per_cell} for an elastic one");
    const std::string rigid = "no deformable";
    d.force = f.choice("rigid_body_force", mpm::kRigidBodyForceNames, mpm::RigidBodyForce::contact_impulse,
                       Doc("the soil's reaction on the rigid body: the impulse exchanged at the contact, or the "
                           "paper's eq. 1 as printed (the soil's internal force) "
                           "([theory](../theory.md#rigid-body))")
                           .only_with(rigid));
    d.external_force_N = f.number("external_force_N", Range::closed(-1e9, 1e9, "N", "+ up"), 0.0,
                                  Doc("an extra vertical force on the rigid body").only_with(rigid));
  }
  f.finish(
      "ffp (mass_kg, impact_velocity_m_s, tip, cone_apex_angle_deg, base_radius_m, edge_radius_m, body_length_m, "
      "deformable, rigid_body_force, external_force_N)");
  return speed;
}

void read_contact(SceneReader& scene, mpm::FfpDescription& d) {
  SceneReader c = scene.required_object("contact", Doc("the penetrometer–soil contact"));
  const bool rough = c.boolean("rough", false, Doc("no slip at all (instead of delta_deg)"));
  if (rough && c.has("delta_deg"))
    c.fail("delta_deg", "give either delta_deg (Coulomb, μ = tan δ) or rough: true (no slip), not both");
  if (!rough && !c.has("delta_deg"))
    c.fail("delta_deg", "is required (the FFP–soil friction angle), or give rough: true");
  d.contact.rough = rough;
  if (!rough)
    d.contact.friction =
        std::tan(c.number("delta_deg", Range::half_open(0.0, 90.0, "degrees"),
                          Doc("interface friction angle δ (Coulomb, μ = tan δ)").only_with("rough = false")) *
                 kDegree);
  // Where the contact acts: the nodes within detection_cells of the outline, or each sand particle's
  // domain against the exact outline (mpm/particle_contact.hpp).
  d.surface = c.choice("surface", mpm::kContactSurfaceNames, mpm::ContactSurface::nodes,
                       Doc("where the contact acts: the nodes near the outline, or each sand particle's domain "
                           "against the exact outline (a rigid body only) "
                           "([theory](../theory.md#contact-surface))"));
  if (d.surface == mpm::ContactSurface::particles) {
    if (d.deformable) c.fail("surface", "particles applies to a rigid penetrometer only (this one is deformable)");
    if (d.soil.saturated)
      c.fail("surface", "a saturated sand takes the contact on the nodes (the pore water's is nodal)");
    if (d.force != mpm::RigidBodyForce::contact_impulse)
      c.fail("surface", "particles exchanges impulses: it needs rigid_body_force contact_impulse");
    // The nodes' settings mean nothing to it: refused rather than silently ignored.
    for (const char* key : {"velocity_scaling", "detection_cells"})
      if (c.has(key)) c.fail(key, "applies to surface nodes only (this contact is on the particles)");
  } else {
    // A cap on the correction's strain per step (the paper's code: 0.75), 0 for none.
    d.contact.velocity_scaling =
        c.number("velocity_scaling", Range::closed(0.0, 10.0, "", "strain per step; 0: no cap"), 0.75,
                 Doc("a cap on a contact correction's strain in one step, |Δv|Δt/h (Bardenhagen et al. 2001 as the "
                     "paper's code applies it) ([theory](../theory.md#velocity-scaling))")
                     .only_with("surface = nodes"));
    // Nodes up to half a cell outside the outline take part: the contact surface is then centred on the
    // outline at every h (with 0, only nodes inside: the cone is 0.38 h thinner and soil intrudes 0.75 h).
    d.detection_cells = c.number("detection_cells", Range::closed(0.0, 3.0, "cells"), 0.5,
                                 Doc("nodes up to this many min cells outside the outline are contact nodes: 0.5 "
                                     "centres the contact surface on the outline "
                                     "([theory](../theory.md#detection-cells))")
                                     .only_with("surface = nodes"));
  }
  // Soil particles that end up inside the rigid body's exact outline are put back onto it
  // (positions only), so that the grid contact's small per-step leak cannot accumulate: on by
  // default for a rigid body, chosen by the intrusion it removes (0.07–0.41 cells without it,
  // growing with penetration and not falling with h), not by any comparison with the paper.
  d.project_particles =
      c.boolean("project_particles", !d.deformable,
                Doc("after each step, sand particles inside the exact outline are put back onto it (positions only) "
                    "([theory](../theory.md#particle-projection))")
                    .by_default("`true` for a rigid penetrometer; `false` (and refused) with ffp.deformable"));
  if (d.project_particles && d.deformable)
    c.fail("project_particles", "applies to a rigid penetrometer only (this one is deformable)");
  c.finish("contact (delta_deg or rough, velocity_scaling, detection_cells, surface, project_particles)");
}

void read_mesh(SceneReader& scene, mpm::FfpDescription& d) {
  SceneReader m = scene.object("mesh", Doc("the grid: fine cells around the tip in a band that moves with it "
                                           "([theory](../theory.md#moving-mesh))"));
  mpm::FfpMesh& mesh = d.mesh;
  mesh.min_cell_m =
      m.number("min_cell_m", Range::positive(1.0, "m"), 0.01,
               Doc("fine cells around and below the tip; every other size defaults to a multiple of it (the paper's "
                   "sand does not converge with it: [verification](../verification.md#mesh-convergence))")
                   .within("(0, 1]; ffp.base_radius_m + min_cell_m ≤ soil.radius_m"));
  const double h = mesh.min_cell_m;
  // Sizes default to multiples of min_cell_m, so that --set mesh.min_cell_m=… refines everything.
  mesh.max_cell_m = m.number("max_cell_m", Range::closed(h, 10.0, "m", "≥ min_cell_m"), 3.0 * h,
                             Doc("far-field cells").by_default("3 × min_cell_m").within("[min_cell_m, 10]"));
  mesh.below_cell_m = m.number("below_cell_m", Range::closed(h, 10.0, "m", "≥ min_cell_m"), 2.0 * h,
                               Doc("initial cells of the compressing zone below the band")
                                   .by_default("2 × min_cell_m")
                                   .within("[min_cell_m, 10]"));
  mesh.min_compressed_cell_m =
      m.number("min_compressed_cell_m", Range::closed(0.0, mesh.below_cell_m, "m", "≤ below_cell_m; 0: no limit"), h,
               Doc("the compressing zone's cells shrink to this height, then the band stops and the penetrometer "
                   "goes on through its cells (0: no limit, the paper's moving mesh) "
                   "([theory](../theory.md#min-compressed-cell))")
                   .by_default("min_cell_m")
                   .within("[0, below_cell_m]"));
  mesh.fine_radius_m =
      m.number("fine_radius_m", Range::open(d.shape.base_radius_m, kMaxLength_m, "m", "> ffp.base_radius_m"),
               std::max(0.15, d.shape.base_radius_m + 2.0 * h),
               Doc("uniform radial cells up to here, graded beyond")
                   .by_default("max(0.15, ffp.base_radius_m + 2 × min_cell_m)")
                   .within("(ffp.base_radius_m, 100)"));
  mesh.band_below_m = m.number("band_below_m", Range::positive(kMaxLength_m, "m"), 0.05,
                               Doc("fine cells of the moving band below the tip")
                                   .within("(0, 100]; band_below_m + 2 × min_cell_m < soil.depth_m"));
  mesh.fine_above_m = m.number("fine_above_m", Range::positive(kMaxLength_m, "m"), 0.3,
                               Doc("fine cells of the moving band above the tip"));
  mesh.air_above_m = m.number("air_above_m", Range::positive(kMaxLength_m, "m"), 0.1,
                              Doc("the stretching zone above the penetrometer's top"));
  mesh.growth = m.number("growth", Range{1.0, 2.0, true, false, ""}, 1.2,
                         Doc("largest ratio of neighbouring cells in the graded zones"));
  mesh.tip_offset_cells = m.number("tip_offset_cells", Range{0.0, 1.0, false, true, "cells"}, 0.0,
                                   Doc("the band's node rows sit this many cells above the tip (0: the tip on a node "
                                       "row): the grid's phase against the cone "
                                       "([theory](../theory.md#grid-phase))"));
  mesh.edge_offset_cells = m.number("edge_offset_cells", Range{0.0, 1.0, false, true, "cells"}, 0.0,
                                    Doc("R lies this many cells past the last node column inside it (0: a column on "
                                        "R; 0.5: R midway between two, as the punch benchmarks) "
                                        "([verification](../verification.md#punch))"));
  if (d.soil.near_spacing_m && *d.soil.near_spacing_m > h)
    scene.fail("soil.near_spacing_m",
               "must be at most mesh.min_cell_m (" + std::to_string(h) + " m): at least one particle per cell");
  if (d.shape.base_radius_m + h > d.soil.radius_m)
    m.fail("min_cell_m", "leaves no cell between the penetrometer and the chamber wall");
  if (d.shape.total_length_m() < 3.0 * h)
    m.fail("min_cell_m", "must be at most a third of the penetrometer's length (its cone and ffp.body_length_m)");
  if (mesh.band_below_m + 2.0 * h >= d.soil.depth_m)
    m.fail("band_below_m", "must leave at least two cells of sand below the moving band (soil.depth_m)");
  m.finish(
      "mesh (min_cell_m, max_cell_m, below_cell_m, min_compressed_cell_m, fine_radius_m, band_below_m, fine_above_m, "
      "air_above_m, growth, tip_offset_cells, edge_offset_cells)");
}

void read_solver(SceneReader& scene, mpm::FfpDescription& d, PenetrometerKind kind) {
  SceneReader solver = scene.object("solver", Doc("the time integration"));
  mpm::SolverSettings& s = d.solver;
  s.shape_function = read_shape_function(solver);
  // USL by default: of the two consistent steps, the one whose final penetration
  // changes by shrinking amounts as h halves (the report's convergence study).
  s.transfer = read_transfer(solver, mpm::Transfer::usl);
  s.flip_fraction = read_flip_fraction(solver);
  s.courant = read_courant(solver);
  s.strain_smoothing = read_strain_smoothing(solver);
  d.pic_blend = solver.choice("pic_blend", mpm::kPicBlendNames, mpm::PicBlend::per_soil_step,
                              Doc("how the PIC share 1 − flip_fraction is applied: per soil CFL step (scaled by "
                                  "Δt/Δt_soil), per step, or per second (the 1 cm mesh's soil step on every mesh, as "
                                  "a convergence study needs) ([theory](../theory.md#pic-blend))"));
  if (kind == PenetrometerKind::cpt) {
    // A quasi-static push may damp the waves that an undamped explicit model keeps forever.
    s.local_damping = read_local_damping(solver);
    solver.finish(
        "solver (shape_function, transfer, flip_fraction, pic_blend, courant, strain_smoothing, local_damping)");
  } else {
    if (solver.has("local_damping"))
      solver.fail("local_damping", "the FFP impact is dynamic: no artificial damping (paper section 4)");
    // A stiff deformable penetrometer may take its own substeps inside the soil's step
    // (mpm/body_subcycle.hpp); off by default. Read only with a deformable body, so that a
    // rigid run's echoed scene has no subcycle key and runs again.
    if (d.deformable) {
      d.subcycle = solver.choice("subcycle", mpm::kSubcycleNames, mpm::Subcycle::off,
                                 Doc("a deformable penetrometer's own CFL substeps inside the soil's step: off, on, "
                                     "or auto (when the soil's step is at least 4 times the body's) "
                                     "([verification](../verification.md#subcycling))")
                                     .only_with("ffp.deformable"));
    } else if (solver.has("subcycle")) {
      solver.fail("subcycle", "applies to a deformable penetrometer (ffp.deformable) only");
    }
    solver.finish("solver (shape_function, transfer, flip_fraction, pic_blend, courant, strain_smoothing, subcycle)");
  }
}

}  // namespace

FfpScene read_ffp_scene(SceneReader& scene, PenetrometerKind kind) {
  FfpScene out;
  out.kind = kind;
  mpm::FfpDescription& d = out.model;
  // 0: a weightless soil (the punch benchmarks); the geostatic stage and gravity then drop out.
  d.gravity_m_s2 = scene.number("gravity_m_s2", Range::non_negative(1e3, "m/s²"), 9.81,
                                Doc("gravity g, along −z (0: a weightless soil without a geostatic stage)"));
  const double cohesion_Pa = read_soil(scene, d);
  const double speed = read_penetrometer(scene, d, kind);
  read_contact(scene, d);
  read_mesh(scene, d);
  read_solver(scene, d, kind);

  const Doc end_time = Doc("the simulated time");
  if (kind == PenetrometerKind::cpt) {
    if (scene.has("end_time_s") && scene.has("end_depth_m"))
      scene.fail("end_time_s", "give either end_depth_m or end_time_s, not both");
    if (scene.has("end_time_s")) {
      out.end_time_s = scene.number("end_time_s", Range::positive(kMaxTime_s, "s"),
                                    end_time.by_default("end_depth_m / ffp.push_velocity_m_s"));
    } else {
      const double depth =
          scene.number("end_depth_m", Range::open(0.0, d.soil.depth_m, "m", "< soil.depth_m"),
                       Doc("the push depth").by_default("required unless end_time_s").within("(0, soil.depth_m)"));
      out.end_time_s = depth / speed;
    }
  } else {
    out.end_time_s = scene.number("end_time_s", Range::positive(kMaxTime_s, "s"), end_time);
  }
  if (kind == PenetrometerKind::cpt && d.shape.flat_tip() && cohesion_Pa > 0.0) {
    // A flat punch in a cohesive soil: the bearing benchmark (punch_smooth/rough.json).
    BearingPlateau b;
    b.cohesion_Pa = cohesion_Pa;
    if (auto window = scene.optional_numbers(
            "plateau_settlement_ratio", Range::open(0.0, 1.0, "", "settlement / base_radius_m"), 2, 2,
            Doc("the settlement window [from, to], as fractions of ffp.base_radius_m, over which bearing_factor is "
                "the mean pressure over c' ([verification](../verification.md#punch))")
                .by_default("[0.04, 0.06]")
                .within("2 numbers in (0, 1), from < to, to × ffp.base_radius_m within the push")
                .only_with("ffp.tip = flat and material.c_peak_kPa > 0"))) {
      b.from_ratio = (*window)[0];
      b.to_ratio = (*window)[1];
      if (b.to_ratio <= b.from_ratio) scene.fail("plateau_settlement_ratio", "must be [from, to] with from < to");
    }
    const double window_end_m = b.to_ratio * d.shape.base_radius_m;
    if (window_end_m > speed * out.end_time_s * (1.0 + 1e-9))
      scene.fail("plateau_settlement_ratio", "the window ends at a settlement of " + std::to_string(window_end_m) +
                                                 " m, beyond the push (end_depth_m)");
    out.bearing = b;
  } else if (scene.has("plateau_settlement_ratio")) {
    scene.fail("plateau_settlement_ratio",
               "applies to a cpt scene with ffp.tip flat in a soil with c_peak_kPa > 0 only");
  }

  SceneReader output = scene.object("output", Doc("what the run writes besides the summary"));
  FfpOutput& o = out.output;
  o.history_interval_s =
      output.number("history_interval_s", Range::positive(kMaxTime_s, "s"), std::min(2e-4, out.end_time_s / 100.0),
                    Doc("time between history.csv rows")
                        .by_default("min(2e-4, end_time_s / 100)")
                        .within("(0, 1e4], at most 1e6 rows"));
  if (out.end_time_s / o.history_interval_s > 1e6) output.fail("history_interval_s", "gives more than 10^6 rows");
  if (auto times = output.optional_numbers(
          "field_times_s", Range::closed(0.0, out.end_time_s, "s", "≤ end_time_s"), 0, 1000,
          Doc("times of the particle fields (VTU) and of the strain and stress pictures")
              .by_default(kind == PenetrometerKind::ffp ? "0.04 and 0.06 (those before end_time_s) and end_time_s"
                                                        : "end_time_s")
              .within("0 to 1000 numbers, each in [0, end_time_s]"))) {
    o.field_times_s = *times;
  } else {
    // Fig. 9 shows t = 0.04 s and 0.06 s; a CPT (and a short run) gets its end state.
    if (kind == PenetrometerKind::ffp)
      for (double t : {0.04, 0.06})
        if (t < out.end_time_s) o.field_times_s.push_back(t);
    o.field_times_s.push_back(out.end_time_s);
  }
  std::sort(o.field_times_s.begin(), o.field_times_s.end());
  o.strain_colour_max = output.number("strain_colour_max", Range::positive(100.0), 0.5,
                                      Doc("top of the deviatoric-strain colour scale in the pictures"));
  o.localisation =
      output
          .optional_boolean("localisation",
                            Doc("the soil's loss of ellipticity (Rudnicki & Rice 1975) at the history rows and the "
                                "fields: history localised_fraction, fields localised and band_angle_deg, summary "
                                "localised_fraction_max and localised_time_s "
                                "([outputs](../outputs.md#localisation), [theory](../theory.md#localisation))")
                                .by_default("`false`"))
          .value_or(false);
  output.finish("output (history_interval_s, field_times_s, strain_colour_max, localisation)");
  scene.finish(kind == PenetrometerKind::cpt ? "a cpt scene" : "an ffp scene");
  return out;
}

}  // namespace ffp
