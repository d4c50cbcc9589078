#include "mpm/grid_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ffp::mpm {

namespace {

void check_coordinates(std::span<const double> x) {
  if (x.size() < 3) throw std::invalid_argument("a grid axis needs at least 3 nodes (2 cells)");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw std::invalid_argument("grid coordinate " + std::to_string(i) + " is not finite");
    if (i > 0 && !(x[i] > x[i - 1]))
      throw std::invalid_argument("grid coordinates must increase strictly (node " + std::to_string(i) + ")");
  }
}

}  // namespace

GridAxis::GridAxis(std::vector<double> coordinates) : x_(std::move(coordinates)) {
  check_coordinates(x_);
  build_lookup();
}

void GridAxis::set_coordinates(std::span<const double> coordinates) {
  if (coordinates.size() != x_.size()) throw std::invalid_argument("moving mesh: the node count must not change");
  check_coordinates(coordinates);
  std::copy(coordinates.begin(), coordinates.end(), x_.begin());
  build_lookup();
}

void GridAxis::build_lookup() {
  min_spacing_ = x_[1] - x_[0];
  inverse_spacing_.resize(static_cast<std::size_t>(cells()));
  for (int c = 0; c < cells(); ++c) {
    min_spacing_ = std::min(min_spacing_, spacing(c));
    inverse_spacing_[static_cast<std::size_t>(c)] = 1.0 / spacing(c);
  }
  // Buckets no wider than the smallest cell leave at most one step in cell_of;
  // the cap bounds memory for extreme grading (a few more steps then).
  const double length = x_.back() - x_.front();
  const double bucket = std::max(min_spacing_, length / 1.0e6);
  const std::size_t count = static_cast<std::size_t>(std::ceil(length / bucket)) + 1;
  inverse_bucket_ = 1.0 / bucket;
  lookup_.assign(count, 0);
  int c = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double start = x_.front() + static_cast<double>(k) * bucket;
    while (c < cells() - 1 && start >= x_[static_cast<std::size_t>(c) + 1]) ++c;
    lookup_[k] = c;
  }
}

double GridAxis::hat_integral(int node, double a, double b) const {
  double total = 0.0;
  // The hat rises on the cell to the left of the node and falls on the one to its right;
  // on each the integral of a linear function is length × value at the midpoint.
  if (node > 0) {
    const double x0 = coordinate(node - 1), x1 = coordinate(node);
    const double lo = std::max(a, x0), hi = std::min(b, x1);
    if (hi > lo) total += (hi - lo) * ((0.5 * (lo + hi) - x0) / (x1 - x0));
  }
  if (node < cells()) {
    const double x0 = coordinate(node), x1 = coordinate(node + 1);
    const double lo = std::max(a, x0), hi = std::min(b, x1);
    if (hi > lo) total += (hi - lo) * ((x1 - 0.5 * (lo + hi)) / (x1 - x0));
  }
  return total;
}

double GridAxis::hat_moment(int node, double a, double b) const {
  double total = 0.0;
  // On each of the node's two cells N x is quadratic: Simpson's rule is exact.
  for (const int other : {node - 1, node + 1}) {
    if (other < 0 || other > cells()) continue;
    const double x_node = coordinate(node), x_other = coordinate(other);
    const double lo = std::max(a, std::min(x_node, x_other)), hi = std::min(b, std::max(x_node, x_other));
    if (!(hi > lo)) continue;
    const auto moment = [&](double x) { return (x - x_other) / (x_node - x_other) * x; };
    total += (hi - lo) / 6.0 * (moment(lo) + 4.0 * moment(0.5 * (lo + hi)) + moment(hi));
  }
  return total;
}

}  // namespace ffp::mpm
