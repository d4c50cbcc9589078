#pragma once
/// The summary figures of an `ffp` or `cpt` run, as pure functions of its history
/// samples (one per history row): no I/O, no MPM, so they are unit-tested on
/// hand-made samples.
///
/// The reaction of a sample is the mean over the interval since the previous
/// one, from the exact impulse I(t) = ∫R dt the contact transmits, so Σ R·Δt
/// over the samples is I. Every windowed mean below is read from I too:
/// R̄(a, b) = (I(b) − I(a))/(b − a), I interpolated linearly between samples.
#include <cstddef>
#include <limits>
#include <span>

namespace ffp {

/// One history row of a penetrometer run. Depth and velocity are + down, the
/// reaction (soil on the penetrometer) + up.
struct FfpSample {
  double time_s = 0.0;
  double penetration_m = 0.0;
  double velocity_m_s = 0.0;
  double reaction_N = 0.0;      ///< mean over the interval since the previous sample
  double deceleration_g = 0.0;  ///< (R − W)/W with W the weight: + when slowing a downward motion
  double impulse_N_s = 0.0;     ///< ∫R dt since the start
};

/// The sample at `time_s`; its reaction is the mean since `previous` (nullptr for the
/// first sample: since t = 0 with no impulse), 0 over an empty interval.
FfpSample next_ffp_sample(const FfpSample* previous, double time_s, double penetration_m, double velocity_m_s,
                          double impulse_N_s, double weight_N);

/// I(t), linear between samples, the first or last sample's value outside them.
double impulse_at(std::span<const FfpSample> samples, double time_s);

/// R̄ = (I(b) − I(a))/(b − a).
double mean_reaction(std::span<const FfpSample> samples, double a_s, double b_s);

/// What the figures need beside the samples.
struct FfpRunFacts {
  double mass_kg = 0.0;
  double weight_N = 0.0;
  double initial_velocity_m_s = 0.0;  ///< impact (ffp) or push (cpt) velocity, + down
  double end_time_s = 0.0;            ///< the scene's, for the final-reaction window
  double max_penetration_m = 0.0;     ///< the largest depth at any step (not only at the samples)
};

struct FfpFigures {
  // The largest row values (the first row that reaches them).
  double peak_deceleration_g = 0.0, time_of_peak_s = 0.0, depth_of_peak_m = 0.0;
  double peak_reaction_N = 0.0, time_of_peak_reaction_s = 0.0, depth_of_peak_reaction_m = 0.0;
  /// The largest 2 ms centred running mean of the deceleration; −∞ when no full window fits.
  double peak_deceleration_2ms_g = -std::numeric_limits<double>::infinity();
  /// The mean reaction over the last min(10 ms, end_time_s/10), from the sample at or before that
  /// window's start; 0 when the window is empty.
  double final_reaction_N = 0.0, final_reaction_window_s = 0.0;
  /// The part of it that decelerates the body, M Δv/Δt over the window (0 when the window is empty).
  double final_reaction_inertia_N = 0.0;
  /// |M(v0 − v_end) − (I_end − W t_end)| / (M v0) (or / W when v0 ≤ 0): zero up to round-off when the
  /// impulse drives the body exactly.
  double momentum_balance_error = 0.0;
  double final_velocity_m_s = 0.0, final_penetration_m = 0.0, max_penetration_m = 0.0, rebound_m = 0.0;
};

/// The figures of a run; `samples` is not empty, ascending in time, and its last sample is the final state.
FfpFigures ffp_figures(std::span<const FfpSample> samples, const FfpRunFacts& facts);

}  // namespace ffp
