#pragma once
/// Heat maps of a scalar on a regular grid through gnuplot (pngcairo), with
/// contour lines; skipped with a warning when gnuplot is missing, and failing
/// (WriteFailure) when it cannot be drawn, like plot.hpp.
#include <filesystem>
#include <string>
#include <vector>

namespace ffp {

struct HeatMap {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string value_label;
  std::vector<double> x;               ///< nx grid abscissae (increasing)
  std::vector<double> y;               ///< ny grid ordinates (increasing)
  std::vector<double> values;          ///< values[iy * nx + ix]
  bool log_values = true;              ///< colour and contours by log10(value); values ≤ 0 are floored
  std::vector<double> contour_levels;  ///< in value units; empty: none
  int width_px = 800;
  int height_px = 700;
};

/// Write `map` to `png` (via a temporary file). Returns false if skipped (no gnuplot,
/// or fewer than 2 × 2 values); throws WriteFailure when it cannot be drawn or written.
bool write_heatmap_png(const HeatMap& map, const std::filesystem::path& png);

}  // namespace ffp
