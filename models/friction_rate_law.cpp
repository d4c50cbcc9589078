#include "models/friction_rate_law.hpp"

#include <algorithm>
#include <cmath>

namespace ffp {

double FrictionRateLaw::peak_friction_rad(double reference_peak_rad, double strain_rate_per_s) const {
  if (alpha_phi == 0.0 || !(strain_rate_per_s > reference_strain_rate_per_s)) return reference_peak_rad;
  const double raised =
      reference_peak_rad * (1.0 + alpha_phi * std::log10(strain_rate_per_s / reference_strain_rate_per_s));
  return std::min(raised, std::max(max_friction_angle_rad, reference_peak_rad));
}

double FrictionRateLaw::smoothed_rate(double previous_smoothed_per_s, double newest_per_s) const {
  const double weight = 2.0 / (static_cast<double>(std::max(smoothing_increments, 1)) + 1.0);
  return weight * newest_per_s + (1.0 - weight) * previous_smoothed_per_s;
}

}  // namespace ffp
