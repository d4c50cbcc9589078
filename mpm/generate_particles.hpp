#pragma once
/// Filling a body's region with particles on a regular sub-lattice of the grid cells.
#include <cstddef>
#include <cstdint>
#include <span>

#include "mpm/grid.hpp"
#include "mpm/model.hpp"
#include "mpm/particles.hpp"

namespace ffp::mpm {

/// Appends the body's particles: n_r × n_z per cell at the sub-cell centres
/// that lie inside the region; A_p is the sub-cell area, V_p = r_p·A_p,
/// m_p = ρ·V_p, GIMP half-lengths half the sub-cell sides. Cells are visited
/// along the longer grid direction first, so that the particles of one
/// ParticleBins strip sit together in memory. Sets the K0 stress when asked, with
/// the unit weight γ of its vertical stress (ρ·g; a saturated body's effective stress
/// takes the buoyant γ' = γ_sat − γ_w). Cells whose centre lies in one of the body's
/// seeding zones are seeded at the zone's spacing instead.
void append_body_particles(const Grid& grid, const BodyDescription& body, std::uint8_t body_index,
                           double geostatic_unit_weight_N_m3, Particles& particles,
                           std::span<const SeedingZone> zones = {});

/// How many particles append_body_particles would make on a grid with these
/// axes, without making them; counting stops at `limit` (then the result is
/// `limit`: at least that many).
std::size_t count_body_particles(const GridAxis& r_axis, const GridAxis& z_axis, const BodyDescription& body,
                                 std::uint8_t body_index, std::span<const SeedingZone> zones, std::size_t limit);

}  // namespace ffp::mpm
