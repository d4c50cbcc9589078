#pragma once
/// The pore pressure a piezocone-type FFP reads in saturated sand, taken from the particles
/// that touch its outline (docs/outputs.md#pore-pressure): u1 on the cone's lower half, u2
/// just above the cone–shaft junction (the BlueDrop's port, the "shoulder").
///
/// With h the minimum cell, z_tip the tip's height and H the cone's height, a saturated sand
/// particle touches the outline when its signed distance to it is at most h (one cell outside,
/// or inside it). Of those:
///   u1: z_p ≤ z_tip + H/2            (the cone's lower half, the apex included)
///   u2: z_tip + H ≤ z_p ≤ z_tip + H + 2h   (the first two cells of the shaft above the junction)
/// and the reading is their volume-weighted mean pore pressure Σ V_p p_p / Σ V_p (gauge,
/// hydrostatic included), its excess over hydrostatic likewise. A region no particle touches
/// reads the water standing there: the hydrostatic pressure at the region's mid-height
/// (z_tip + H/4, z_tip + H + h), excess 0.
#include <cstddef>

#include "mpm/ffp_model.hpp"

namespace ffp::mpm {

struct PorePressureReading {
  double pressure_Pa = 0.0;   ///< gauge, compression positive, hydrostatic included
  double excess_Pa = 0.0;     ///< over hydrostatic
  std::size_t particles = 0;  ///< the particles averaged (0: the water's hydrostatic pressure)
};

struct ConePorePressure {
  PorePressureReading u1, u2;
};

/// The readings of a run on a saturated sand at its current state (both 0 on a dry sand).
ConePorePressure cone_pore_pressure(const FfpRun& run);

}  // namespace ffp::mpm
