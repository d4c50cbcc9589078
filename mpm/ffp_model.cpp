#include "mpm/ffp_model.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mpm/diagnostics.hpp"
#include "mpm/model_size.hpp"

namespace ffp::mpm {

namespace {

/// n equal cells over [a, b] appended after a (a itself is already there).
void append_uniform(std::vector<double>& x, double b, int n) {
  const double a = x.back();
  for (int k = 1; k < n; ++k) x.push_back(a + (b - a) * k / n);
  x.push_back(b);
}

/// Cells growing from `first` by `growth` per cell up to `largest`, ending
/// exactly at b: of the two counts around the length, the one whose sizes need
/// the smaller scaling to fit, unless shrinking would make the first cell
/// smaller than `floor` (the neighbouring fine cell).
void append_graded(std::vector<double>& x, double b, double first, double largest, double growth, double floor) {
  const double a = x.back(), length = b - a;
  if (!(length > 0.0)) return;
  std::vector<double> sizes;
  double total = 0.0, size = std::min(first, largest);
  while (total < length) {
    sizes.push_back(size);
    total += size;
    size = std::min(largest, size * growth);
  }
  const double shorter = total - sizes.back();
  const bool shrink_ok = sizes.front() * length / total >= floor;
  if (sizes.size() > 1 && (!shrink_ok || total - length > length - shorter)) {
    total = shorter;
    sizes.pop_back();
  }
  const double scale = length / total;
  double at = a;
  for (std::size_t k = 0; k + 1 < sizes.size(); ++k) {
    at += sizes[k] * scale;
    x.push_back(at);
  }
  x.push_back(b);
}

int cells_in(double length, double cell) { return std::max(1, static_cast<int>(std::floor(length / cell + 1e-9))); }

}  // namespace

FfpGridLayout ffp_grid_layout(const FfpDescription& d) {
  const FfpMesh& m = d.mesh;
  const double h = m.min_cell_m, R = d.shape.base_radius_m;
  // The sizes' ranges and how they fit together are the scene reader's to check, with the
  // key's name in the message (drivers/app/ffp_scene.cpp): here the invariants the layout's
  // arithmetic relies on (cells of positive size that grow, offsets within a cell, a band
  // inside the chamber), which any description that passed the reader holds.
  assert(h > 0.0 && m.max_cell_m >= h && m.below_cell_m >= h && m.growth > 1.0);
  assert(m.tip_offset_cells >= 0.0 && m.tip_offset_cells < 1.0);
  assert(m.edge_offset_cells >= 0.0 && m.edge_offset_cells < 1.0);
  assert(R > 0.0 && R + h <= d.soil.radius_m && m.fine_radius_m > R);
  assert(m.band_below_m > 0.0 && m.band_below_m + 2.0 * h < d.soil.depth_m);

  FfpGridLayout g;
  // Radial: uniform cells no smaller than h on [0, R] and [R, fine], a node exactly at R;
  // or, with an edge offset o, n + o cells of R/(n + o) over [0, R] and the same cells on
  // to the first node at or past `fine` (R then lies o cells past the last column inside it).
  g.r_nodes_m = {0.0};
  double fine = std::min(m.fine_radius_m, d.soil.radius_m);
  if (d.soil.radius_m - fine < 2.0 * h) fine = d.soil.radius_m;  // no sliver of graded cells
  double fine_cell = 0.0;
  if (m.edge_offset_cells > 0.0) {
    const int inside = std::max(1, static_cast<int>(std::floor(R / h - m.edge_offset_cells + 1e-9)));
    fine_cell = R / (inside + m.edge_offset_cells);
    const int cells = static_cast<int>(std::ceil(fine / fine_cell - 1e-9));
    // Not a range of one key: the reader cannot tell before the layout is made.
    if (cells * fine_cell > d.soil.radius_m * (1.0 + 1e-12))
      throw std::invalid_argument("mesh: edge_offset_cells leaves no room in the chamber");
    fine = cells * fine_cell;
    append_uniform(g.r_nodes_m, fine, cells);
  } else {
    append_uniform(g.r_nodes_m, R, cells_in(R, h));
    const int n_fine = cells_in(fine - R, h);
    append_uniform(g.r_nodes_m, fine, n_fine);
    fine_cell = (fine - R) / n_fine;
  }
  append_graded(g.r_nodes_m, d.soil.radius_m, fine_cell * m.growth, std::max(m.max_cell_m, fine_cell), m.growth,
                fine_cell);

  // Vertical, bottom to top: compressing zone, fine band (below and above the
  // tip), graded band along the body up to its top plus a cell, stretching air.
  const int n_below = std::max(1, static_cast<int>(std::lround(m.band_below_m / h)));
  // The band's rows sit tip_offset_cells·h above the tip's row position: 0 puts the
  // tip on a node row, 0.5 half a cell between two (the staircase bias of a
  // non-conforming cone is measured by comparing the two).
  const double offset = m.tip_offset_cells * h;
  const double band_bottom = -n_below * h + offset;
  const double compress = d.soil.depth_m + band_bottom;
  const int n_compress = std::max(2, static_cast<int>(std::lround(compress / m.below_cell_m)));
  g.z_nodes_m = {-d.soil.depth_m};
  if (d.soil.walls == ChamberWalls::absorbing) {
    // One empty cell under the sand: the absorbing base moves (about a millimetre under the
    // axis), and the sand it carries down must stay inside the grid.
    g.z_nodes_m.insert(g.z_nodes_m.begin(), -d.soil.depth_m - compress / n_compress);
    g.base_row = 1;
  }
  append_uniform(g.z_nodes_m, band_bottom, n_compress);
  g.band_first = static_cast<int>(g.z_nodes_m.size()) - 1;
  const double top = d.shape.total_length_m();
  // Fine cells above the tip, leaving at least one cell's height below the body's top (no sliver cell).
  const int n_above =
      std::clamp(static_cast<int>(std::lround(m.fine_above_m / h)), 1, std::max(1, cells_in(top, h) - 1));
  append_uniform(g.z_nodes_m, n_above * h + offset, n_above + n_below);
  append_graded(g.z_nodes_m, top, h * m.growth, m.max_cell_m, m.growth, h);
  const double last_cell = g.z_nodes_m.back() - g.z_nodes_m[g.z_nodes_m.size() - 2];
  g.z_nodes_m.push_back(g.z_nodes_m.back() + last_cell);
  g.band_last = static_cast<int>(g.z_nodes_m.size()) - 1;
  append_uniform(g.z_nodes_m, g.z_nodes_m.back() + m.air_above_m,
                 std::max(2, static_cast<int>(std::lround(m.air_above_m / m.max_cell_m))));
  return g;
}

namespace {

ModelDescription build_model(const FfpDescription& d, const FfpGridLayout& g, const PenetrometerGeometry& geometry) {
  ModelDescription m;
  m.r_nodes_m = g.r_nodes_m;
  m.z_nodes_m = g.z_nodes_m;
  if (d.gravity_m_s2 > 0.0) m.gravity_m_s2 = d.gravity_m_s2;  // weightless: no gravity stage, no K0 stress
  m.solver = d.solver;
  // Paper Fig. 4b: lateral wall on rollers, bottom and top fixed (the top is in the air).
  const FfpSoil& s = d.soil;
  const bool absorbing = s.walls == ChamberWalls::absorbing;
  m.boundaries = {Fixity::roller, absorbing ? Fixity::absorbing : Fixity::roller,
                  absorbing ? Fixity::absorbing : Fixity::fixed, Fixity::fixed};
  if (absorbing) {
    m.wave_source_m = std::pair{0.0, 0.0};  // the impact point: the sand's surface on the axis
    m.absorbing_bottom_row = g.base_row;    // the sand's base, above the grid's empty bottom cell
  }
  assert(s.near_ppc_r >= 1 && s.near_ppc_z >= 1 && s.far_ppc_r >= 1 && s.far_ppc_z >= 1);  // the reader's range
  m.bodies.push_back(BodyDescription{
      "soil", s.law, s.density_kg_m3, BoxRegion{0.0, s.radius_m, -s.depth_m, 0.0}, s.far_ppc_r, s.far_ppc_z, 0.0, 0.0,
      d.gravity_m_s2 > 0.0 ? std::optional<GeostaticStress>(GeostaticStress{s.k0, 0.0}) : std::nullopt,
      s.disconnected_density_ratio * s.density_kg_m3, s.micropolar, s.saturated});
  if (s.saturated) {
    // The wall and base as the scene says; the axis holds v_r = 0 for both phases, and the top
    // row is in the air above the sand, whose free surface is drained.
    m.fluid = s.fluid;
    m.drainage = {Drainage::impermeable, s.wall_drainage, s.base_drainage, Drainage::drained};
    m.water_table_z_m = s.water_depth_m;  // the sand's surface is z = 0
  }
  const double h = d.mesh.min_cell_m;
  assert(!s.near_spacing_m || (*s.near_spacing_m > 0.0 && *s.near_spacing_m <= h));  // the reader's range
  const double spacing_r = s.near_spacing_m ? *s.near_spacing_m : h / s.near_ppc_r;
  const double spacing_z = s.near_spacing_m ? *s.near_spacing_m : h / s.near_ppc_z;
  m.seeding_zones.push_back(
      SeedingZone{0, BoxRegion{0.0, s.near_radius_m, -s.near_depth_m, 0.0}, spacing_r, spacing_z});
  if (d.deformable) {
    const DeformableFfp& f = *d.deformable;
    // The density is fixed below so that the particles carry exactly the given mass.
    const double density = d.mass_kg / d.shape.volume_m3();
    m.bodies.push_back(
        BodyDescription{"penetrometer", LinearElastic(ElasticConstants{f.youngs_modulus_Pa, f.poisson_ratio}), density,
                        ShapeRegion{[geometry](double r, double z) { return geometry.contains(r, z, 0.0); }}, f.ppc_r,
                        f.ppc_z, 0.0, d.velocity_m_s, std::nullopt, 0.0});
  }
  return m;
}

}  // namespace

ModelSize estimate_ffp_size(const FfpDescription& d, double budget_bytes) {
  const FfpGridLayout layout = ffp_grid_layout(d);
  const PenetrometerGeometry geometry(d.shape);
  return estimate_model_size(build_model(d, layout, geometry), budget_bytes);
}

namespace {

/// The settings both kinds of penetrometer take from the description alike.
template <class Settings>
Settings penetrometer_settings(const FfpDescription& d) {
  Settings settings;
  settings.shape = d.shape;
  settings.tip_z_m = 0.0;
  settings.contact = d.contact;
  settings.detection_distance_m = d.detection_cells * d.mesh.min_cell_m;
  return settings;
}

RigidPenetrometerSettings rigid_settings(const FfpDescription& d) {
  auto settings = penetrometer_settings<RigidPenetrometerSettings>(d);
  settings.mass_kg = d.mass_kg;
  settings.velocity_m_s = d.velocity_m_s;
  settings.motion = d.prescribed ? RigidMotion::prescribed : RigidMotion::free;
  settings.force = d.force;
  settings.external_force_N = d.external_force_N;
  settings.surface = d.surface;
  settings.project_particles = d.project_particles;
  if (d.soil.saturated) {
    settings.water_density_kg_m3 = d.soil.fluid.density_kg_m3;
    settings.water_surface_z_m = d.soil.water_depth_m;
  }
  return settings;
}

/// Whether the deformable body takes its own substeps: Subcycle::automatic compares
/// the soil's CFL step (without the body's p-wave; its speed still counts) with the body's.
bool subcycles(Simulation& s, const MaterialGroup& body, Subcycle subcycle) {
  if (subcycle != Subcycle::automatic) return subcycle == Subcycle::on;
  s.main_step_end = body.begin;
  const double soil_limit = cfl_time_step_limit(s);
  s.main_step_end = s.particles.size();
  return soil_limit >= kSubcycleRatio * group_time_step_limit(s, body);
}

/// The deformable penetrometer's own nodal field (two-body contact) and its exact mass:
/// the particles, seeded in its outline, scaled to carry the description's mass.
std::unique_ptr<DeformablePenetrometer> make_deformable(Simulation& s, const FfpDescription& d) {
  // The scene reader refuses these with a rigid body's keys: a deformable body has none of them.
  assert(!d.prescribed && !d.project_particles && d.surface == ContactSurface::nodes);
  s.grid.fields.resize(2);
  s.grid.fields[1].resize(s.grid.nodes());
  s.bodies[1].field = 1;
  MaterialGroup& group = s.groups[1];
  double sampled = 0.0;
  for (std::size_t p = group.begin; p < group.end; ++p) sampled += kTwoPi * s.particles.mass[p];
  const double scale = d.mass_kg / sampled;
  for (std::size_t p = group.begin; p < group.end; ++p) s.particles.mass[p] *= scale;
  group.density_kg_m3 *= scale;
  auto settings = penetrometer_settings<DeformablePenetrometerSettings>(d);
  settings.body = 1;
  settings.subcycle = subcycles(s, group, d.subcycle);
  return std::make_unique<DeformablePenetrometer>(s, settings);
}

/// The PIC share of a step scaled to its length, before update_particles (PicBlend).
void insert_pic_blend(Simulation& s, PicBlend blend, double soil_dt_s, double c_p, double speed_m_s) {
  if (blend == PicBlend::per_step || s.settings.flip_fraction >= 1.0) return;
  // The share of a step is (1 − α)·Δt/Δt_ref. per_soil_step: Δt_ref is this mesh's soil step, and a step
  // takes at most 1 − α. per_second: Δt_ref is the 1 cm mesh's, so the share per step falls with Δt ∝ h
  // and every mesh damps at the same rate per second (per_soil_step's rate grows as 1/h: twice the PIC
  // per second at each halving); a coarse mesh's long step may take more than 1 − α, up to all of it.
  const double pic = 1.0 - s.settings.flip_fraction;
  const bool per_second = blend == PicBlend::per_second;
  const double reference_dt_s = per_second ? 0.5 * kPicReferenceCell_m / (c_p + speed_m_s) : soil_dt_s;
  s.stages.insert_before("update_particles", {"scale_pic_blend", [pic, per_second, reference_dt_s](Simulation& sim) {
                                                sim.settings.flip_fraction =
                                                    per_second ? 1.0 - std::min(1.0, pic * sim.dt_s / reference_dt_s)
                                                               : 1.0 - pic * std::min(1.0, sim.dt_s / reference_dt_s);
                                              }});
}

}  // namespace

FfpRun::FfpRun(const FfpDescription& d)
    : description_(d),
      geometry_(d.shape),
      layout_(ffp_grid_layout(d)),
      mesh_(layout_.z_nodes_m, layout_.band_first, layout_.band_last, d.mesh.min_compressed_cell_m, layout_.base_row),
      simulation_(build_model(d, layout_, geometry_)) {
  Simulation& s = simulation_;
  if (d.deformable && d.soil.saturated)
    throw std::invalid_argument(
        "a saturated sand takes a rigid penetrometer (the pore water's contact is the rigid body's)");
  if (d.deformable) {
    deformable_ = make_deformable(s, d);
    deformable_->attach(s);
  } else {
    rigid_ = std::make_unique<RigidPenetrometer>(rigid_settings(d));
    rigid_->attach(s);
    s.rigid_speed_m_s = std::abs(d.velocity_m_s);
  }
  // The first step: the CFL step of the model with the penetrometer attached.
  s.dt_limit_s = cfl_time_step_limit(s);
  if (s.two_phase) s.dt_limit_s = std::min(s.dt_limit_s, two_phase_time_step_limit(s));
  if (!s.settings.fixed_dt_s) s.dt_s = s.dt_next_s = s.settings.courant * s.dt_limit_s;
  const char* last = s.stages.contains("update_time_step") ? "update_time_step" : "check_time_step";
  s.stages.insert_before(last,
                         {"move_mesh", [this](Simulation& sim) { mesh_.apply(sim.grid, state().displacement_m); }});

  const MaterialGroup& soil = s.groups[0];
  const double c_p = std::sqrt(soil.constrained_modulus() / soil.density_kg_m3);
  // At the project's standard Courant number 0.5, so that the damping per unit time does not
  // follow the Courant number either.
  soil_dt_s_ = 0.5 * s.grid.min_spacing() / (c_p + std::abs(d.velocity_m_s));
  insert_pic_blend(s, d.pic_blend, soil_dt_s_, c_p, std::abs(d.velocity_m_s));
}

double FfpRun::soil_intrusion_m() const {
  const Simulation& s = simulation_;
  const Particles& P = s.particles;
  const MaterialGroup& soil = s.groups[0];
  const double tip = tip_z_m(), R = description_.shape.base_radius_m, top = tip + description_.shape.total_length_m();
  double deepest = 0.0;
  for (std::size_t p = soil.begin; p < soil.end; ++p) {
    if (P.r[p] >= R || P.z[p] <= tip || P.z[p] >= top) continue;  // outside the outline's bounding box
    // Outside the outline the signed distance is ≥ 0 and never the deepest (which starts at 0):
    // the side test spares the distance of the soil particles in the box but outside the outline.
    if (!geometry_.inside(P.r[p], P.z[p], tip)) continue;
    deepest = std::max(deepest, -geometry_.query(P.r[p], P.z[p], tip).signed_distance_m);
  }
  return deepest;
}

std::size_t FfpRun::disconnected_soil_particles() const {
  const Particles& P = simulation_.particles;
  const MaterialGroup& soil = simulation_.groups[0];
  std::size_t count = 0;
  for (std::size_t p = soil.begin; p < soil.end; ++p) count += P.mass[p] <= soil.disconnected_below_kg_m3 * P.volume[p];
  return count;
}

FfpRun::VolumeRatios FfpRun::soil_volume_ratios() const {
  const Particles& P = simulation_.particles;
  const MaterialGroup& soil = simulation_.groups[0];
  VolumeRatios ratios;
  for (std::size_t p = soil.begin; p < soil.end; ++p) {
    const double J = P.volume[p] * soil.density_kg_m3 / P.mass[p];  // V/V0, V0 = m/ρ0
    ratios.max = std::max(ratios.max, J);
    ratios.inflated += J > 2.0 * (1.0 - 1e-9);  // at or past twice V0 (a disconnected particle is held at its limit)
  }
  return ratios;
}

}  // namespace ffp::mpm
