#include "drivers/app/memory_check.hpp"

#include "drivers/output/machine_memory.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

namespace {
// The rest is left to the operating system, the page cache and the outputs.
constexpr double kUsableShare = 0.9;

std::string counts(const mpm::ModelSize& size) {
  const std::string nodes = std::to_string(size.nodes) + " nodes";
  if (size.particles_at_least && size.particles == 0) return nodes + "; particles not counted";
  return (size.particles_at_least ? "more than " : "") + std::to_string(size.particles) + " particles, " + nodes;
}
}  // namespace

double memory_budget_bytes() { return kUsableShare * usable_memory().bytes; }

void require_fits_in_memory(const mpm::ModelSize& size, const std::string& key, const std::string& advice) {
  const MemoryLimit limit = usable_memory();
  if (size.bytes() <= kUsableShare * limit.bytes) return;
  throw SceneError(key + ": the model needs " + (size.particles_at_least ? "at least " : "about ") +
                   format_bytes(size.bytes()) + " (" + counts(size) + ") but " + format_bytes(limit.bytes) +
                   " is usable here (" + limit.source + "): " + advice);
}

void describe_memory(std::ostream& out, const mpm::ModelSize& size) {
  const MemoryLimit limit = usable_memory();
  out << "memory: " << (size.particles_at_least ? "at least " : "about ") << format_bytes(size.bytes()) << " ("
      << counts(size) << "); usable " << format_bytes(limit.bytes) << " (" << limit.source << ")\n";
}

}  // namespace ffp
