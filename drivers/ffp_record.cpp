#include "drivers/ffp_record.hpp"
#include "models/math_constants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ffp {

namespace {

std::string row_name(std::size_t index, const std::vector<double>& time_s) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "data row %zu (time_s = %.9g)", index + 1, time_s[index]);
  return buffer;
}

}  // namespace

// The three forms as BlueDrop_Analysis_Lib (stevADUS) implements them, with
// the sources it names; the original papers were not at hand to check them.
double strain_rate_factor(const RateCorrection& c, double v, double v_ref, double v_impact) {
  if (!(v > v_ref)) return 1.0;
  switch (c.law) {
    case RateLaw::logarithmic:  // Dayal & Allen (1975): f = 1 + K log10(v/v_ref)
      return 1.0 + c.k * std::log10(v / v_ref);
    case RateLaw::brilli:  // Brilli et al.: f = 1 + K v_max log10(v/v_ref), K = 0.31 s/m for air drops
      return 1.0 + c.k * v_impact * std::log10(v / v_ref);
    case RateLaw::inverse_hyperbolic_sine:  // Randolph & Hope (2004), Stephan (2015): f = 1 + (K/ln 10) asinh(v/v_ref)
      return 1.0 + c.k / std::numbers::ln10 * std::asinh(v / v_ref);
  }
  return 1.0;
}

double TipAreas::projected_m2(double depth_m) const {
  if (depth_m <= 0.0) return 0.0;
  const double r =
      cone_height_m > 0.0 ? base_radius_m * std::min(depth_m, cone_height_m) / cone_height_m : base_radius_m;
  return kPi * r * r;
}

double TipAreas::mantle_m2(double depth_m) const {
  if (depth_m <= 0.0) return 0.0;
  if (cone_height_m <= 0.0) return kPi * base_radius_m * base_radius_m;
  const double z = std::min(depth_m, cone_height_m);
  const double r = base_radius_m * z / cone_height_m;
  return kPi * r * std::hypot(r, z);  // lateral area of a cone of radius r and height z
}

void check_record_channel(const std::vector<double>& t, const std::vector<double>& v, std::string_view column,
                          std::optional<double> full_scale, double max_gap_ratio) {
  const std::string col(column);
  if (t.size() < 3) throw RecordError("the record has " + std::to_string(t.size()) + " rows: at least 3 are needed");
  std::vector<double> steps;
  steps.reserve(t.size() - 1);
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (!(t[k] > t[k - 1]))
      throw RecordError("column 'time_s', " + row_name(k, t) + ": time must increase (the row before has " +
                        std::to_string(t[k - 1]) + ")");
    steps.push_back(t[k] - t[k - 1]);
  }
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k] > max_gap_ratio * median) {
      char buffer[160];
      std::snprintf(buffer, sizeof buffer,
                    ": a gap of %.3g s after the row before, %.3g times the median sampling interval %.3g s", steps[k],
                    steps[k] / median, median);
      throw RecordError("column 'time_s', " + row_name(k + 1, t) + buffer);
    }
  if (full_scale) {
    for (std::size_t k = 0; k < v.size(); ++k)
      if (std::abs(v[k]) >= *full_scale)
        throw RecordError("column '" + col + "', " + row_name(k, t) + ": " + std::to_string(v[k]) +
                          " is at the sensor's full scale ±" + std::to_string(*full_scale) +
                          " (sensor_range): the channel is saturated, its peak unknown");
    return;
  }
  // A clipped channel holds its top value: a run of equal samples at the maximum inside a pulse.
  const double top = *std::max_element(v.begin(), v.end());
  constexpr std::size_t kFlatTop = 5;
  for (std::size_t k = 0; k < v.size();) {
    if (v[k] != top) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < v.size() && v[end] == top) ++end;
    if (end - k >= kFlatTop && k > 0 && end < v.size())
      throw RecordError(
          "column '" + col + "', " + row_name(k, t) + ": " + std::to_string(end - k) +
          " equal samples at the record's maximum " + std::to_string(top) +
          ": the channel looks saturated (give sensor_range_g or sensor_range_m_s2 for the true full scale)");
    k = end;
  }
}

std::size_t detect_impact(const std::vector<double>& d, double threshold_g) {
  const auto first = std::find_if(d.begin(), d.end(), [&](double x) { return x > threshold_g; });
  if (first == d.end()) {
    const double top = d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
    char buffer[200];
    std::snprintf(
        buffer, sizeof buffer,
        "no impact found: the net deceleration never exceeds impact_threshold_g = %g (its maximum is %.4g g); "
        "give a lower impact_threshold_g or the impact_time_s",
        threshold_g, top);
    throw RecordError(buffer);
  }
  // Back to where the pulse begins to rise: before it the body falls (−1 g) or rests (0 g).
  std::size_t k = static_cast<std::size_t>(first - d.begin());
  while (k > 0 && d[k - 1] < d[k]) --k;
  return k;
}

InterpretedRecord interpret_record(const std::vector<double>& t, const std::vector<double>& d,
                                   const RecordSettings& s) {
  InterpretedRecord out;
  const double g = s.gravity_m_s2, M = s.mass_kg;
  if (s.impact_time_s) {
    const auto at =
        std::lower_bound(t.begin(), t.end(), *s.impact_time_s - 1e-12 * std::max(1.0, std::abs(*s.impact_time_s)));
    if (at == t.end() || at + 1 == t.end())
      throw RecordError("impact_time_s = " + std::to_string(*s.impact_time_s) +
                        " is at or after the record's last sample (" + std::to_string(t.back()) + " s)");
    out.impact_index = static_cast<std::size_t>(at - t.begin());
    out.impact_detected = false;
  } else {
    out.impact_index = detect_impact(d, s.impact_threshold_g);
    if (out.impact_index + 1 >= t.size())
      throw RecordError("the impact is at the record's last sample: nothing to interpret");
  }
  const std::size_t k0 = out.impact_index;
  out.impact_time_s = t[k0];
  // Kinematics by the cumulative trapezoid, as BlueDrop_Analysis_Lib's impulse integration:
  // dv/dt = −g·d (d the net deceleration, + slowing), dz/dt = v.
  double v = 0.0;
  if (s.impact_velocity_m_s) {
    v = *s.impact_velocity_m_s;
  } else {
    out.impact_velocity_integrated = true;  // released from rest at the first sample
    for (std::size_t k = 1; k <= k0; ++k) v -= g * 0.5 * (d[k] + d[k - 1]) * (t[k] - t[k - 1]);
  }
  out.impact_velocity_m_s = v;
  const double frontal_m2 = kPi * s.tip.base_radius_m * s.tip.base_radius_m;
  const double buoyancy_N = s.medium == DropMedium::water ? s.fluid_density_kg_m3 * s.volume_m3 * g : 0.0;
  out.q_sbc_kPa.assign(s.rate_laws.size(), {});
  double z = 0.0;
  out.peak_deceleration_g = -std::numeric_limits<double>::infinity();
  for (std::size_t k = k0 + 1; k < t.size(); ++k) {
    const double dt = t[k] - t[k - 1];
    const double v_next = v - g * 0.5 * (d[k] + d[k - 1]) * dt;
    z += 0.5 * (v + v_next) * dt;
    v = v_next;
    // Soil bearing force (BlueDrop's air/water drop): F = m a + m g − ρ V g − ½ ρ C_D A v², a = g·d up.
    const double force_N =
        M * g * (d[k] + 1.0) - buoyancy_N - 0.5 * s.fluid_density_kg_m3 * s.drag_coefficient * frontal_m2 * v * v;
    const double projected = s.tip.projected_m2(z), mantle = s.tip.mantle_m2(z);
    // q_dyn = F / A_contact; at a contact area of zero (the body back out of the soil) q is 0.
    const double q_projected = projected > 0.0 ? 1e-3 * force_N / projected : 0.0;
    const double q_mantle = mantle > 0.0 ? 1e-3 * force_N / mantle : 0.0;
    out.time_s.push_back(t[k]);
    out.penetration_m.push_back(z);
    out.velocity_m_s.push_back(v);
    out.deceleration_g.push_back(d[k]);
    out.q_dyn_projected_kPa.push_back(q_projected);
    out.q_dyn_mantle_kPa.push_back(q_mantle);
    const double q_base = s.q_sbc_on_mantle ? q_mantle : q_projected;
    for (std::size_t law = 0; law < s.rate_laws.size(); ++law)
      out.q_sbc_kPa[law].push_back(
          q_base / strain_rate_factor(s.rate_laws[law], v, s.reference_velocity_m_s, out.impact_velocity_m_s));
    if (d[k] > out.peak_deceleration_g) {
      out.peak_deceleration_g = d[k];
      out.time_of_peak_s = t[k];
      out.depth_of_peak_m = z;
    }
    out.max_penetration_m = std::max(out.max_penetration_m, z);
  }
  out.final_penetration_m = z;
  return out;
}

}  // namespace ffp
