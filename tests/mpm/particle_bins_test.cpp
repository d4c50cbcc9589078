/// ParticleBins' balanced batches (for_each_particle_batch): every particle of the
/// range once, whatever the thread count and wherever the range cuts the parts.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <vector>

#include "mpm/parallel.hpp"
#include "mpm/particle_bins.hpp"

using namespace ffp::mpm;

namespace {

/// Bins over a 40 × 10 cell grid (strips of cell columns) whose particles crowd into
/// the first strips, as the plastic zone about the cone does: the parts then
/// hold unequal index ranges.
ParticleBins crowded_bins(std::size_t n) {
  ParticleBins bins;
  bins.configure(40, 10);
  std::vector<std::uint32_t> strip(n);
  for (std::size_t p = 0; p < n; ++p) strip[p] = static_cast<std::uint32_t>(p < n / 2 ? 0 : (p % 10));
  bins.build(strip);
  return bins;
}

}  // namespace

TEST_CASE("balanced batches visit each particle of the range once, for any thread count", "[mpm][bins]") {
  const int threads = thread_count();
  constexpr std::size_t n = 20000;
  for (int t : {1, 2, 3}) {
    set_thread_count(t);
    const ParticleBins bins = crowded_bins(n);
    for (const auto& [begin, end] : {std::pair<std::size_t, std::size_t>{0, n}, {137, 15001}, {19000, n}, {500, 500}}) {
      std::vector<std::atomic<int>> visits(n);
      std::atomic<int> bad_batches{0};  // Catch's assertions are not for worker threads
      bins.for_each_particle_batch(begin, end, n, 512, true, [&](std::size_t first, std::size_t last) {
        if (!(first < last && last - first <= 512)) ++bad_batches;
        for (std::size_t p = first; p < last; ++p) ++visits[p];
      });
      int wrong = 0;
      for (std::size_t p = 0; p < n; ++p) wrong += visits[p] != (p >= begin && p < end ? 1 : 0);
      CHECK(wrong == 0);
      CHECK(bad_batches == 0);
    }
  }
  set_thread_count(threads);
}
