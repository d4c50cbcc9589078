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

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace ffp::mpm {

/// Loops over fewer items than this run on one thread: a parallel region costs
/// microseconds, more than a small verification model's whole loop.
inline constexpr std::size_t kParallelMinimum = 4096;

/// Threads the MPM loops use (no-op without OpenMP).
void set_thread_count(int threads);
int thread_count();

/// Inside a parallel region: the team's size and this thread's place in it (1 and 0 outside).
inline int team_size() {
#if defined(_OPENMP)
  return omp_get_num_threads();
#else
  return 1;
#endif
}
inline int team_member() {
#if defined(_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}

}  // namespace ffp::mpm
