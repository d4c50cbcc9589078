#include "drivers/ffp_record.hpp"
#include "drivers/record_plausibility.hpp"
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

/// The first sample at or after the given impact time (to round-off). The impact must lie within the
/// record and leave at least one sample after it: a time outside is no impact the record holds.
std::size_t sample_at_impact_time(const std::vector<double>& t, double impact_time_s) {
  const double slack = 1e-12 * std::max(1.0, std::abs(impact_time_s));
  auto refuse = [&](const char* why) {
    char message[200];
    std::snprintf(message, sizeof message, "impact_time_s = %.9g s %s: the record runs from %.9g s to %.9g s",
                  impact_time_s, why, t.front(), t.back());
    throw RecordError(message);
  };
  if (impact_time_s < t.front() - slack || impact_time_s > t.back() + slack) refuse("is outside the record");
  const auto at = std::lower_bound(t.begin(), t.end(), impact_time_s - slack);
  if (at + 1 == t.end()) refuse("leaves no sample after the impact");
  return static_cast<std::size_t>(at - t.begin());
}

}  // namespace

// The rate laws as the FFP literature states them. Only the log law's source could be read
// (Zambrano-Cruzatty & Yerro 2020, "Numerical simulation of a free fall penetrometer deployment using
// the material point method", Soils and Foundations: eq. 6); for the others the original papers were
// not found, so the forms are those of BlueDrop_Analysis_Lib
// (lib/mechanics_functions/bearing_capacity_funcs.py, calc_qs_bearing_capacity), with the sources it
// names and no equation number. q_dyn and q_sbc share the contact area, so q_dyn/q_sbc = F_dyn/F_0.
double strain_rate_factor(const RateCorrection& c, double v, double v_ref, double v_impact) {
  // f = 1 at or below v_ref, where the logarithm would fall below 1 and then below 0. For the asinh
  // law, which is regular down to v = 0, this is a jump of (K/ln 10)·asinh(1) = 0.383 K at v_ref
  // (BlueDrop applies it at every velocity); kept so that existing interpretations do not change.
  if (!(v > v_ref)) return 1.0;
  switch (c.law) {
    case RateLaw::logarithmic:
      // Zambrano-Cruzatty & Yerro (2020) eq. 6, F_dyn = F_0 (1 + K log(v/v_ref)), v_ref = 2 cm/s (the CPT
      // rate), after Albatal (2018); log is log10, as the K values quoted with it (0.2–1.5: Stoll et al.
      // 2007, Stark et al. 2012, Albatal 2018; ≈ 0.75 in their own runs) assume. Dayal & Allen (1975,
      // Can. Geotech. J. 12(3)) found the dynamic/static strength ratio linear in log(v/v_static) for
      // clays, 0.13 to 550 cm/s, and no significant rate effect in sands (abstract; equation not seen).
      return 1.0 + c.k * std::log10(v / v_ref);
    case RateLaw::brilli:
      // Brilli et al. as BlueDrop_Analysis_Lib cites it ("2023" in one version, "20??" in another; the
      // paper was not found): f = 1 + K v_max log10(v/v_ref), K = 0.31 s/m for air drops. v_max is the
      // impact velocity here; BlueDrop takes the largest velocity of the impulse (higher by the rise
      // after first contact).
      return 1.0 + c.k * v_impact * std::log10(v / v_ref);
    case RateLaw::inverse_hyperbolic_sine:
      // Randolph & Hope (2004), Stephan (2015), as BlueDrop_Analysis_Lib cites them (papers not found):
      // f = 1 + (K/ln 10) asinh(v/v_ref). For v ≫ v_ref, asinh x → ln 2x: f → 1 + K log10(2v/v_ref).
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
    const double bottom = d.empty() ? 0.0 : *std::min_element(d.begin(), d.end());
    char buffer[400];
    const int length = std::snprintf(
        buffer, sizeof buffer,
        "no impact found: the net deceleration never exceeds impact_threshold_g = %g (its maximum is %.4g g); "
        "give a lower impact_threshold_g or the impact_time_s",
        threshold_g, top);
    // An impact pulse read upside down sinks far below free fall's −1 g, where no free body goes.
    if (bottom < kWrongSignBelow_g && length > 0 && static_cast<std::size_t>(length) < sizeof buffer)
      std::snprintf(buffer + length, sizeof buffer - static_cast<std::size_t>(length),
                    ". Its minimum, %.4g g, lies far below free fall's −1 g: if the channel has the wrong sign, "
                    "negate the column",
                    bottom);
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
    out.impact_index = sample_at_impact_time(t, *s.impact_time_s);
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
    // Soil bearing force: the rigid body's balance M a = M g − F (Zambrano-Cruzatty & Yerro 2020 eq. 1,
    // no external load), a = −g·d down, gives F = M g (1 + d); the buoyancy ρ V g and drag ½ ρ C_D A v²
    // of a drop through water or air are BlueDrop_Analysis_Lib's (calc_water_drop_dyn_bearing; the
    // source it follows is not named): F = m a + m g − ρ V g − ½ ρ C_D A v², a = g·d up.
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
