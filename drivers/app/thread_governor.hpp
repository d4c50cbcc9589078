#pragma once
/// The MPM's OpenMP thread count, chosen from the cores other processes leave
/// idle and re-chosen as that changes during a run.
///
/// Why: every MPM step passes a dozen barriers. When another process holds a
/// core, the thread that shares it waits a scheduler quantum at each of them,
/// and two threads are many times slower than one (measured here: a 0.7 s FFP
/// run took 8–11 s on two threads beside one busy process, 0.5–0.7 s on one).
/// The results do not depend on the thread count (mpm/parallel.hpp), so the
/// count may change at any step.
///
/// How: at the start, the runnable tasks of /proc/stat other than this one;
/// then every `interval` the CPU time other processes took (all CPUs' busy
/// time less this process's own), rounded up from 0.2 of a core. A user's
/// OMP_NUM_THREADS turns the governor off.
#include <chrono>

namespace ffp {

class ThreadGovernor {
 public:
  explicit ThreadGovernor(std::chrono::milliseconds interval = std::chrono::milliseconds(250));
  ~ThreadGovernor();  ///< gives back the thread count it found
  ThreadGovernor(const ThreadGovernor&) = delete;
  ThreadGovernor& operator=(const ThreadGovernor&) = delete;
  /// Call once per step: cheap (a clock read) except once per interval.
  void poll();
  int threads() const { return threads_; }

 private:
  struct CpuTimes {
    double all_busy = 0.0, all_total = 0.0, own = 0.0;  ///< clock ticks
  };
  static CpuTimes read_cpu_times();
  void choose(double others_cores);

  bool active_ = false;
  int cores_ = 1, threads_ = 1;
  std::chrono::milliseconds interval_;
  std::chrono::steady_clock::time_point last_;
  CpuTimes last_times_;
};

}  // namespace ffp
