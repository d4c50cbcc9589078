/// The batched, bounded least-squares fit behind the `inverse` kind, on models
/// with closed-form answers.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "calibration/bounded_least_squares.hpp"

using namespace ffp;

namespace {

std::vector<double> noise(std::size_t n, double sigma, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> e(n);
  for (double& v : e) v = normal(engine);
  return e;
}

}  // namespace

TEST_CASE("a straight-line fit gives the ordinary least-squares values and standard errors", "[inverse]") {
  // A linear model: the forward differences are exact, so the fit is OLS and its errors are
  // se_b = s/√Sxx, se_a = s √(1/n + t̄²/Sxx), s² = Σr²/(n − 2).
  const std::size_t n = 30;
  std::vector<double> t(n), y(n);
  const auto e = noise(n, 0.05, 7);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 0.1 * static_cast<double>(i);
    y[i] = 1.5 + 0.8 * t[i] + e[i];
  }
  std::size_t largest_batch = 0;
  const BatchEvaluator line = [&](const std::vector<std::vector<double>>& points) {
    largest_batch = std::max(largest_batch, points.size());
    std::vector<std::vector<double>> out;
    for (const auto& x : points) {
      std::vector<double> r(n);
      for (std::size_t i = 0; i < n; ++i) r[i] = x[0] + x[1] * t[i] - y[i];
      out.push_back(r);
    }
    return out;
  };
  // Tolerances at round-off: Levenberg–Marquardt's damped steps approach the OLS point over a few
  // iterations, and the defaults (1e-4, for noisy MPM misfits) stop earlier.
  const BoundedFitSettings tight{50, 1e-15, 1e-15};
  const BoundedFit fit = fit_bounded_least_squares({{"a", 0.0, -10.0, 10.0, 0.01}, {"b", 0.0, -10.0, 10.0, 0.01}},
                                                   static_cast<int>(n), line, tight);
  double t_mean = 0.0, y_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) t_mean += t[i] / n, y_mean += y[i] / n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    sxx += (t[i] - t_mean) * (t[i] - t_mean), sxy += (t[i] - t_mean) * (y[i] - y_mean);
  const double b = sxy / sxx, a = y_mean - b * t_mean;
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) ssr += std::pow(a + b * t[i] - y[i], 2);
  const double s = std::sqrt(ssr / (n - 2));
  CHECK(fit.values[0] == Approx(a).epsilon(1e-8));
  CHECK(fit.values[1] == Approx(b).epsilon(1e-8));
  REQUIRE(fit.standard_errors[0]);
  CHECK(*fit.standard_errors[0] == Approx(s * std::sqrt(1.0 / n + t_mean * t_mean / sxx)).epsilon(1e-6));
  CHECK(*fit.standard_errors[1] == Approx(s / std::sqrt(sxx)).epsilon(1e-6));
  CHECK(fit.correlation[0][1] < 0.0);  // intercept and slope trade off for t > 0
  CHECK(largest_batch == 3);           // the point and its two neighbours, handed over together
  CHECK(fit.final_cost == Approx(0.5 * ssr).epsilon(1e-8));
}

TEST_CASE("a nonlinear fit within bounds finds the true parameters within two standard errors", "[inverse]") {
  const std::size_t n = 40;
  const auto e = noise(n, 0.01, 11);
  std::vector<double> t(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 0.05 * static_cast<double>(i);
    y[i] = 2.0 * std::exp(-1.3 * t[i]) * (1.0 + e[i]);  // 1 % noise
  }
  const BatchEvaluator decay = [&](const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> out;
    for (const auto& x : points) {
      std::vector<double> r(n);
      for (std::size_t i = 0; i < n; ++i) r[i] = x[0] * std::exp(-x[1] * t[i]) - y[i];
      out.push_back(r);
    }
    return out;
  };
  const BoundedFit fit = fit_bounded_least_squares({{"amplitude", 1.0, 0.5, 5.0, 1e-4}, {"rate", 0.5, 0.1, 3.0, 1e-4}},
                                                   static_cast<int>(n), decay);
  INFO(fit.termination);
  CHECK(fit.converged);
  REQUIRE(fit.standard_errors[1]);
  CHECK(std::abs(fit.values[0] - 2.0) < 2.0 * *fit.standard_errors[0]);
  CHECK(std::abs(fit.values[1] - 1.3) < 2.0 * *fit.standard_errors[1]);
  CHECK(fit.final_cost < fit.initial_cost);
}

TEST_CASE("a bound holds the fit and a failing model point is stepped around", "[inverse]") {
  // The minimum of (x − 3)² lies beyond the upper bound 2: the fit stops on the bound. Points
  // above 1.9 fail (as an MPM run might), except the bound itself and its neighbour below.
  int failures = 0;
  const BatchEvaluator model = [&](const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> out;
    for (const auto& x : points) {
      if (x[0] > 1.9 && x[0] < 1.99) {
        ++failures;
        out.emplace_back();
      } else {
        out.push_back({x[0] - 3.0});
      }
    }
    return out;
  };
  const BoundedFit fit = fit_bounded_least_squares({{"x", 0.0, -2.0, 2.0, 0.005}}, 1, model);
  CHECK(fit.values[0] == Approx(2.0).margin(0.02));
  CHECK_FALSE(fit.standard_errors[0]);  // one residual, one parameter: nothing left to estimate the noise
  CHECK_THROWS_WITH(fit_bounded_least_squares({{"x", 3.0, -2.0, 2.0, 0.1}}, 1, model), Catch::Contains("outside"));
}

TEST_CASE("what the model throws mid-fit stops the fit and comes out as it was thrown", "[inverse]") {
  // An interrupt in the middle of a fit (the evaluator's third batch) must reach the program
  // as that interrupt, not as a failed model or a fit that "converged".
  struct Stop {};
  int batches = 0;
  const BatchEvaluator model = [&](const std::vector<std::vector<double>>& points) {
    if (++batches == 3) throw Stop{};
    std::vector<std::vector<double>> out;
    for (const auto& x : points) out.push_back({x[0] - 1.5, 0.1 * (x[0] - 1.5)});
    return out;
  };
  CHECK_THROWS_AS(fit_bounded_least_squares({{"x", -1.0, -2.0, 2.0, 0.01}}, 2, model), Stop);
  CHECK(batches == 3);  // stopped at the throw: no further batch was asked for
}

TEST_CASE("the Jacobian at the solution holds each parameter's effect, zero for one the model ignores", "[inverse]") {
  // r_i = a·t_i − y_i does not depend on b: its column is exactly zero, a's is t_i.
  const std::vector<double> t = {1.0, 2.0, 3.0};
  const BatchEvaluator model = [&](const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> out;
    for (const auto& x : points) out.push_back({x[0] * t[0] - 2.0, x[0] * t[1] - 4.0, x[0] * t[2] - 6.0});
    return out;
  };
  const BoundedFit fit = fit_bounded_least_squares({{"a", 1.0, 0.0, 5.0, 0.01}, {"b", 1.0, 0.0, 5.0, 0.01}}, 3, model);
  REQUIRE(fit.jacobian.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    REQUIRE(fit.jacobian[i].size() == 2);
    CHECK(fit.jacobian[i][0] == Approx(t[i]).epsilon(1e-9));  // linear: the forward difference is exact
    CHECK(fit.jacobian[i][1] == 0.0);
  }
  CHECK_FALSE(fit.standard_errors[1]);  // JᵀJ is singular: b is not identifiable
}
