#pragma once
/// What the CFL step needs of a range of particles: max 1/ρ, max |v|², max |σ| (a
/// Gershgorin bound on the principal stresses of the (r, z) block, and σ_θθ), and how
/// many particles have a non-finite state. Maxima and counts are exact in any order
/// and any grouping of the ranges, so a pass of its own (cfl_time_step_limit) and
/// update_stresses' batches, merged, give the same time step bit for bit.
#include <algorithm>
#include <cstddef>

#include "mpm/particles.hpp"

namespace ffp::mpm {

struct SignalMaxima {
  double stiffest = 0.0, speed2 = 0.0, stress = 0.0;  ///< max 1/ρ, max |v|², max |σ|
  long bad = 0;

  void merge(const SignalMaxima& other) {
    stiffest = std::max(stiffest, other.stiffest);
    speed2 = std::max(speed2, other.speed2);
    stress = std::max(stress, other.stress);
    bad += other.bad;
  }
};

/// The maxima of particles [begin, end).
SignalMaxima signal_maxima(const Particles& particles, std::size_t begin, std::size_t end);

}  // namespace ffp::mpm
