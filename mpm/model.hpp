#pragma once
/// What a simulation is built from: grid coordinates, bodies, boundaries,
/// loads and solver settings. The `mpm` scene kind fills this from JSON; tests
/// fill it in code.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "models/micropolar.hpp"
#include "mpm/boundary_conditions.hpp"
#include "mpm/material_group.hpp"
#include "mpm/pore_fluid.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp::mpm {

enum class Transfer : std::uint8_t {
  usl,            ///< update stress last: positions and strain rate from v_i^{n+1} of the grid update
  musl,           ///< modified USL (Sulsky et al. 1995): positions from v_i^{n+1}, strain rate from the velocities
                  ///< remapped from the updated particles (with contact, the remapped field is corrected again)
  musl_remapped,  ///< the paper's code (Anura3D): positions and strain rate both from the remapped
                  ///< velocities, no second contact correction: a particle moves as it strains
};
using TransferName = std::pair<Transfer, std::string_view>;
/// The scene's names of Transfer, in the order messages list them.
inline constexpr auto kTransferNames = std::to_array<TransferName>(
    {{Transfer::usl, "usl"}, {Transfer::musl, "musl"}, {Transfer::musl_remapped, "musl_remapped"}});
inline std::string to_string(Transfer t) {
  return std::string(std::ranges::find(kTransferNames, t, &TransferName::first)->second);
}

/// Which part of the strain increment is averaged over each cell (and, as its
/// transpose in the internal force, which part of the stress): stage_stress.cpp.
enum class StrainSmoothing {
  off,         ///< each particle its own strain increment and stress
  volumetric,  ///< B-bar: the cell-mean volumetric part (anti-locking)
  full,        ///< the whole cell-mean tensor: one strain per cell, as one-point (mixed) integration
};
using StrainSmoothingName = std::pair<StrainSmoothing, std::string_view>;
/// The scene's names of StrainSmoothing, in the order messages list them.
inline constexpr auto kStrainSmoothingNames = std::to_array<StrainSmoothingName>(
    {{StrainSmoothing::off, "off"}, {StrainSmoothing::volumetric, "volumetric"}, {StrainSmoothing::full, "full"}});

struct SolverSettings {
  ShapeFunction shape_function = ShapeFunction::gimp;
  Transfer transfer = Transfer::musl;
  double flip_fraction = 0.99;       ///< α in v_p ← α·FLIP + (1 − α)·PIC
  double courant = 0.5;              ///< Δt = C·h_min/(c_p + |v|_max)
  std::optional<double> fixed_dt_s;  ///< when set, Δt is fixed (checked against the CFL limit every step)
  StrainSmoothing strain_smoothing = StrainSmoothing::volumetric;
  double local_damping = 0.0;  ///< Cundall's local damping coefficient (0: no damping stage)
};

/// Particles fill the grid cells inside the region (a particle belongs to the
/// body when its centre is inside).
struct BoxRegion {
  double r_min_m = 0.0, r_max_m = 0.0, z_min_m = 0.0, z_max_m = 0.0;
};
/// A sphere centred on the axis.
struct SphereRegion {
  double center_z_m = 0.0, radius_m = 0.0;
};
/// Any shape given by a membership test on (r, z), e.g. the penetrometer's outline.
struct ShapeRegion {
  std::function<bool(double r_m, double z_m)> contains;
};
using Region = std::variant<BoxRegion, SphereRegion, ShapeRegion>;

/// Denser seeding inside part of a body: grid cells of `body` whose centre lies
/// in `region` get round(h_r/spacing_r) × round(h_z/spacing_z) particles (at least
/// 1 × 1) instead of the body's particles per cell, so that the particle spacing
/// stays the same in cells of different size (a graded or compressing mesh).
struct SeedingZone {
  std::size_t body = 0;
  BoxRegion region;
  double spacing_r_m = 0.0, spacing_z_m = 0.0;
};

/// K0 initial stress: σ'_v = γ·depth, σ'_h = K0·σ'_v (depth below surface_z).
struct GeostaticStress {
  double k0 = 0.5;
  double surface_z_m = 0.0;
};

struct BodyDescription {
  std::string name;
  MaterialLaw law;
  double density_kg_m3 = 0.0;
  Region region;
  int particles_per_cell_r = 2, particles_per_cell_z = 2;
  double initial_velocity_r_m_s = 0.0, initial_velocity_z_m_s = 0.0;
  std::optional<GeostaticStress> initial_stress;  ///< needs gravity
  /// Granular bodies: below this density (kg/m³) the grains have lost contact and
  /// the particle carries no stress (0: never). See MaterialGroup.
  double disconnected_below_kg_m3 = 0.0;
  /// A micropolar (Cosserat) body: the law's return unchanged on the symmetric strain, plus
  /// a micro-rotation and the linear elastic micro terms (mpm/micropolar.hpp). None: classical.
  std::optional<MicropolarParameters> micropolar = std::nullopt;
  /// A saturated (two-phase) body: its pores hold the model's PoreFluid, and
  /// density_kg_m3 is its dry density (mpm/pore_fluid.hpp). None: a dry body.
  std::optional<SaturatedSoil> saturated = std::nullopt;
};

enum class Side : std::uint8_t { inner, outer, top };
using SideName = std::pair<Side, std::string_view>;
/// The scene's names of Side, in the order messages list them.
inline constexpr auto kSideNames =
    std::to_array<SideName>({{Side::inner, "inner"}, {Side::outer, "outer"}, {Side::top, "top"}});
inline std::string to_string(Side s) { return std::string(std::ranges::find(kSideNames, s, &SideName::first)->second); }

/// A normal pressure on the inner or outer grid line r = r_0 / r_max, over
/// z_min ≤ z ≤ z_max, or on the top grid line z = z_max over r_min ≤ r ≤ r_max
/// (the body's face must lie on that grid line).
struct SurfacePressure {
  Side side = Side::inner;
  double z_min_m = 0.0, z_max_m = 0.0;               ///< inner, outer: the loaded band
  std::function<double(double time_s)> pressure_Pa;  ///< compression positive
  double r_min_m = 0.0, r_max_m = 0.0;               ///< top: the loaded band
};

struct ModelDescription {
  std::vector<double> r_nodes_m, z_nodes_m;
  std::vector<BodyDescription> bodies;
  BoundaryConditions boundaries;
  /// Where the waves an absorbing side takes come from (r, z in m): adds the far field's
  /// springs to its dashpots (mpm/boundary_conditions.hpp). None: dashpots alone.
  std::optional<std::pair<double, double>> wave_source_m;
  /// The row of an absorbing bottom's dashpots: 0 (the grid's edge) or a row above empty cells
  /// (the sand's base over a margin), whose grid edge is then fixed.
  int absorbing_bottom_row = 0;
  std::optional<double> gravity_m_s2;  ///< magnitude, acting along −z; absent: no gravity stage
  std::vector<SurfacePressure> pressures;
  SolverSettings solver;
  std::vector<SeedingZone> seeding_zones;  ///< first matching zone wins; none: bodies' particles per cell
  /// The pore fluid of the saturated bodies and which sides drain it (unused without one).
  PoreFluid fluid;
  DrainageConditions drainage;
  /// The water table z_wt of the hydrostatic pore pressure (m): above a body's K0 surface for
  /// a sea bed under water (its surface then carries ρ_w g (z_wt − z_surface)). None: the
  /// first saturated body's K0 surface.
  std::optional<double> water_table_z_m;
};

}  // namespace ffp::mpm
