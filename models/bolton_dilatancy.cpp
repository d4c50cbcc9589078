#include "models/bolton_dilatancy.hpp"

#include <algorithm>
#include <cmath>

namespace ffp {

double bolton_dilatancy_index(double relative_density, double mean_pressure_kPa) {
  constexpr double kMaxIndex = 4.0;         // Bolton (1986): I_R ≤ 4
  if (relative_density <= 0.0) return 0.0;  // I_R = −1 before clamping, whatever p' is
  if (!(mean_pressure_kPa > 0.0)) return kMaxIndex;
  // Paper eq. 5 (Bolton 1986 with Q = 10, R = 1).
  const double index = relative_density * (10.0 - std::log(mean_pressure_kPa)) - 1.0;
  return std::clamp(index, 0.0, kMaxIndex);
}

double bolton_peak_dilatancy_rad(double relative_density, double mean_pressure_kPa) {
  // Paper eq. 4: D_max = 0.3 I_R is a proxy for tan ψ_max (Fern et al. 2016).
  return std::atan(0.3 * bolton_dilatancy_index(relative_density, mean_pressure_kPa));
}

}  // namespace ffp
