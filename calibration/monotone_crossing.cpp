#include "calibration/monotone_crossing.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace ffp {

namespace {

double sign(double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; }

/// Fritsch–Carlson slopes d_k: 0 at a local extremum of the data, else the
/// weighted harmonic mean of the neighbouring secants δ (weights 2h_k + h_k−1,
/// h_k + 2h_k−1); at the ends the three-point formula, limited to keep the
/// interpolant monotone (0 against δ's sign, 3δ where the secants change sign).
std::vector<double> pchip_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), delta(n - 1), d(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    delta[k] = (y[k + 1] - y[k]) / h[k];
  }
  if (n == 2) return {delta[0], delta[0]};
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (delta[k - 1] * delta[k] <= 0.0) continue;
    const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
    d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
  }
  auto end_slope = [](double h0, double h1, double d0, double d1) {
    const double s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (sign(s) != sign(d0)) return 0.0;
    if (sign(d0) != sign(d1) && std::abs(s) > std::abs(3.0 * d0)) return 3.0 * d0;
    return s;
  };
  d.front() = end_slope(h[0], h[1], delta[0], delta[1]);
  d.back() = end_slope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  return d;
}

}  // namespace

double monotone_crossing(const std::vector<double>& x, const std::vector<double>& y, double level) {
  if (x.size() < 2 || y.size() != x.size())
    throw std::invalid_argument("monotone_crossing: needs ≥ 2 points, as many y as x");
  for (std::size_t k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1])) throw std::invalid_argument("monotone_crossing: x must increase strictly");
  const std::vector<double> d = pchip_slopes(x, y);
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double fa = y[k] - level, fb = y[k + 1] - level;
    if (fa * fb > 0.0) continue;
    if (fa == 0.0) return x[k];
    if (fb == 0.0) return x[k + 1];
    // The Hermite cubic on [x_k, x_k+1], t ∈ [0, 1]; bisection keeps the bracket
    // (the cubic is monotone here when the data are, and straddles the level anyway).
    const double h = x[k + 1] - x[k];
    auto f = [&](double t) {
      const double t2 = t * t, t3 = t2 * t;
      return (2 * t3 - 3 * t2 + 1) * y[k] + (t3 - 2 * t2 + t) * h * d[k] + (-2 * t3 + 3 * t2) * y[k + 1] +
             (t3 - t2) * h * d[k + 1] - level;
    };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      if ((f(mid) > 0.0) == (fa > 0.0))
        lo = mid;
      else
        hi = mid;
    }
    return x[k] + 0.5 * (lo + hi) * h;
  }
  throw std::invalid_argument("monotone_crossing: no interval straddles the level");
}

}  // namespace ffp
