#pragma once
/// Software prefetch for the particle loops that go through ParticleBins' strip order.
/// Such a loop reads each particle's data through an index list, and on the Zen 5
/// EPYC guest the hardware prefetcher did not bring those rows in time once the
/// particles' data lived in memory: asking for the particle 16 places ahead took the
/// sand block's linear P2G (102,400 particles) from 13.6–14.4 to 12.0–12.5 ns per
/// particle-step and its MUSL update from 10.1–10.6 to 9.4–9.5 ns (8 and 32 places
/// ahead gained less). With the data in cache the prefetches are only work: the
/// reference FFP at 1 cm (6,086 particles) ran 2–3 % slower with them. So they are on
/// from kPrefetchMinimum particles (docs/performance.md#design). No result changes.
#include <cstddef>
#include <cstdint>
#include <span>

namespace ffp::mpm {

inline constexpr std::size_t kPrefetchAhead = 16;        ///< particles ahead in the loop's order
inline constexpr std::size_t kPrefetchMinimum = 32'768;  ///< particles from which a step's data outgrow the cache

/// The prefetches of one loop over a run's particles.
class Prefetch {
 public:
  explicit Prefetch(std::size_t particles) : on_(particles >= kPrefetchMinimum) {}
  bool on() const { return on_; }

  /// Asks for the cache lines of *item.
  template <class T>
  void lines(const T* item) const {
    if (!on_) return;
    const char* first = reinterpret_cast<const char*>(item);
    for (std::size_t offset = 0; offset < sizeof(T); offset += 64) __builtin_prefetch(first + offset);
    if constexpr (sizeof(T) % 64 != 0) __builtin_prefetch(first + sizeof(T) - 1);  // an item across two lines
  }
  /// Asks for data[order[k + kPrefetchAhead]], if the loop has it.
  template <class T>
  void ahead(const T* data, std::span<const std::uint32_t> order, std::size_t k) const {
    if (on_ && k + kPrefetchAhead < order.size()) lines(data + order[k + kPrefetchAhead]);
  }

 private:
  bool on_;
};

}  // namespace ffp::mpm
