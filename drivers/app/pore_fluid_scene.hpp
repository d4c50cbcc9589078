#pragma once
/// The keys of a saturated (two-phase) body in an `mpm` scene: the body's pores, the
/// scene's pore fluid and which sides drain it. A scene without a saturated body carries
/// none of them (and its echo gains none). Each key is declared where it is read.
#include <optional>
#include <string>

#include "drivers/scene/scene_reader.hpp"
#include "mpm/boundary_conditions.hpp"
#include "mpm/pore_fluid.hpp"

namespace ffp {

/// A body's `saturated`, `porosity`, `permeability_m_s`, `permeability_law` (reader on the
/// body): none for a dry body.
std::optional<mpm::SaturatedSoil> read_saturation(SceneReader& body);

/// The top-level `fluid` object: read when a body is saturated, refused otherwise. With
/// `water_depth_m` (an ffp or cpt scene's sea bed) it also reads `fluid.water_depth_m`, the free
/// water above the sand, into it.
/// `saturated_key` names the key that makes a body saturated, for the refusal of a dry scene's `fluid`.
mpm::PoreFluid read_pore_fluid(SceneReader& scene, bool saturated, double* water_depth_m = nullptr,
                               const std::string& saturated_key = "bodies[i].saturated");

/// The chamber's sides in an ffp or cpt scene: `soil.drainage` {wall, base} (reader on `soil`),
/// each impermeable (the default: a closed chamber) or drained; refused on a dry sand.
struct ChamberDrainage {
  mpm::Drainage wall = mpm::Drainage::impermeable, base = mpm::Drainage::impermeable;
};
ChamberDrainage read_chamber_drainage(SceneReader& soil, bool saturated);

/// `boundaries.drainage` (reader on `boundaries`): per side impermeable or drained; refused
/// without a saturated body, and an impermeable side must hold the solid's normal velocity.
mpm::DrainageConditions read_drainage(SceneReader& boundaries, const mpm::BoundaryConditions& fixities, bool axis,
                                      bool saturated);

}  // namespace ffp
