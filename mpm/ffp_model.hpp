#pragma once
/// The FFP model of the paper's section 4 (Fig. 4): an axisymmetric sand
/// chamber, a penetrometer (rigid, or linear elastic) whose tip touches the
/// surface at t = 0, frictional contact between them, and a moving mesh that
/// carries a band of fine cells with the penetrometer. Built from plain
/// values (the `ffp`/`cpt` scene kinds and the tests fill them).
///
/// Coordinates: z up, the sand surface at z = 0, the tip initially at z = 0.
/// Every mesh size derives from min_cell_m unless given, so a convergence
/// study needs to change min_cell_m only.
#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/contact_law.hpp"
#include "mpm/deformable_penetrometer.hpp"
#include "mpm/material_group.hpp"
#include "mpm/model.hpp"
#include "mpm/model_size.hpp"
#include "mpm/moving_mesh.hpp"
#include "mpm/penetrometer_geometry.hpp"
#include "mpm/rigid_penetrometer.hpp"
#include "mpm/simulation.hpp"

namespace ffp::mpm {

/// The chamber's base and lateral wall: the paper's rigid ones (base fixed, wall on
/// rollers) or absorbing ones (mpm/boundary_conditions.hpp: the sand goes on beyond them,
/// as under a field drop; the waves the impact sends out do not come back).
enum class ChamberWalls : std::uint8_t { rigid, absorbing };
using ChamberWallsName = std::pair<ChamberWalls, std::string_view>;
/// The scene's names of ChamberWalls, in the order messages list them.
inline constexpr auto kChamberWallsNames =
    std::to_array<ChamberWallsName>({{ChamberWalls::rigid, "rigid"}, {ChamberWalls::absorbing, "absorbing"}});

struct FfpSoil {
  MaterialLaw law = LinearElastic(ElasticConstants{1e6, 0.3});
  double density_kg_m3 = 1488.3;
  double depth_m = 0.4, radius_m = 0.4;  ///< the chamber
  ChamberWalls walls = ChamberWalls::rigid;
  double k0 = 0.39;  ///< σ'_h = K0 σ'_v at t = 0
  /// Near zone (r ≤ near_radius, depth ≤ near_depth): this many particles per
  /// min_cell × min_cell, at the same spacing in larger cells (paper: 10 per cell below the FFP).
  int near_ppc_r = 3, near_ppc_z = 3;
  /// Instead of near_ppc: the near zone's particle spacing as a length, fixed
  /// whatever the mesh (the paper's density, about 4–5 points per cm under the FFP).
  std::optional<double> near_spacing_m;
  /// Elsewhere: particles per grid cell (paper: 4).
  int far_ppc_r = 2, far_ppc_z = 2;
  double near_radius_m = 0.15, near_depth_m = 0.4;
  /// Below this fraction of its initial density a sand particle has lost grain
  /// contact and carries no stress (MaterialGroup::disconnected_below_kg_m3; 0: never).
  /// 0.5 is far beyond any packing (loose sand at D_r = 0 is already at e_max), so
  /// only soil thrown up or torn apart is affected.
  double disconnected_density_ratio = 0.5;
  /// A micropolar sand: the law unchanged, plus a micro-rotation and its linear elastic micro
  /// terms (mpm/micropolar.hpp). None: the classical sand.
  std::optional<MicropolarParameters> micropolar = std::nullopt;
  /// A saturated sand (mpm/two_phase.hpp): its pores, the pore fluid and which chamber sides
  /// drain it (the axis and the air's top row let nothing through / are drained). None: dry.
  std::optional<SaturatedSoil> saturated = std::nullopt;
  PoreFluid fluid;
  Drainage wall_drainage = Drainage::impermeable, base_drainage = Drainage::impermeable;
  /// Free water above the sand surface (m): the water table sits this high above z = 0, the
  /// sand's pore pressure is hydrostatic from it, and the penetrometer's part below it is
  /// buoyed (mpm/rigid_penetrometer.hpp). Saturated only.
  double water_depth_m = 0.0;
};

struct FfpMesh {
  double min_cell_m = 0.01;             ///< the fine cells around and below the tip
  double max_cell_m = 0.03;             ///< far field (radial), above the fine band, the air
  double fine_radius_m = 0.15;          ///< uniform radial cells up to here, then growth ×growth per cell
  double band_below_m = 0.05;           ///< fine moving cells below the tip
  double fine_above_m = 0.3;            ///< fine moving cells above the tip (where the soil beside the body ends up)
  double below_cell_m = 0.02;           ///< initial cells of the compressing zone (they shrink as the FFP goes down)
  double min_compressed_cell_m = 0.01;  ///< ... down to this height; then the band stops (0: no limit)
  double air_above_m = 0.1;             ///< stretching zone above the penetrometer's top
  double growth = 1.2;                  ///< largest ratio of neighbouring cells in graded zones
  double tip_offset_cells = 0.0;        ///< the band's node rows this many cells above the tip's (0: the tip on a row)
  /// The base radius R lies this many radial cells past the last node column at or inside it
  /// (0: a column on R; 0.5: R midway between two, so that the columns inside the base have
  /// tributary widths that tile [0, R] exactly). The radial cells then measure R/(n + offset).
  double edge_offset_cells = 0.0;
};

struct DeformableFfp {
  double youngs_modulus_Pa = 20e6, poisson_ratio = 0.0;  ///< paper Fig. 7: 20 MPa, ν = 0
  int ppc_r = 2, ppc_z = 2;
};

/// How the PIC share (1 − flip_fraction) of the particle velocity update is applied.
enum class PicBlend : std::uint8_t {
  per_step,       ///< the core's rule: (1 − α) of PIC every step, whatever Δt is
  per_soil_step,  ///< (1 − α)·Δt/Δt_soil per step: the same damping per unit time at any Δt of one mesh
  per_second,     ///< (1 − α)·Δt/Δt_1cm per step: the same damping per unit time on every mesh
};
/// The cell of per_second's reference step Δt_1cm = 0.5·h/(c_p + |v0|): the reference FFP's 1 cm.
inline constexpr double kPicReferenceCell_m = 0.01;
using PicBlendName = std::pair<PicBlend, std::string_view>;
/// The scene's names of PicBlend, in the order messages list them.
inline constexpr auto kPicBlendNames = std::to_array<PicBlendName>({{PicBlend::per_soil_step, "per_soil_step"},
                                                                    {PicBlend::per_step, "per_step"},
                                                                    {PicBlend::per_second, "per_second"}});
inline std::string to_string(PicBlend b) {
  return std::string(std::ranges::find(kPicBlendNames, b, &PicBlendName::first)->second);
}

/// Whether a deformable penetrometer takes its own substeps inside the soil's step
/// (mpm/body_subcycle.hpp) or the whole model steps at the stiffer CFL step.
enum class Subcycle : std::uint8_t {
  automatic,  ///< subcycle when the body's CFL step is below kSubcycleRatio times the soil's
  on,
  off,
};
using SubcycleName = std::pair<Subcycle, std::string_view>;
/// The scene's names of Subcycle, in the order messages list them.
inline constexpr auto kSubcycleNames =
    std::to_array<SubcycleName>({{Subcycle::automatic, "auto"}, {Subcycle::on, "on"}, {Subcycle::off, "off"}});
inline std::string to_string(Subcycle c) {
  return std::string(std::ranges::find(kSubcycleNames, c, &SubcycleName::first)->second);
}
/// Subcycling::automatic subcycles when the soil's CFL step is at least this many
/// times the body's: below it a few substeps save little, and the single step is exact.
inline constexpr double kSubcycleRatio = 4.0;

struct FfpDescription {
  FfpSoil soil;
  PenetrometerShape shape;
  double mass_kg = 7.71;
  double velocity_m_s = -5.6;               ///< + up: impact velocity (free) or push velocity (prescribed)
  bool prescribed = false;                  ///< CPT-like constant velocity
  std::optional<DeformableFfp> deformable;  ///< absent: rigid body (section 4.1)
  RigidBodyForce force = RigidBodyForce::contact_impulse;
  double external_force_N = 0.0;  ///< on a free rigid body, + up
  ContactLaw contact;
  ContactSurface surface = ContactSurface::nodes;  ///< rigid only
  double detection_cells = 0.0;  ///< nodes within this many min cells outside the outline are penetrometer nodes
  /// Rigid only: soil particles inside the outline after a step are put back onto it
  /// (RigidPenetrometerSettings::project_particles).
  bool project_particles = false;
  FfpMesh mesh;
  SolverSettings solver;
  /// The PIC blend is a numerical viscosity of about (1 − α)·h²/Δt: applied per
  /// step, a smaller step (a steel FFP's 1e-6 s, the collapse of Δt late in a
  /// run) damps more per unit time and changes the result (measured: a rigid
  /// FFP run at 1/100 of its Δt loses 7 % of its speed in 4 ms instead of 1 %).
  /// per_soil_step scales it to the soil's initial CFL step at Courant 0.5.
  PicBlend pic_blend = PicBlend::per_soil_step;
  Subcycle subcycle = Subcycle::off;  ///< deformable penetrometer only (off: today's single step)
  double gravity_m_s2 = 9.81;
};

/// Initial grid: radial nodes (one exactly at the base radius, so the body's
/// cylinder is grid-conforming) and vertical nodes with the moving band's rows.
struct FfpGridLayout {
  std::vector<double> r_nodes_m, z_nodes_m;
  int band_first = 0, band_last = 0;  ///< rows of the band's bottom and top
  /// The sand's base row: 0, or 1 under absorbing walls, whose base moves and needs a cell of
  /// grid below it for the sand it carries down.
  int base_row = 0;
};

/// The description's sizes in their ranges and fitting together is the scene reader's to
/// check (drivers/app/ffp_scene.cpp; asserted here). Throws std::invalid_argument where
/// the layout itself finds no room (an edge offset whose cells overrun the chamber).
FfpGridLayout ffp_grid_layout(const FfpDescription& description);

/// Nodes and particles of FfpRun(description) before it is built (see estimate_model_size).
ModelSize estimate_ffp_size(const FfpDescription& description, double budget_bytes);

class FfpRun {
 public:
  /// A description the scene reader has checked (see ffp_grid_layout); throws
  /// std::invalid_argument where the model finds it does not fit.
  explicit FfpRun(const FfpDescription& description);
  FfpRun(const FfpRun&) = delete;
  FfpRun& operator=(const FfpRun&) = delete;

  void advance() { simulation_.advance(); }

  Simulation& simulation() { return simulation_; }
  const Simulation& simulation() const { return simulation_; }
  const FfpDescription& description() const { return description_; }
  const FfpGridLayout& layout() const { return layout_; }
  const PenetrometerGeometry& geometry() const { return geometry_; }

  const PenetrometerState& state() const { return rigid_ ? rigid_->state() : deformable_->state(); }
  double tip_z_m() const { return rigid_ ? rigid_->tip_z_m() : deformable_->tip_z_m(); }
  double penetration_m() const { return -state().displacement_m; }  ///< + down
  double velocity_down_m_s() const { return -state().velocity_m_s; }
  /// Whole-body mass: the description's for a rigid body, the particles' sum (equal) for a deformable one.
  double penetrometer_mass_kg() const { return deformable_ ? deformable_->mass_kg() : description_.mass_kg; }
  bool deformable() const { return deformable_ != nullptr; }
  /// The deformable penetrometer's substeps (nullptr: rigid, or stepping with the soil).
  const BodySubcycle* subcycle() const { return deformable_ ? deformable_->subcycle() : nullptr; }
  /// The soil's CFL step at t = 0 with the impact (or push) speed, 0.5·h_min/(c_p + |v0|):
  /// the reference step of PicBlend::per_soil_step.
  double soil_time_step_s() const { return soil_dt_s_; }
  const RigidPenetrometer* rigid() const { return rigid_.get(); }
  RigidPenetrometer* rigid() { return rigid_.get(); }

  std::size_t soil_body() const { return 0; }
  std::size_t soil_particles() const { return simulation_.groups[0].size(); }
  /// How deep the deepest soil particle is inside the outline (0 when none is).
  double soil_intrusion_m() const;
  /// Soil particles that have lost grain contact (below the disconnection density).
  std::size_t disconnected_soil_particles() const;
  /// The largest J = V/V0 of a soil particle, and how many have J > 2.
  struct VolumeRatios {
    double max = 0.0;
    std::size_t inflated = 0;
  };
  VolumeRatios soil_volume_ratios() const;

 private:
  FfpDescription description_;
  PenetrometerGeometry geometry_;
  FfpGridLayout layout_;
  MovingMesh mesh_;
  Simulation simulation_;
  std::unique_ptr<RigidPenetrometer> rigid_;
  std::unique_ptr<DeformablePenetrometer> deformable_;
  double soil_dt_s_ = 0.0;
};

}  // namespace ffp::mpm
