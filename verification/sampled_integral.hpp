#pragma once
/// ∫ f dt over [t0, t1] of a history sampled at `time` (trapezoids; a row interval cut by t0 or t1
/// counts its part inside): the impulse integrals the wave verifications read their arrivals and
/// jumps from.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace ffp {

/// f(j) is the integrand at row j.
template <class F>
double sampled_integral(const std::vector<double>& time, double t0, double t1, F&& f) {
  double sum = 0.0;
  for (std::size_t j = 1; j < time.size(); ++j) {
    const double a = std::max(time[j - 1], t0), b = std::min(time[j], t1);
    if (b > a) sum += 0.5 * (f(j - 1) + f(j)) * (b - a);
  }
  return sum;
}

}  // namespace ffp
