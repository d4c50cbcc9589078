#include "mpm/moving_mesh.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "mpm/simulation.hpp"

namespace ffp::mpm {

MovingMesh::MovingMesh(std::vector<double> z_nodes, int band_first, int band_last, double min_compressed_cell_m,
                       int base_row)
    : z0_(std::move(z_nodes)), band_first_(band_first), band_last_(band_last), base_row_(base_row) {
  const int last = static_cast<int>(z0_.size()) - 1;
  if (!(base_row >= 0 && band_first > base_row && band_first < band_last && band_last < last))
    throw std::invalid_argument("moving mesh: the band must leave at least one cell below and above it");
  if (!(min_compressed_cell_m >= 0.0)) throw std::invalid_argument("moving mesh: the smallest cell must be ≥ 0");
  // The zone [bottom, band bottom] compresses uniformly: its smallest cell, times the
  // ratio below = (height + u)/height, reaches the limit at u = height (ratio − 1).
  const auto lo = static_cast<std::size_t>(band_first), base = static_cast<std::size_t>(base_row);
  const double height = z0_[lo] - z0_[base];
  double smallest = height;
  for (std::size_t j = base + 1; j <= lo; ++j) smallest = std::min(smallest, z0_[j] - z0_[j - 1]);
  band_stop_m_ = min_compressed_cell_m > 0.0 ? height * (std::min(1.0, min_compressed_cell_m / smallest) - 1.0)
                                             : -std::numeric_limits<double>::infinity();
}

std::vector<double> MovingMesh::coordinates(double u) const {
  const std::size_t n = z0_.size();
  const auto lo = static_cast<std::size_t>(band_first_), hi = static_cast<std::size_t>(band_last_);
  const auto base = static_cast<std::size_t>(base_row_);
  const double bottom = z0_[base], top = z0_.back();
  // Compressing zone [bottom, band bottom] and stretching zone [band top, top]:
  // each node keeps its relative position in its zone.
  const double below = (z0_[lo] + u - bottom) / (z0_[lo] - bottom);
  const double above = (top - (z0_[hi] + u)) / (top - z0_[hi]);
  if (!(below > 0.05) || !(above > 0.05))
    throw StepFailure("moving mesh: the penetrometer's band came within 5 % of the grid's " +
                      std::string(below <= 0.05 ? "bottom" : "top") + " (displacement " + std::to_string(u) + " m): " +
                      (below <= 0.05 ? "the penetrometer went through the chamber; give a deeper soil.depth_m or a "
                                       "shorter end_time_s"
                                     : "it rebounded out of the grid; give a larger mesh.air_above_m"));
  // The band follows the penetrometer down to band_stop_m_ only.
  const double band = std::max(u, band_stop_m_);
  const double band_below = (z0_[lo] + band - bottom) / (z0_[lo] - bottom);
  const double band_above = (top - (z0_[hi] + band)) / (top - z0_[hi]);
  std::vector<double> z(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (j <= base) {
      z[j] = z0_[j];  // the margin under the sand, and the sand's base
    } else if (j <= lo) {
      z[j] = bottom + (z0_[j] - bottom) * band_below;
    } else if (j < hi) {
      z[j] = z0_[j] + band;
    } else {
      z[j] = top - (top - z0_[j]) * band_above;
    }
  }
  z[base] = bottom;  // the fixed ends stay exactly where they are
  z.back() = top;
  return z;
}

void MovingMesh::apply(Grid& grid, double u) const { grid.z.set_coordinates(coordinates(u)); }

}  // namespace ffp::mpm
