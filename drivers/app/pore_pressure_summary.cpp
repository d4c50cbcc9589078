#include "drivers/app/pore_pressure_summary.hpp"

#include <cmath>
#include <cstdio>

namespace ffp {

ShoulderPressureFigures shoulder_pressure_figures(std::span<const ShoulderPressureRow> rows) {
  ShoulderPressureFigures f;
  std::size_t peak = 0, low = 0, rest = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    if (rows[k].u2_kPa > rows[peak].u2_kPa) peak = k;
    if (rows[k].u2_kPa < rows[low].u2_kPa) low = k;
    if (rest == 0 && rows[k].velocity_m_s <= 0.0) rest = k;
  }
  f.peak_kPa = rows[peak].u2_kPa;
  f.time_of_peak_s = rows[peak].time_s;
  f.min_kPa = rows[low].u2_kPa;
  f.time_of_min_s = rows[low].time_s;
  if (rest == 0) {
    f.dissipation_note = "the body still moves down at the end of the run";
    return f;
  }
  f.rest_time_s = rows[rest].time_s;
  const double at_rest = rows[rest].u2_excess_kPa;
  f.excess_at_rest_kPa = at_rest;
  if (at_rest == 0.0) {
    f.dissipation_note = "u2 has no excess pore pressure when the body comes to rest";
    return f;
  }
  for (std::size_t k = rest; k < rows.size(); ++k) {
    if (std::abs(rows[k].u2_excess_kPa) <= 0.1 * std::abs(at_rest)) {
      f.dissipation_time_s = rows[k].time_s - rows[rest].time_s;
      return f;
    }
  }
  char note[160];
  std::snprintf(note, sizeof note,
                "u2's excess is still %.0f %% of its value at rest (%.3g kPa) at the end of the run, %.3g s after it",
                100.0 * std::abs(rows.back().u2_excess_kPa / at_rest), at_rest, rows.back().time_s - rows[rest].time_s);
  f.dissipation_note = note;
  return f;
}

}  // namespace ffp
