#include "drivers/record_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ffp {

namespace {

template <class... Args>
std::string formatted(const char* format, Args... args) {
  const int length = std::snprintf(nullptr, 0, format, args...);
  std::string out(static_cast<std::size_t>(std::max(length, 0)), '\0');
  std::snprintf(out.data(), out.size() + 1, format, args...);
  return out;
}

/// The bound of largest_credible_deceleration_g and the two figures it comes from.
struct CredibleBound {
  double interval_s, fastest_m_s, deceleration_g;
};

CredibleBound credible_bound(const std::vector<double>& t, const RecordSettings& s) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < t.size(); ++k) steps.push_back(t[k] - t[k - 1]);
  const auto middle = steps.begin() + static_cast<long>(steps.size() / 2);
  std::nth_element(steps.begin(), middle, steps.end());
  const double interval = *middle;
  const double fastest = s.impact_velocity_m_s.value_or(0.0) + s.gravity_m_s2 * (t.back() - t.front());
  return {interval, fastest, 2.0 * fastest / (s.gravity_m_s2 * interval)};
}

/// The body never slows: either the pulse is upside down (a net deceleration far below free
/// fall, which only a wrong sign gives) or no impact follows the impact time.
[[noreturn]] void refuse_never_slowing(const InterpretedRecord& r, std::string_view column, double v_min,
                                       double v_end) {
  const double most_negative = *std::min_element(r.deceleration_g.begin(), r.deceleration_g.end());
  const double most_positive = *std::max_element(r.deceleration_g.begin(), r.deceleration_g.end());
  const std::string what = formatted(
      "after the impact at t = %.6g s the body never slows: from %.4g m/s it never falls below %.4g m/s "
      "and ends at %.4g m/s",
      r.impact_time_s, r.impact_velocity_m_s, v_min, v_end);
  if (most_negative < kWrongSignBelow_g && -most_negative > most_positive)
    throw RecordError(
        std::string(column) + " looks like it has the wrong sign: " + what +
        formatted(" while its pulse reaches %.4g g net; a penetrometer slows in the soil "
                  "(net deceleration + while slowing, sensor reading + toward the sky): negate the column",
                  most_negative));
  throw RecordError(what + "; no impact follows " +
                    (r.impact_detected ? std::string("the detected start of the pulse")
                                       : std::string("impact_time_s: is it right?")));
}

/// The free-fall bound: after the impact nothing but gravity speeds the body up, so
/// v(t) ≤ v0 + g (t − t0).
void refuse_faster_than_free_fall(const InterpretedRecord& r, double g, std::string_view column) {
  const double v0 = r.impact_velocity_m_s;
  std::size_t worst = 0;
  double excess = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < r.time_s.size(); ++k) {
    const double e = r.velocity_m_s[k] - v0 - g * (r.time_s[k] - r.impact_time_s);
    if (e > excess) {
      excess = e;
      worst = k;
    }
  }
  if (excess > kExcessTolerance * v0)
    throw RecordError(formatted(
        "at t = %.6g s the body moves down at %.4g m/s, %.3g m/s faster than free fall from the impact (%.4g m/s at "
        "t = %.6g s) allows: only a downward force beyond its weight could do that; %s's sign or zero offset is wrong",
        r.time_s[worst], r.velocity_m_s[worst], excess, v0, r.impact_time_s, std::string(column).c_str()));
}

/// The energy bound on a rebound: ½ v_up² ≤ ½ v0² + g z_max (all the kinetic energy of the impact
/// and all the potential energy of the penetration given back).
void refuse_rebound_beyond_energy(const InterpretedRecord& r, double g, double v_min, std::string_view column) {
  const double v0 = r.impact_velocity_m_s;
  const double allowed = std::sqrt(v0 * v0 + 2.0 * g * std::max(r.max_penetration_m, 0.0));
  if (-v_min > (1.0 + kExcessTolerance) * allowed)
    throw RecordError(formatted(
        "the body rises at %.4g m/s, faster than the %.4g m/s all the energy of its impact (%.4g m/s, %.4g m deep) "
        "could give back: %s's zero offset or sign is wrong",
        -v_min, allowed, v0, r.max_penetration_m, std::string(column).c_str()));
}

}  // namespace

double largest_credible_deceleration_g(const std::vector<double>& t, const RecordSettings& s) {
  return credible_bound(t, s).deceleration_g;
}

void check_deceleration_bound(const std::vector<double>& t, const std::vector<double>& d, std::string_view column,
                              const RecordSettings& s) {
  const CredibleBound bound = credible_bound(t, s);
  for (std::size_t k = 0; k < d.size(); ++k)
    if (!(std::abs(d[k]) <= bound.deceleration_g))
      throw RecordError(formatted(
          "column '%s', data row %zu (time_s = %.9g): a net deceleration of %.4g g is beyond the ±%.3g g a rigid "
          "penetrometer can read: held over one sampling interval (%.3g s) it would change the velocity by more than "
          "a full reversal of the fastest the body can move (%.3g m/s: the impact velocity plus free fall over the "
          "record)",
          std::string(column).c_str(), k + 1, t[k], d[k], bound.deceleration_g, bound.interval_s, bound.fastest_m_s));
}

std::vector<std::string> check_impact_kinematics(const InterpretedRecord& r, double g, std::string_view column) {
  const double v0 = r.impact_velocity_m_s;
  if (!(v0 > 0.0))
    throw RecordError(formatted(
        "integrated from rest at the first sample, the body moves at %.4g m/s (+ down) at the impact (t = %.6g s): a "
        "drop meets the soil falling. Either the record does not start at release (give impact_velocity_m_s) or %s "
        "has the wrong sign (in free fall the net deceleration reads −1 g, the sensor 0)",
        v0, r.impact_time_s, std::string(column).c_str()));
  const auto [lowest, highest] = std::minmax_element(r.velocity_m_s.begin(), r.velocity_m_s.end());
  const double v_min = *lowest, v_max = *highest, v_end = r.velocity_m_s.back();
  if (v_min > (1.0 - kLeastSlowing) * v0) refuse_never_slowing(r, column, v_min, v_end);
  refuse_faster_than_free_fall(r, g, column);
  refuse_rebound_beyond_energy(r, g, v_min, column);

  std::vector<std::string> warnings;
  if (v_max > (1.0 + kRiseWarning) * v0)
    warnings.push_back(formatted(
        "the velocity rises to %.4g m/s after the impact, %.0f%% above the impact velocity %.4g m/s: the soil held "
        "less than the body's weight for at least %.3g s (is the impact time too early?)",
        v_max, 100.0 * (v_max / v0 - 1.0), v0, (v_max - v0) / g));
  if (v_end > kRiseWarning * v0)
    warnings.push_back(formatted(
        "the record ends at t = %.6g s with the body still moving down at %.4g m/s (%.0f%% of the impact velocity): "
        "it stops deeper than final_penetration_m",
        r.time_s.back(), v_end, 100.0 * v_end / v0));
  return warnings;
}

}  // namespace ffp
