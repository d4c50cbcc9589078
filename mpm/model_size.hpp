#pragma once
/// The size of a model before it is built: nodes, particles and the memory
/// they will take, so that a scene that cannot fit is refused before any
/// allocation (a 1e-5 m mesh of the FFP chamber would ask for ~10^10 particles).
#include <cstddef>

#include "mpm/model.hpp"

namespace ffp::mpm {

struct ModelSize {
  std::size_t nodes = 0;
  std::size_t particles = 0;
  bool particles_at_least = false;  ///< counting stopped once the memory budget was passed

  /// Bytes per particle and per node of a running FFP model, measured with the
  /// peak resident size of `ffp run` on the reference scene at 2.5 and 1.25 mm
  /// (97,560 → 395,280 particles, 25,080 → 99,750 nodes: 97 → 341 MB, GIMP,
  /// including the spare capacity of growing vectors) and rounded up.
  static constexpr double kBytesPerParticle = 900.0;
  static constexpr double kBytesPerNode = 400.0;
  static constexpr double kBaseBytes = 32e6;  ///< the program and its libraries
  double bytes() const {
    return kBaseBytes + kBytesPerParticle * static_cast<double>(particles) + kBytesPerNode * static_cast<double>(nodes);
  }
};

/// Counts the nodes and the particles `Simulation(model)` would make, without
/// making them; stops counting particles once the estimate passes `budget_bytes`.
ModelSize estimate_model_size(const ModelDescription& model, double budget_bytes);

}  // namespace ffp::mpm
