#pragma once
/// What an MPM run will cost on this machine, said before it runs:
///
///   wall time ≈ steps × particles × (seconds per particle-step)
///
/// The steps to end_time_s come from the time step, the particles from the
/// model, and the rate from a probe: a few steps of the scene's own model,
/// timed here, now. A probe rather than a rate cached by `ffp bench`: a
/// particle-step's cost depends on the scene (probes of the shipped scenes at
/// one load: 0.36 µs for the reference FFP, 0.58 for the SSMC push, 3.4 for the
/// subcycled steel penetrometer) and on what else the machine is running, and a
/// probe measures both; it costs a fraction of a second and needs no file kept
/// per machine.
///
/// How good it is, measured (estimate against the run's wall time, two runs each, a 2-core
/// machine with a load of 12–17): the reference FFP 0.89 and 1.25, the same at 5 mm cells 0.92
/// and 0.76, the steel penetrometer 1.03, the geostatic column 1.19 and 0.86; the CPT push
/// 0.55 and 0.28. A drop or a
/// short run is within about ±25 % (mostly the load changing); a long push runs up to 3.6×
/// longer than estimated, because the probe sees only its start: its step shrinks by a third
/// as the sand loosens around the cone (1.04e4 steps estimated, 14739 taken) and its later
/// steps cost twice its first ones (the contact and the yielding zone grow with depth).
#include <cstddef>
#include <optional>
#include <string>

namespace ffp {

namespace mpm {
class Simulation;
}

struct RunCost {
  double steps = 0.0;  ///< to end_time_s
  std::size_t particles = 0;
  std::optional<double> seconds_per_particle_step;  ///< measured by a probe; none without one
  long probe_steps = 0;                             ///< the steps timed
  std::string probe_failure;                        ///< why the probe has no rate (its step failed)
  /// How many such runs, at most, a job makes one after another (an inverse fit's model runs).
  long runs = 1;

  /// steps × particles × rate, for one run; 0 without a rate.
  double wall_s() const;
  /// Whether one run could last `limit_s` even at kSlowestParticleStep_s: only then is a
  /// probe worth its time before a run.
  bool could_last(double limit_s) const;
};

/// A particle-step's wall time that no scene reaches: 300× the slowest shipped scene's probe
/// (the subcycled steel penetrometer, 3.4 µs on 2 cores under a load of 16).
inline constexpr double kSlowestParticleStep_s = 1e-3;

/// An MPM run above this is refused unless the user allows it (--allow-long).
inline constexpr double kLongRun_s = 86400.0;

/// Steps and particles of a run of `s` (at its start) to `end_time_s`, without a rate.
RunCost plan_mpm_cost(const mpm::Simulation& s, double end_time_s);

/// Steps `s` a little (at least 3 steps and 0.2 s after one untimed step, at most 200 steps,
/// never to end_time_s) and returns the rate it measured and the steps from there to
/// end_time_s at the step it reached. Leaves `s` advanced: the caller builds it afresh.
RunCost measure_mpm_cost(mpm::Simulation& s, double end_time_s);

/// "12 s", "3.5 min", "5.2 h", "12 days".
std::string format_duration(double seconds);

/// One line: "about 1.43e+08 steps to end_time_s × 6086 particles × 0.3 µs per particle-step
/// (measured over 120 steps on this machine now): estimated wall time 12 days", or why there
/// is no estimate.
std::string describe_cost(const RunCost& cost);

}  // namespace ffp
