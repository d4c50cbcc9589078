#pragma once
/// The summary figures of the shoulder pore pressure u2 of an `ffp` run on a saturated sand
/// (mpm/cone_pore_pressure.hpp), as pure functions of its history rows: no I/O, no MPM.
#include <optional>
#include <span>
#include <string>

namespace ffp {

/// One history row: time, the body's downward velocity, u2 and its excess over hydrostatic.
struct ShoulderPressureRow {
  double time_s = 0.0;
  double velocity_m_s = 0.0;  ///< + down
  double u2_kPa = 0.0, u2_excess_kPa = 0.0;
};

struct ShoulderPressureFigures {
  double peak_kPa = 0.0, time_of_peak_s = 0.0;  ///< the largest u2 (the first row reaching it)
  double min_kPa = 0.0, time_of_min_s = 0.0;    ///< the smallest
  /// The body comes to rest at the first row (after the first) whose downward velocity is ≤ 0: the
  /// end of its downward motion. None when it still moves down at the last row.
  std::optional<double> rest_time_s;
  double excess_at_rest_kPa = 0.0;
  /// The time from the rest until |u2's excess| first falls to 10 % of its value at rest; none,
  /// with the reason in `dissipation_note`, when the body does not come to rest, has no excess
  /// then, or the excess stays above 10 % to the last row.
  std::optional<double> dissipation_time_s;
  std::string dissipation_note;
};

/// The figures of a run's rows (not empty, ascending in time).
ShoulderPressureFigures shoulder_pressure_figures(std::span<const ShoulderPressureRow> rows);

}  // namespace ffp
