#pragma once
/// The moving mesh of Al-Kafaji (2013), as the paper uses it (section 4,
/// Fig. 4b): the rows of a band of cells around the penetrometer translate
/// with it, the rows below compress and the rows above stretch, each zone
/// uniformly, between the fixed bottom and top of the grid. Particles keep
/// their positions; only the vertical node coordinates change, between steps.
#include <vector>

#include "mpm/grid.hpp"

namespace ffp::mpm {

class MovingMesh {
 public:
  MovingMesh() = default;
  /// `z_nodes` are the initial vertical coordinates; rows band_first..band_last
  /// (0 < band_first < band_last < last row) form the moving band.
  MovingMesh(std::vector<double> z_nodes, int band_first, int band_last);

  /// Vertical coordinates for a band displaced by `displacement_m` (+ up).
  /// Throws StepFailure when the band would squeeze a zone below 5 % of its
  /// initial height (the penetrometer reached the bottom or the top).
  std::vector<double> coordinates(double displacement_m) const;
  /// Replace the grid's vertical coordinates (weights, cells and h_min follow next step).
  void apply(Grid& grid, double displacement_m) const;

  int band_first() const { return band_first_; }
  int band_last() const { return band_last_; }
  const std::vector<double>& initial() const { return z0_; }

 private:
  std::vector<double> z0_;
  int band_first_ = 0, band_last_ = 0;
};

}  // namespace ffp::mpm
