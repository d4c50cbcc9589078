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

/// Where a particle's stress sits on its Mohr–Coulomb surface, and whether it has localised
/// (`face` and `edge`: evaluated and elliptic; `apex`: not evaluated).
enum class YieldPlace : unsigned char { inside, face, edge, apex, localised };

struct LocalisationMap {
  std::vector<YieldPlace> place;       ///< one per particle (`inside` outside the group)
  std::vector<double> localised;       ///< 1 where det A ≤ 0 (rounding aside), else 0; one per particle
  std::vector<double> band_angle_deg;  ///< band normal from the r axis, [0°, 180°), where localised; else 0
  std::size_t on_face = 0;             ///< particles on a face of the Mohr–Coulomb surface (one plane's tangent)
  std::size_t on_edge = 0;             ///< on an edge (the corner tangent of its two planes: models/localisation.hpp)
  std::size_t at_apex = 0;  ///< at the apex (c' = 0: stress-free, e.g. thrown up or at the surface; not evaluated)
  std::size_t localised_on_face = 0, localised_on_edge = 0;
  std::size_t localised_count() const { return localised_on_face + localised_on_edge; }
  /// The share of the evaluated yielding particles (on a face or an edge) that have localised
  /// (0 when none yields).
  double localised_fraction() const {
    const std::size_t evaluated = on_face + on_edge;
    return evaluated == 0 ? 0.0 : static_cast<double>(localised_count()) / static_cast<double>(evaluated);
  }
};

/// The fewest yielding particles (on a face or an edge) a history row needs for its localised
/// share to count as the run's largest (summary localised_fraction_max): a share of a handful of
/// particles, as under the tip in the first millisecond of a drop, says nothing of the sand.
/// kMinimumYieldingShare of the soil's particles, at least one.
std::size_t minimum_yielding_for_share(std::size_t soil_particles);

/// The share of the soil's particles that must yield (minimum_yielding_for_share).
inline constexpr double kMinimumYieldingShare = 0.05;

/// The map over particles [group.begin, group.end) of `stress` (absolute indices; the
/// arrays are sized to `stress`, 0 outside the group). A law without a Mohr–Coulomb
/// surface (linear elastic) never localises. Each particle's current φ', ψ, c' and the
/// law's hardening moduli at its state: 0 for Mohr–Coulomb, the softening moduli
/// (H < 0 on a face, H_ab at the even split on an edge) of a strain-softening law
/// (models/localisation.hpp).
LocalisationMap map_localisation(const MaterialGroup& group, std::span<const Voigt> stress);

}  // namespace ffp::mpm
