#pragma once
/// PNG line plots through gnuplot (pngcairo). If gnuplot is not installed the
/// plot is skipped with one warning on stderr: runs never fail for a figure.
#include <filesystem>
#include <string>
#include <vector>

namespace ffp {

struct Series {
  std::vector<double> x;
  std::vector<double> y;
  std::string title;
  std::string style = "lines";  ///< gnuplot style: "lines", "points", "linespoints", "lines dashtype 2", ...
};

struct Plot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
  bool log_x = false;
  bool log_y = false;
  bool reverse_y = false;  ///< e.g. penetration depth growing downward
  std::string key_position = "top right";
  int width_px = 900;
  int height_px = 600;
};

/// Write `plot` to `png` (via a temporary file). Returns false if skipped.
bool write_png(const Plot& plot, const std::filesystem::path& png);

/// Several plots stacked in one PNG (one column), e.g. depth/velocity/deceleration.
bool write_png_stack(const std::vector<Plot>& plots, const std::filesystem::path& png, int width_px = 900,
                     int panel_height_px = 360);

/// True when a gnuplot executable is on PATH.
bool gnuplot_available();

}  // namespace ffp
