#include "drivers/app/ffp_summary.hpp"

#include <algorithm>
#include <cmath>

namespace ffp {

FfpSample next_ffp_sample(const FfpSample* previous, double time_s, double penetration_m, double velocity_m_s,
                          double impulse_N_s, double weight_N) {
  const double last_t = previous ? previous->time_s : 0.0, last_impulse = previous ? previous->impulse_N_s : 0.0;
  const double interval = time_s - last_t;
  FfpSample s;
  s.time_s = time_s;
  s.penetration_m = penetration_m;
  s.velocity_m_s = velocity_m_s;
  s.reaction_N = interval > 0.0 ? (impulse_N_s - last_impulse) / interval : 0.0;
  s.deceleration_g = (s.reaction_N - weight_N) / weight_N;
  s.impulse_N_s = impulse_N_s;
  return s;
}

double impulse_at(std::span<const FfpSample> samples, double time_s) {
  const auto it = std::lower_bound(samples.begin(), samples.end(), time_s,
                                   [](const FfpSample& s, double t) { return s.time_s < t; });
  if (it == samples.begin()) return samples.front().impulse_N_s;
  if (it == samples.end()) return samples.back().impulse_N_s;
  const FfpSample& a = *(it - 1);
  const FfpSample& b = *it;
  return a.impulse_N_s + (b.impulse_N_s - a.impulse_N_s) * (time_s - a.time_s) / (b.time_s - a.time_s);
}

double mean_reaction(std::span<const FfpSample> samples, double a_s, double b_s) {
  return (impulse_at(samples, b_s) - impulse_at(samples, a_s)) / (b_s - a_s);
}

FfpFigures ffp_figures(std::span<const FfpSample> samples, const FfpRunFacts& facts) {
  const FfpSample& last = samples.back();
  const double M = facts.mass_kg, weight = facts.weight_N, v0 = facts.initial_velocity_m_s;
  FfpFigures f;

  std::size_t peak = 0, peak_reaction = 0;
  for (std::size_t k = 1; k < samples.size(); ++k) {
    if (samples[k].deceleration_g > samples[peak].deceleration_g) peak = k;
    if (samples[k].reaction_N > samples[peak_reaction].reaction_N) peak_reaction = k;
  }
  f.peak_deceleration_g = samples[peak].deceleration_g;
  f.time_of_peak_s = samples[peak].time_s;
  f.depth_of_peak_m = samples[peak].penetration_m;
  f.peak_reaction_N = samples[peak_reaction].reaction_N;
  f.time_of_peak_reaction_s = samples[peak_reaction].time_s;
  f.depth_of_peak_reaction_m = samples[peak_reaction].penetration_m;

  // The 2 ms running mean (centred) at every sample: the cell-crossing ripple (~1.5 ms at 1 cm
  // and 4 m/s) averaged out, as an accelerometer's filter would.
  for (const FfpSample& centre : samples) {
    const double a = std::max(0.0, centre.time_s - 0.001), b = std::min(last.time_s, centre.time_s + 0.001);
    if (b - a < 0.0019) continue;
    f.peak_deceleration_2ms_g = std::max(f.peak_deceleration_2ms_g, (mean_reaction(samples, a, b) - weight) / weight);
  }

  // "Final" reaction: the mean over the last 10 ms (or tenth of the run).
  const double window = std::min(0.01, 0.1 * facts.end_time_s);
  std::size_t from = samples.size() - 1;
  while (from > 0 && samples[from].time_s > last.time_s - window) --from;
  const FfpSample& start = samples[from];
  f.final_reaction_window_s = last.time_s - start.time_s;
  if (last.time_s > start.time_s) {
    f.final_reaction_N = (last.impulse_N_s - start.impulse_N_s) / (last.time_s - start.time_s);
    f.final_reaction_inertia_N = M * (start.velocity_m_s - last.velocity_m_s) / (last.time_s - start.time_s);
  }

  // M(v0 − v) = ∫(R − Mg) dt for the penetrometer.
  const double balance = M * (v0 - last.velocity_m_s) - (last.impulse_N_s - weight * last.time_s);
  f.momentum_balance_error = v0 > 0.0 ? std::abs(balance) / (M * v0) : std::abs(balance) / weight;

  f.final_velocity_m_s = last.velocity_m_s;
  f.final_penetration_m = last.penetration_m;
  f.max_penetration_m = facts.max_penetration_m;
  f.rebound_m = facts.max_penetration_m - last.penetration_m;
  return f;
}

}  // namespace ffp
