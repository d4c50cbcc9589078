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
    const auto [first, last] = chunk_range(t);
    std::uint32_t* count = counts(t);
    for (std::size_t p = first; p < last; ++p) ++count[strip[p]];
  }
  finish_build(strip);
}

// A stable counting sort: particles in T contiguous chunks, strip counts per
// chunk, offsets in (strip, chunk) order. The resulting order — by strip,
// ascending index within a strip — is unique, so it is the same for any T.
// (Count rows are offsets.size() = strips + 1 long; the last entry is unused.)
// The chunks are the parts of the last build (nearly the same particles: each
// thread counts the particles it has in cache); the first time, or when the
// thread count or the particles changed, equal index ranges.
void ParticleBins::begin_build(std::size_t n) {
  order.resize(n);
  chunks_ = thread_count();
  const auto T = static_cast<std::size_t>(chunks_);
  if (part_particle_.size() != T + 1 || part_particle_.back() != n) {
    part_particle_.resize(T + 1);
    for (std::size_t t = 0; t <= T; ++t) part_particle_[t] = n * t / T;
  }
  counts_.assign(T * offsets.size(), 0u);
}

// Part t ends at the strip boundary nearest to t·n/T particles.
void ParticleBins::partition(int parts) {
  const auto T = static_cast<std::size_t>(parts);
  const int last_strip = strips();
  const std::size_t n = offsets[static_cast<std::size_t>(last_strip)];
  part_strip_.assign(T + 1, last_strip);
  part_strip_[0] = 0;
  int s = 0;
  for (std::size_t t = 1; t < T; ++t) {
    const std::size_t target = n * t / T;
    while (s < last_strip && offsets[static_cast<std::size_t>(s) + 1] <= target) ++s;
    int cut = s;
    if (s < last_strip &&
        offsets[static_cast<std::size_t>(s) + 1] - target < target - offsets[static_cast<std::size_t>(s)])
      cut = s + 1;
    part_strip_[t] = std::max(cut, part_strip_[t - 1]);
  }
  part_particle_.resize(T + 1);
  for (std::size_t t = 0; t <= T; ++t) part_particle_[t] = offsets[static_cast<std::size_t>(part_strip_[t])];
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
    const auto [first, last] = chunk_range(t);
    std::uint32_t* next = counts(t);
    for (std::size_t p = first; p < last; ++p) order[next[strip[p]]++] = static_cast<std::uint32_t>(p);
  }
  partition(chunks_);
}

}  // namespace ffp::mpm
