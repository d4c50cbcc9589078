/// The FFP summary figures (drivers/app/ffp_summary.hpp) on hand-made samples:
/// times on a binary grid (multiples of 2⁻ⁿ s) keep the impulse sums exact, so
/// most answers are stated exactly.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "drivers/app/ffp_summary.hpp"

using namespace ffp;

namespace {

/// Samples at the given times and impulses, the reaction and deceleration from next_ffp_sample;
/// depth and velocity as given.
std::vector<FfpSample> samples_of(const std::vector<double>& t, const std::vector<double>& impulse,
                                  const std::vector<double>& depth, const std::vector<double>& velocity,
                                  double weight_N) {
  std::vector<FfpSample> s;
  for (std::size_t k = 0; k < t.size(); ++k)
    s.push_back(next_ffp_sample(s.empty() ? nullptr : &s.back(), t[k], depth[k], velocity[k], impulse[k], weight_N));
  return s;
}

/// A rigid body of mass M dropped at v0 onto a soil pushing back with a constant R (W = Mg):
/// v = v0 − (R − W)t/M, depth = v0 t − (R − W)t²/(2M), I = R t; one sample every 2⁻¹⁰ s.
std::vector<FfpSample> constant_reaction_drop(double M, double g, double v0, double R, int rows) {
  const double W = M * g, a = (R - W) / M, dt = std::ldexp(1.0, -10);
  std::vector<double> t, I, depth, v;
  for (int k = 0; k < rows; ++k) {
    const double time = k * dt;
    t.push_back(time);
    I.push_back(R * time);
    depth.push_back(v0 * time - 0.5 * a * time * time);
    v.push_back(v0 - a * time);
  }
  return samples_of(t, I, depth, v, W);
}

}  // namespace

TEST_CASE("a row's reaction is the mean ΔI/Δt since the previous row and its deceleration (R − W)/W",
          "[ffp][summary]") {
  const double W = 4.0;
  const FfpSample first = next_ffp_sample(nullptr, 0.0, 0.0, 5.0, 0.0, W);
  CHECK(first.reaction_N == 0.0);
  CHECK(first.deceleration_g == -1.0);  // no reaction yet: free fall, −1 g
  const FfpSample second = next_ffp_sample(&first, 0.5, 0.25, 4.0, 10.0, W);
  CHECK(second.reaction_N == 20.0);
  CHECK(second.deceleration_g == 4.0);
  CHECK(second.impulse_N_s == 10.0);
  CHECK(second.penetration_m == 0.25);
  CHECK(second.velocity_m_s == 4.0);
  // A first row after t = 0 measures from t = 0 with no impulse.
  CHECK(next_ffp_sample(nullptr, 0.25, 0.0, 0.0, 2.0, W).reaction_N == 8.0);
  // An empty interval (a repeated time) has no mean: 0.
  CHECK(next_ffp_sample(&second, 0.5, 0.25, 4.0, 11.0, W).reaction_N == 0.0);
}

TEST_CASE("the impulse between rows is linear and held beyond the first and last rows", "[ffp][summary]") {
  const std::vector<FfpSample> s = samples_of({0.0, 1.0, 2.0}, {0.0, 4.0, 6.0}, {0, 0, 0}, {0, 0, 0}, 1.0);
  CHECK(impulse_at(s, -1.0) == 0.0);
  CHECK(impulse_at(s, 0.0) == 0.0);
  CHECK(impulse_at(s, 0.5) == 2.0);
  CHECK(impulse_at(s, 1.0) == 4.0);
  CHECK(impulse_at(s, 1.5) == 5.0);
  CHECK(impulse_at(s, 3.0) == 6.0);
  CHECK(mean_reaction(s, 0.5, 1.5) == 3.0);  // (5 − 2)/1: half a second at 4 N, half at 2 N
}

TEST_CASE("the peak is the first row of the largest reaction with that row's time and depth", "[ffp][summary]") {
  // Reactions 10, 30, 30, 20 N over 1 s intervals, W = 10 N.
  const std::vector<FfpSample> s =
      samples_of({0, 1, 2, 3, 4}, {0, 10, 40, 70, 90}, {0, 0.5, 0.75, 0.875, 1.0}, {1, 0.75, 0.5, 0.25, 0.0}, 10.0);
  const FfpFigures f = ffp_figures(s, {1.0, 10.0, 1.0, 4.0, 1.0});
  CHECK(f.peak_deceleration_g == 2.0);
  CHECK(f.time_of_peak_s == 2.0);
  CHECK(f.depth_of_peak_m == 0.75);
  CHECK(f.peak_reaction_N == 30.0);
  CHECK(f.time_of_peak_reaction_s == 2.0);
  CHECK(f.depth_of_peak_reaction_m == 0.75);
  // Centred 2 ms means at t = 1, 2, 3 s: 20, 30 and 25 N (the ends have no full window).
  CHECK(f.peak_deceleration_2ms_g == Approx(2.0).epsilon(1e-9));
  CHECK(f.final_penetration_m == 1.0);
  CHECK(f.final_velocity_m_s == 0.0);
}

TEST_CASE("a 2 ms running mean averages a half-millisecond ripple out", "[ffp][summary]") {
  // Reactions alternate 30 and 10 N every 0.5 ms (W = 10 N): rows peak at 2 g, the 2 ms mean is 20 N, 1 g.
  std::vector<double> t, I, zero;
  double impulse = 0.0;
  for (int k = 0; k <= 20; ++k) {
    if (k > 0) impulse += (k % 2 ? 30.0 : 10.0) * 0.0005;
    t.push_back(k * 0.0005);
    I.push_back(impulse);
    zero.push_back(0.0);
  }
  const FfpFigures f = ffp_figures(samples_of(t, I, zero, zero, 10.0), {1.0, 10.0, 0.0, 0.01, 0.0});
  CHECK(f.peak_deceleration_g == Approx(2.0).epsilon(1e-9));
  CHECK(f.peak_deceleration_2ms_g == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("a run shorter than 2 ms has no running-mean peak", "[ffp][summary]") {
  const std::vector<FfpSample> s = samples_of({0.0, 0.0015}, {0.0, 0.03}, {0, 0}, {1, 1}, 10.0);
  CHECK(std::isinf(ffp_figures(s, {1.0, 10.0, 1.0, 0.0015, 0.0}).peak_deceleration_2ms_g));
}

TEST_CASE("under a constant reaction the figures are those of constant deceleration", "[ffp][summary]") {
  // M = 2 kg, g = 10 m/s², W = 20 N, R = 60 N: 2 g, a = 20 m/s²; v0 = 3 m/s; 0.125 s (129 rows).
  const std::vector<FfpSample> s = constant_reaction_drop(2.0, 10.0, 3.0, 60.0, 129);
  const double t_end = 0.125;
  const FfpFigures f = ffp_figures(s, {2.0, 20.0, 3.0, t_end, 0.21875});
  CHECK(f.peak_deceleration_g == 2.0);              // every row after the first, exactly
  CHECK(f.time_of_peak_s == std::ldexp(1.0, -10));  // the first of them
  CHECK(f.peak_deceleration_2ms_g == Approx(2.0).epsilon(1e-12));
  CHECK(f.final_velocity_m_s == 0.5);       // 3 − 20·0.125
  CHECK(f.final_penetration_m == 0.21875);  // 3·0.125 − 10·0.125²
  CHECK(f.rebound_m == 0.0);
  // Window min(10 ms, 12.5 ms): from the last row at or before 0.115 s, row 117 (0.11426 s).
  CHECK(f.final_reaction_window_s == 11 * std::ldexp(1.0, -10));
  CHECK(f.final_reaction_N == 60.0);
  CHECK(f.final_reaction_inertia_N == Approx(40.0).epsilon(1e-12));  // M a = R − W
  CHECK(f.momentum_balance_error == Approx(0.0).margin(1e-15));
}

TEST_CASE("an impulse that does not match the velocity change shows in the momentum balance", "[ffp][summary]") {
  std::vector<FfpSample> s = constant_reaction_drop(2.0, 10.0, 3.0, 60.0, 129);
  s.back().impulse_N_s += 0.375;  // 0.375 N·s the body did not feel
  CHECK(ffp_figures(s, {2.0, 20.0, 3.0, 0.125, 0.21875}).momentum_balance_error == Approx(0.375 / (2.0 * 3.0)));
  // Without an impact velocity (a body released at rest) the error is per newton of weight.
  std::vector<FfpSample> r = constant_reaction_drop(2.0, 10.0, 0.0, 20.0, 9);  // resting: R = W
  r.back().impulse_N_s += 0.5;
  CHECK(ffp_figures(r, {2.0, 20.0, 0.0, 0.0078125, 0.0}).momentum_balance_error == Approx(0.5 / 20.0));
}

TEST_CASE("a body at rest at the end carries its weight with no inertia in the final window", "[ffp][summary]") {
  // Rows every 1/128 s to 1/16 s, W = 10 N: the last row rests, R = W. The window, 6.25 ms
  // (a tenth of the run), starts from row 7 at 0.0546875 s.
  const double dt = 1.0 / 128;
  const std::vector<FfpSample> s = samples_of({0, dt, 2 * dt, 3 * dt, 4 * dt, 5 * dt, 6 * dt, 7 * dt, 8 * dt},
                                              {0, 0, 0.5, 0.75, 0.875, 0.9, 0.95, 1.0, 1.078125},
                                              {0, 0.05, 0.125, 0.25, 0.25, 0.21875, 0.1875, 0.1875, 0.1875},
                                              {2, 2, 1, 0, -0.5, -0.25, 0, 0, 0}, 10.0);
  const FfpFigures f = ffp_figures(s, {1.0, 10.0, 2.0, 0.0625, 0.25});
  CHECK(f.final_reaction_window_s == dt);
  CHECK(f.final_reaction_N == 10.0);
  CHECK(f.final_reaction_inertia_N == 0.0);
  CHECK(f.max_penetration_m == 0.25);
  CHECK(f.final_penetration_m == 0.1875);
  CHECK(f.rebound_m == 0.0625);
}

TEST_CASE("a run of one row has an empty final window", "[ffp][summary]") {
  const std::vector<FfpSample> s = samples_of({0.0}, {0.0}, {0.0}, {5.0}, 10.0);
  const FfpFigures f = ffp_figures(s, {1.0, 10.0, 5.0, 0.0, 0.0});
  CHECK(f.final_reaction_window_s == 0.0);
  CHECK(f.final_reaction_N == 0.0);
  CHECK(f.final_reaction_inertia_N == 0.0);
  CHECK(f.momentum_balance_error == 0.0);
  CHECK(f.peak_deceleration_g == -1.0);
}
