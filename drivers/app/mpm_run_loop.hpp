#pragma once
/// The time loop every MPM kind (`mpm`, `ffp`, `cpt`) runs: step the simulation
/// to end_time_s, landing on it exactly; a history row at the start, at every
/// history interval and at the end; particle fields at the first step reaching
/// each field time; progress on stderr; Ctrl-C and numerical failures reported
/// as the program reports them. What a row holds and what a field file holds is
/// the kind's, passed in as callbacks (called once per row or file, never per particle).
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/app/job.hpp"
#include "mpm/simulation.hpp"

namespace ffp {

/// When a run writes what.
struct MpmOutputTimes {
  double end_time_s = 0.0;
  double history_interval_s = 0.0;
  std::vector<double> field_times_s;  ///< ascending; fields at the first step reaching each (one file per step)
};

struct MpmRunCallbacks {
  std::function<void()> record_row;      ///< append one history row for the simulation's current state
  std::function<void()> write_fields;    ///< write the particle fields of the current state
  std::function<void()> after_step;      ///< optional: after every step (running extremes)
  std::function<void()> after_step_row;  ///< optional: after every history row a step produced (not the initial one)
  /// Optional: a scene that repeats the failing step, saved by the program beside the error.
  std::function<json(const mpm::StepFailure&)> reproducer;
};

struct MpmRunResult {
  long steps = 0;         ///< the simulation's step count at the end
  double dt_min_s = 0.0;  ///< the smallest step the solver chose (a landing step's cut to end_time_s left out)
};

/// Runs `s` from its current time to `times.end_time_s`. `kind` names the run in
/// the progress line ("<kind> <name>") and in a failure ("<kind> step N: …"):
/// an mpm::StepFailure becomes a RunFailure (exit 1); Progress's Interrupted
/// (Ctrl-C) passes through.
MpmRunResult run_mpm(mpm::Simulation& s, const MpmOutputTimes& times, const MpmRunCallbacks& callbacks,
                     const std::string& kind, const std::string& name, bool show_progress);

/// Builds a kind's model, turning the model's refusals (std::invalid_argument,
/// or a StepFailure from the initial step) into the SceneError "<kind> scene: …".
template <class Make>
auto build_mpm_model(const std::string& kind, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    throw SceneError(kind + " scene: " + e.what());
  } catch (const mpm::StepFailure& e) {
    throw SceneError(kind + " scene: " + e.what());
  }
}

}  // namespace ffp
