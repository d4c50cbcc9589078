#include "drivers/app/run_cost.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "drivers/app/thread_governor.hpp"
#include "mpm/simulation.hpp"

namespace ffp {

namespace {

/// The probe's length: enough steps that a clock read and one slow step (a page fault, a
/// scheduler quantum) are a few per cent of it, short enough that `ffp check` stays quick.
constexpr double kProbeWall_s = 0.2;
constexpr long kProbeMinSteps = 3, kProbeMaxSteps = 200;

/// Steps from the current time to end_time_s at the current step.
double steps_to_end(const mpm::Simulation& s, double end_time_s) {
  return s.dt_s > 0.0 ? std::ceil(std::max(0.0, end_time_s - s.time_s) / s.dt_s) : 0.0;
}

/// Whether the next step would reach end_time_s (the run's own landing step, which the probe leaves alone).
bool next_step_ends(const mpm::Simulation& s, double end_time_s) { return s.time_s + s.dt_s >= end_time_s; }

}  // namespace

double RunCost::wall_s() const {
  return seconds_per_particle_step ? steps * static_cast<double>(particles) * *seconds_per_particle_step : 0.0;
}

bool RunCost::could_last(double limit_s) const {
  return steps * static_cast<double>(particles) * kSlowestParticleStep_s > limit_s;
}

RunCost plan_mpm_cost(const mpm::Simulation& s, double end_time_s) {
  RunCost cost;
  cost.steps = steps_to_end(s, end_time_s);
  cost.particles = s.particles.size();
  return cost;
}

RunCost measure_mpm_cost(mpm::Simulation& s, double end_time_s) {
  RunCost cost = plan_mpm_cost(s, end_time_s);
  if (cost.steps < 1.0 || cost.particles == 0) return cost;
  ThreadGovernor threads;  // the thread count the run would have
  using Clock = std::chrono::steady_clock;
  try {
    // The first step touches every array for the first time: timed only if it is all there is.
    const Clock::time_point first = Clock::now();
    s.advance();
    threads.poll();
    double elapsed_s = std::chrono::duration<double>(Clock::now() - first).count();
    long timed = 1;
    if (!next_step_ends(s, end_time_s)) {
      const Clock::time_point start = Clock::now();
      timed = 0;
      do {
        s.advance();
        threads.poll();
        ++timed;
        elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
      } while (!next_step_ends(s, end_time_s) && timed < kProbeMaxSteps &&
               (timed < kProbeMinSteps || elapsed_s < kProbeWall_s));
    }
    cost.probe_steps = timed;
    cost.seconds_per_particle_step = elapsed_s / static_cast<double>(timed) / static_cast<double>(cost.particles);
    cost.steps = static_cast<double>(s.step) + steps_to_end(s, end_time_s);
  } catch (const mpm::StepFailure& e) {
    cost.probe_failure = "step " + std::to_string(s.step) + " failed: " + e.what();
  }
  return cost;
}

std::string format_duration(double seconds) {
  char text[32];
  if (seconds < 90.0)
    std::snprintf(text, sizeof text, "%.2g s", seconds);
  else if (seconds < 90.0 * 60.0)
    std::snprintf(text, sizeof text, "%.2g min", seconds / 60.0);
  else if (seconds < 48.0 * 3600.0)
    std::snprintf(text, sizeof text, "%.2g h", seconds / 3600.0);
  else
    std::snprintf(text, sizeof text, "%.3g days", seconds / 86400.0);
  return text;
}

std::string describe_cost(const RunCost& cost) {
  char text[320];
  if (!cost.seconds_per_particle_step) {
    std::snprintf(text, sizeof text, "about %.3g steps to end_time_s × %zu particles; no wall-time estimate (%s)",
                  cost.steps, cost.particles, cost.probe_failure.empty() ? "not measured" : cost.probe_failure.c_str());
    return text;
  }
  std::snprintf(text, sizeof text,
                "about %.3g steps to end_time_s × %zu particles × %.2g µs per particle-step (measured over %ld "
                "steps on this machine now): estimated wall time %s",
                cost.steps, cost.particles, 1e6 * *cost.seconds_per_particle_step, cost.probe_steps,
                format_duration(cost.wall_s()).c_str());
  std::string line = text;
  if (cost.runs > 1) {
    std::snprintf(text, sizeof text, " per model run; at most about %ld runs: up to %s of runs one after another",
                  cost.runs, format_duration(static_cast<double>(cost.runs) * cost.wall_s()).c_str());
    line += text;
  }
  return line;
}

}  // namespace ffp
