#pragma once
/// OpenMP switches for the MPM loops. The pragmas vanish in builds without
/// OpenMP (FFP_OPENMP=OFF), so the loops stay plain and warning-free.
///
/// Determinism: no loop here reduces floating-point sums across threads.
/// Particle→grid sums are ordered by ParticleBins (mpm/particle_bins.hpp), and
/// every other parallel loop writes one particle or one node per iteration, so
/// results are bit-identical for any thread count.
#if defined(_OPENMP)
#define FFP_OMP(...) _Pragma(#__VA_ARGS__)
#else
#define FFP_OMP(...)
#endif

#include <cstddef>

namespace ffp::mpm {

/// Loops over fewer items than this run on one thread: a parallel region costs
/// microseconds, more than a small verification model's whole loop.
inline constexpr std::size_t kParallelMinimum = 4096;

/// Threads the MPM loops use (no-op without OpenMP).
void set_thread_count(int threads);
int thread_count();

}  // namespace ffp::mpm
