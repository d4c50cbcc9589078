#pragma once
/// What can be a free-fall penetrometer's impact, and what cannot. A record is
/// refused (RecordError) where no rigid body falling onto soil can produce it,
/// and flagged (a warning, a short sentence) where one could but seldom does.
/// Every bound comes from the mechanics of the drop, not from a sensor's data
/// sheet: the body is rigid, nothing pushes it down but its weight, and the
/// soil gives back no more energy than it received.
///
/// The velocity scale of every test is the impact velocity v0. Noise in a
/// record moves the integrated velocity by far less: on the synthetic reference
/// record (data/records/: noise σ of 1 % of its 17.7 g peak on every row, 750
/// rows 0.19 ms apart) the random walk is σ g Δt √N = 0.175 × 9.81 × 1.9e-4 ×
/// √750 = 0.009 m/s, 0.16 % of its 5.6 m/s.
#include <string>
#include <string_view>
#include <vector>

#include "drivers/ffp_record.hpp"

namespace ffp {

/// The largest net deceleration (g) one sample of a record can hold. The
/// trapezoid integration treats a sample as held over about one sampling
/// interval Δt (the median), in which it changes the velocity by g·d·Δt. The
/// body's speed never exceeds V = v0 + g·T (its impact speed, or 0 when it is
/// integrated from release, plus free fall over the whole record of length T),
/// and the largest change within one interval is a full reversal, 2V:
///   |d| ≤ 2V / (g Δt).
/// For the reference record (5.6 m/s, 0.15 s, Δt = 0.19 ms) that is 7.7e3 g,
/// 430 times its 17.7 g peak: only a sample no impact can produce exceeds it.
double largest_credible_deceleration_g(const std::vector<double>& time_s, const RecordSettings& settings);

/// Refuses a sample beyond largest_credible_deceleration_g, naming the column,
/// the data row and the bound (1e308 g, say, would overflow the integration).
void check_deceleration_bound(const std::vector<double>& time_s, const std::vector<double>& deceleration_g,
                              std::string_view column, const RecordSettings& settings);

/// Refuses kinematics no impact produces and returns warnings for unlikely
/// ones. `column` is the channel the deceleration came from (its name goes
/// into the advice). Refused:
///  - an impact velocity ≤ 0 integrated from release (the body would not be falling);
///  - a body that never slows by kLeastSlowing of v0 after the impact; when its
///    net deceleration also falls below kWrongSignBelow_g, the channel's sign is wrong;
///  - a velocity above free fall from the impact by more than kExcessTolerance of v0
///    (a downward force beyond the body's weight);
///  - an upward speed above √(v0² + 2 g z_max) by more than kExcessTolerance
///    (the soil gave back more energy than the impact brought).
/// Flagged: a velocity above v0 by more than kRiseWarning of v0, and a record
/// that ends with the body still moving down at more than kRiseWarning of v0.
std::vector<std::string> check_impact_kinematics(const InterpretedRecord& record, double gravity_m_s2,
                                                 std::string_view column);

/// A penetrometer that meets soil loses its velocity; one that never loses 1 %
/// of it never met any (noise moves it by 0.16 %, above).
inline constexpr double kLeastSlowing = 0.01;
/// A net deceleration below −2 g after impact means something besides gravity
/// pushes the body down with more than its weight, which a free body does not
/// get; with a body that never slows it is the impact pulse read upside down.
/// Noise of a record in free fall (−1 g) stays far from it (σ = 0.18 g above).
inline constexpr double kWrongSignBelow_g = -2.0;
/// Allowance on the free-fall and energy bounds: 30 times the noise drift above.
inline constexpr double kExcessTolerance = 0.05;
/// A cone's bearing force passes the body's weight within the first
/// centimetres (7.71 kg on 100 kPa needs r = 1.6 cm of the 4.4 cm base: 2.7 cm
/// of a 60° cone, 4.8 ms at 5.6 m/s, a velocity gain of 0.8 %). A gain of 10 %
/// (57 ms of unresisted fall at 5.6 m/s, about the whole reference penetration)
/// suggests an impact time set too early.
inline constexpr double kRiseWarning = 0.10;

}  // namespace ffp
