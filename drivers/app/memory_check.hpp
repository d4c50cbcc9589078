#pragma once
/// Refusing an MPM scene that cannot fit in memory, before it allocates.
#include <ostream>
#include <string>

#include "mpm/model_size.hpp"

namespace ffp {

/// Throws SceneError naming `key` (the setting that sizes the model), the
/// estimate and the usable memory when the estimate does not fit in 90 % of it.
void require_fits_in_memory(const mpm::ModelSize& size, const std::string& key, const std::string& advice);

/// The budget estimates are counted against: 90 % of the usable memory.
double memory_budget_bytes();

/// "memory: about 24 MB (6086 particles, 1725 nodes); usable 23.3 GB (available memory)"
void describe_memory(std::ostream& out, const mpm::ModelSize& size);

}  // namespace ffp
