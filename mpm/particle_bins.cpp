#include "mpm/particle_bins.hpp"

namespace ffp::mpm {

void ParticleBins::configure(int cr, int cz) {
  axis = cr >= cz ? 0 : 1;
  cells_r_ = cr;
  cells_z_ = cz;
  const int cells = axis == 0 ? cr : cz;
  offsets.assign(static_cast<std::size_t>((cells + width - 1) / width) + 1, 0);
}

void ParticleBins::build(std::span<const std::uint32_t> strip) {
  // A stable counting sort: particles in T contiguous chunks, strip counts per
  // chunk, offsets in (strip, chunk) order. The resulting order — by strip,
  // ascending index within a strip — is unique, so it is the same for any T.
  const std::size_t n = strip.size();
  const std::size_t strips_count = static_cast<std::size_t>(strips());
  order.resize(n);
  const int chunks = thread_count();
  counts_.assign(static_cast<std::size_t>(chunks) * strips_count, 0u);
  FFP_OMP(omp parallel for schedule(static, 1) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks; ++t) {
    const std::size_t first = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(chunks);
    const std::size_t last = n * (static_cast<std::size_t>(t) + 1) / static_cast<std::size_t>(chunks);
    std::uint32_t* count = counts_.data() + static_cast<std::size_t>(t) * strips_count;
    for (std::size_t p = first; p < last; ++p) ++count[strip[p]];
  }
  std::uint32_t running = 0;
  for (std::size_t s = 0; s < strips_count; ++s) {
    offsets[s] = running;
    for (int t = 0; t < chunks; ++t) {
      std::uint32_t& c = counts_[static_cast<std::size_t>(t) * strips_count + s];
      const std::uint32_t here = c;
      c = running;  // becomes this chunk's next slot in strip s
      running += here;
    }
  }
  offsets[strips_count] = running;
  FFP_OMP(omp parallel for schedule(static, 1) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks; ++t) {
    const std::size_t first = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(chunks);
    const std::size_t last = n * (static_cast<std::size_t>(t) + 1) / static_cast<std::size_t>(chunks);
    std::uint32_t* next = counts_.data() + static_cast<std::size_t>(t) * strips_count;
    for (std::size_t p = first; p < last; ++p) order[next[strip[p]]++] = static_cast<std::uint32_t>(p);
  }
}

}  // namespace ffp::mpm
