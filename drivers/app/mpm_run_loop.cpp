#include "drivers/app/mpm_run_loop.hpp"

#include <algorithm>
#include <cstdio>

#include "drivers/app/thread_governor.hpp"
#include "drivers/output/progress.hpp"

namespace ffp {

namespace {

/// Times are compared with a relative tolerance of 1e-12, so that a time reached
/// by summing steps counts as reached a round-off short of it.
constexpr double kTimeTolerance = 1e-12;

bool reached(double time_s, double target_s) { return time_s >= target_s * (1.0 - kTimeTolerance); }

/// The field times reached by `time_s` and not yet written: one file for all of them.
class FieldTimes {
 public:
  explicit FieldTimes(const std::vector<double>& times) : times_(times) {}

  bool due(double time_s) {
    bool any = false;
    while (next_ < times_.size() && reached(time_s, times_[next_])) {
      ++next_;
      any = true;
    }
    return any;
  }

 private:
  const std::vector<double>& times_;
  std::size_t next_ = 0;
};

}  // namespace

MpmRunResult run_mpm(mpm::Simulation& s, const MpmOutputTimes& times, const MpmRunCallbacks& callbacks,
                     const std::string& kind, const std::string& name, bool show_progress) {
  if (show_progress) std::fprintf(stderr, "%s stages: %s\n", kind.c_str(), s.stages.describe().c_str());
  FieldTimes fields(times.field_times_s);
  callbacks.record_row();
  if (fields.due(s.time_s)) callbacks.write_fields();

  MpmRunResult result;
  result.dt_min_s = s.dt_s;
  double next_history = times.history_interval_s;
  const double end = times.end_time_s;
  Progress progress(kind + " " + name, end, show_progress);
  ThreadGovernor threads;
  try {
    while (!reached(s.time_s, end)) {
      // The smallest step the solver chose, before a landing step's cut: that cut is
      // end_time_s's arithmetic (any length in (0, Δt]), not the model's stability.
      result.dt_min_s = std::min(result.dt_min_s, s.dt_s);
      if (s.time_s + s.dt_s > end) s.dt_s = end - s.time_s;  // land on end_time_s
      s.advance();
      if (callbacks.after_step) callbacks.after_step();
      if (reached(s.time_s, next_history) || reached(s.time_s, end)) {
        callbacks.record_row();
        if (callbacks.after_step_row) callbacks.after_step_row();
        while (next_history <= s.time_s * (1.0 + kTimeTolerance)) next_history += times.history_interval_s;
      }
      if (fields.due(s.time_s)) callbacks.write_fields();
      progress.update(s.time_s, s.step);
      threads.poll();
    }
  } catch (const mpm::StepFailure& e) {
    json reproducer = callbacks.reproducer ? callbacks.reproducer(e) : json(nullptr);
    throw RunFailure(kind + " step " + std::to_string(s.step) + ": " + e.what(), std::move(reproducer));
  }
  progress.finish();
  result.steps = s.step;
  return result;
}

}  // namespace ffp
