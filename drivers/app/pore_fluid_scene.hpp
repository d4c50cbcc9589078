#pragma once
/// The keys of a saturated (two-phase) body in an `mpm` scene: the body's pores, the
/// scene's pore fluid and which sides drain it. A scene without a saturated body carries
/// none of them (and its echo gains none). Each key is declared where it is read.
#include <optional>

#include "drivers/scene/scene_reader.hpp"
#include "mpm/boundary_conditions.hpp"
#include "mpm/pore_fluid.hpp"

namespace ffp {

/// A body's `saturated`, `porosity`, `permeability_m_s`, `permeability_law` (reader on the
/// body): none for a dry body.
std::optional<mpm::SaturatedSoil> read_saturation(SceneReader& body);

/// The top-level `fluid` object: read when a body is saturated, refused otherwise.
mpm::PoreFluid read_pore_fluid(SceneReader& scene, bool saturated);

/// `boundaries.drainage` (reader on `boundaries`): per side impermeable or drained; refused
/// without a saturated body, and an impermeable side must hold the solid's normal velocity.
mpm::DrainageConditions read_drainage(SceneReader& boundaries, const mpm::BoundaryConditions& fixities, bool axis,
                                      bool saturated);

}  // namespace ffp
