#pragma once
/// Where a material group's particles have lost ellipticity (models/localisation.hpp):
/// the particle fields and the share the history reports. Evaluated only when output is
/// written, never inside the step, so a run's steps are the same with or without it.
#include <cstddef>
#include <span>
#include <vector>

#include "models/voigt.hpp"
#include "mpm/material_group.hpp"

namespace ffp::mpm {

/// Where a particle's stress sits on its Mohr–Coulomb surface, and whether it has localised.
enum class YieldPlace : unsigned char { inside, face, edge, apex, localised };

struct LocalisationMap {
  std::vector<YieldPlace> place;       ///< one per particle (`inside` outside the group)
  std::vector<double> localised;       ///< 1 where det A ≤ 0 (rounding aside), else 0; one per particle
  std::vector<double> band_angle_deg;  ///< band normal from the r axis, [0°, 180°), where localised; else 0
  std::size_t on_face = 0;             ///< particles on a face of the Mohr–Coulomb surface (evaluated)
  std::size_t on_edge = 0;             ///< on an edge (not evaluated: models/localisation.hpp)
  std::size_t at_apex = 0;             ///< at the apex (c' = 0: stress-free, e.g. thrown up or at the surface)
  std::size_t localised_count = 0;
  /// The share of the evaluated yielding particles that have localised (0 when none yields).
  double localised_fraction() const { return on_face == 0 ? 0.0 : static_cast<double>(localised_count) / on_face; }
};

/// The map over particles [group.begin, group.end) of `stress` (absolute indices; the
/// arrays are sized to `stress`, 0 outside the group). A law without a Mohr–Coulomb
/// surface (linear elastic) never localises. Each particle's current φ', ψ, c' and the
/// law's hardening modulus at its state: 0 for Mohr–Coulomb, the softening modulus
/// H < 0 of a strain-softening law (models/localisation.hpp).
LocalisationMap map_localisation(const MaterialGroup& group, std::span<const Voigt> stress);

}  // namespace ffp::mpm
