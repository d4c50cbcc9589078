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
  const std::size_t n = strip.size();
  begin_build(n);
  FFP_OMP(omp parallel for schedule(static, 1) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks_; ++t) {
    const auto [first, last] = chunk_range(t, n);
    std::uint32_t* count = counts(t);
    for (std::size_t p = first; p < last; ++p) ++count[strip[p]];
  }
  finish_build(strip);
}

// A stable counting sort: particles in T contiguous chunks, strip counts per
// chunk, offsets in (strip, chunk) order. The resulting order — by strip,
// ascending index within a strip — is unique, so it is the same for any T.
// (Count rows are offsets.size() = strips + 1 long; the last entry is unused.)
void ParticleBins::begin_build(std::size_t n) {
  order.resize(n);
  chunks_ = thread_count();
  counts_.assign(static_cast<std::size_t>(chunks_) * offsets.size(), 0u);
}

void ParticleBins::finish_build(std::span<const std::uint32_t> strip) {
  const std::size_t n = strip.size();
  const std::size_t strips_count = static_cast<std::size_t>(strips());
  std::uint32_t running = 0;
  for (std::size_t s = 0; s < strips_count; ++s) {
    offsets[s] = running;
    for (int t = 0; t < chunks_; ++t) {
      std::uint32_t& c = counts(t)[s];
      const std::uint32_t here = c;
      c = running;  // becomes this chunk's next slot in strip s
      running += here;
    }
  }
  offsets[strips_count] = running;
  FFP_OMP(omp parallel for schedule(static, 1) if (n >= kParallelMinimum))
  for (int t = 0; t < chunks_; ++t) {
    const auto [first, last] = chunk_range(t, n);
    std::uint32_t* next = counts(t);
    for (std::size_t p = first; p < last; ++p) order[next[strip[p]]++] = static_cast<std::uint32_t>(p);
  }
}

}  // namespace ffp::mpm
