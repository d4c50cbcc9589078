#pragma once
/// Progress of a long run on stderr: a refreshed line (percent, simulated
/// time, steps/s, ETA) on a terminal; otherwise plain lines, the first after
/// 2 s, then one per 10% and at least one a minute.
#include <chrono>
#include <string>

namespace ffp {

class Progress {
 public:
  /// `total` is in the run's own unit (simulated seconds, increments, ...).
  Progress(std::string label, double total, bool enabled = true);
  ~Progress();

  /// Report the run at `done` of `total` after `steps` steps. Cheap to call
  /// every step; also polls for Ctrl-C (throws Interrupted).
  void update(double done, long steps);
  void finish();

 private:
  std::string label_;
  double total_;
  bool enabled_;
  bool terminal_;
  bool finished_ = false;
  int next_decile_ = 1;
  long lines_ = 0;  ///< lines drawn
  long calls_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace ffp
