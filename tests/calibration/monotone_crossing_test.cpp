/// The fit's start from the scan (calibration/monotone_crossing.hpp).
#include <cmath>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "calibration/monotone_crossing.hpp"

using namespace ffp;

TEST_CASE("monotone crossing: exact on a straight line, at a sample, and refused without a bracket",
          "[calibration][start]") {
  const std::vector<double> x = {0.0, 1.0, 3.0, 4.0};
  const std::vector<double> line = {5.0, 3.0, -1.0, -3.0};  // y = 5 − 2x: every slope is −2
  CHECK(monotone_crossing(x, line, 0.0) == Approx(2.5).epsilon(1e-12));
  CHECK(monotone_crossing(x, line, 3.0) == 1.0);
  CHECK(monotone_crossing({0.0, 1.0}, {1.0, 0.0}, 0.25) == Approx(0.75).epsilon(1e-12));
  CHECK_THROWS_AS(monotone_crossing(x, line, 6.0), std::invalid_argument);
  CHECK_THROWS_AS(monotone_crossing({0.0, 0.0}, {1.0, 0.0}, 0.5), std::invalid_argument);
}

TEST_CASE("monotone crossing: on a saturating decrease it lands far nearer than the chord", "[calibration][start]") {
  // W(x) = 0.45 + 0.5/(1 + e^(x − 1)), x = ln η, sampled as the meshed scan is (η = 0.1,
  // 2.5, 7.07, 15, 500): it bends like the 2 cm specimen's W (0.93 … 0.46 J).
  auto w = [](double x) { return 0.45 + 0.5 / (1.0 + std::exp(x - 1.0)); };
  std::vector<double> x, y;
  for (double eta : {0.1, 2.5, 7.0710678, 15.0, 500.0}) {
    x.push_back(std::log(eta));
    y.push_back(w(std::log(eta)));
  }
  const double root = 4.2;  // η ≈ 67: between the scan's 15 and 500
  const double level = w(root);
  const double chord = x[3] + (level - y[3]) / (y[4] - y[3]) * (x[4] - x[3]);
  const double cubic = monotone_crossing(x, y, level);
  INFO("chord " << chord << ", cubic " << cubic << ", root " << root);
  CHECK(std::abs(cubic - root) < 0.5 * std::abs(chord - root));
  CHECK(cubic > x[3]);
  CHECK(cubic < x[4]);
}
