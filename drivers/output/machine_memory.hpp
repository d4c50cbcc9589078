#pragma once
/// How much memory this process may use: the least of the machine's available
/// memory (MemAvailable), the cgroup limit (memory.max) and the address-space
/// and data rlimits, and FFP_MEMORY_LIMIT_MB when set. Scenes are checked
/// against it before they allocate.
#include <cstdint>
#include <string>

namespace ffp {

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  ///< which limit it is, for messages ("available memory", "ulimit -v", …)
};

MemoryLimit usable_memory();

/// "3.2 GB", "540 MB", "12 kB".
std::string format_bytes(double bytes);

}  // namespace ffp
