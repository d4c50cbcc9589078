#include "mpm/model_size.hpp"

#include <cmath>
#include <limits>

#include "mpm/generate_particles.hpp"
#include "mpm/grid_axis.hpp"

namespace ffp::mpm {

ModelSize estimate_model_size(const ModelDescription& model, double budget_bytes) {
  ModelSize size;
  size.nodes = model.r_nodes_m.size() * model.z_nodes_m.size();
  const double room = budget_bytes - size.bytes();
  if (room <= 0.0) {
    size.particles_at_least = true;  // the nodes alone do not fit: no need to count particles
    return size;
  }
  const GridAxis r_axis(model.r_nodes_m), z_axis(model.z_nodes_m);
  auto limit = static_cast<std::size_t>(std::min(room / ModelSize::kBytesPerParticle + 1.0, 1e15));
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const std::size_t n =
        count_body_particles(r_axis, z_axis, model.bodies[b], static_cast<std::uint8_t>(b), model.seeding_zones, limit);
    size.particles += n;
    if (n >= limit) {
      size.particles_at_least = true;
      break;
    }
    limit -= n;
  }
  return size;
}

}  // namespace ffp::mpm
