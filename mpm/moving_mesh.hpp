#pragma once
/// The moving mesh of Al-Kafaji (2013), as the paper uses it (section 4,
/// Fig. 4b): the rows of a band of cells around the penetrometer translate
/// with it, the rows below compress and the rows above stretch, each zone
/// uniformly, between the fixed bottom and top of the grid. Particles keep
/// their positions; only the vertical node coordinates change, between steps.
///
/// The compressing zone's cells never get smaller than `min_compressed_cell_m`:
/// from there on the band stops and the penetrometer goes on through its fine
/// cells. Cells squeezed below the particle spacing leave rows of empty cells,
/// and the one-pressure-per-cell smoothing then has a checkerboard mode in z:
/// measured, the reference FFP at 0.125 cm (cells squeezed to 0.6 of the far
/// field's particle spacing) lost the stress of its compressing zone after
/// 75 ms and the soil above it fell under gravity.
#include <vector>

#include "mpm/grid.hpp"

namespace ffp::mpm {

class MovingMesh {
 public:
  MovingMesh() = default;
  /// `z_nodes` are the initial vertical coordinates; rows band_first..band_last
  /// (0 < band_first < band_last < last row) form the moving band. The band stops
  /// going down once the compressing zone's cells are `min_compressed_cell_m`
  /// high (0: no limit, the zone compresses to 5 % of its height).
  /// Rows below `base_row` (a margin under the sand, absorbing walls) stay where they are; the
  /// compressing zone runs from base_row up to the band.
  MovingMesh(std::vector<double> z_nodes, int band_first, int band_last, double min_compressed_cell_m = 0.0,
             int base_row = 0);

  /// Vertical coordinates for a penetrometer displaced by `displacement_m` (+ up):
  /// the band follows it down to band_stop_m(). Throws StepFailure when the
  /// displacement would squeeze a zone below 5 % of its initial height (the
  /// penetrometer reached the bottom or the top), whether or not the band stopped.
  std::vector<double> coordinates(double displacement_m) const;
  /// The lowest displacement the band follows (−∞ without a limit).
  double band_stop_m() const { return band_stop_m_; }
  /// Replace the grid's vertical coordinates (weights, cells and h_min follow next step).
  void apply(Grid& grid, double displacement_m) const;

  int band_first() const { return band_first_; }
  int band_last() const { return band_last_; }
  const std::vector<double>& initial() const { return z0_; }

 private:
  std::vector<double> z0_;
  int band_first_ = 0, band_last_ = 0, base_row_ = 0;
  double band_stop_m_ = 0.0;
};

}  // namespace ffp::mpm
