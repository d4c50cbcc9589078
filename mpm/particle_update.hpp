#pragma once
/// The end of a particle's step, from the nodal velocities gathered at it: its
/// FLIP/PIC velocity and its move, kept inside the walls. The one definition that
/// the soil's update_particles and move_particles and a subcycled body share.
#include <algorithm>
#include <cstddef>

#include "mpm/simulation.hpp"

namespace ffp::mpm {

/// v_p ← α (v_p + Σ_i S_ip Δv_i) + (1 − α) Σ_i S_ip v_i^{n+1} (FLIP blended with PIC),
/// from the particle's gathered sums v = Σ S v_i^{n+1} and dv = Σ S (v_i^{n+1} − v_i^n).
inline void blend_flip_pic(Particles& P, std::size_t p, double alpha, double v_r, double v_z, double dv_r,
                           double dv_z) {
  P.vr[p] = alpha * (P.vr[p] + dv_r) + (1.0 - alpha) * v_r;
  P.vz[p] = alpha * (P.vz[p] + dv_z) + (1.0 - alpha) * v_z;
}

/// Moves a particle to (r, z), kept inside the walls (counted in `clamps`).
inline void move_within_walls(Particles& P, std::size_t p, double r, double z, const Walls& walls, long& clamps) {
  // Interpolation makes v_n → 0 at a wall, so particles approach it but never
  // cross — unless Δt·|v_i| exceeds a cell at some node, which the CFL estimate
  // does not bound. Keep them in, and count it.
  if (r < walls.r_min || r > walls.r_max || z < walls.z_min || z > walls.z_max) {
    r = std::clamp(r, walls.r_min, walls.r_max);
    z = std::clamp(z, walls.z_min, walls.z_max);
    ++clamps;
  }
  P.r[p] = r;
  P.z[p] = z;
}

}  // namespace ffp::mpm
