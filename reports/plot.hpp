#pragma once
/// PNG line plots through gnuplot (pngcairo). If gnuplot is not installed the
/// plot is skipped with one warning on stderr (a documented choice: the numbers
/// are the result, figures are their view). A figure that an installed gnuplot
/// cannot draw, or that cannot be written whole, throws WriteFailure naming the
/// PNG: a run that lost a figure is not done.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace ffp {

struct Series {
  std::vector<double> x{};
  std::vector<double> y{};
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

/// Points coloured by a value (e.g. particles coloured by deviatoric strain,
/// as in the paper's Fig. 9), with optional line overlays (an outline).
struct ColourMap {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string colour_label;
  std::vector<double> x, y, value;
  std::vector<Series> overlays;
  double point_size = 0.4;
  bool equal_axes = true;
  double colour_min = 0.0, colour_max = 0.0;  ///< both 0: automatic range
  /// gnuplot's `set palette …` and `set cbtics …` arguments: a continuous scale by default;
  /// categories take `defined (…)` steps with their names as tics.
  std::string palette = "rgbformulae 33,13,10";
  std::string colour_tics = "";  ///< "" : gnuplot's own
  int width_px = 700;
  int height_px = 700;
};

/// Write `plot` to `png` (via a temporary file). Returns false if skipped (no gnuplot);
/// throws WriteFailure when the figure cannot be drawn or written.
bool write_png(const Plot& plot, const std::filesystem::path& png);

/// Several plots stacked in one PNG (one column), e.g. depth/velocity/deceleration.
bool write_png_stack(const std::vector<Plot>& plots, const std::filesystem::path& png, int width_px = 900,
                     int panel_height_px = 360);

bool write_png(const ColourMap& map, const std::filesystem::path& png);

/// Several colour maps side by side in one PNG (one row).
bool write_png_row(const std::vector<ColourMap>& maps, const std::filesystem::path& png, int panel_width_px = 420,
                   int height_px = 520);

/// True when a gnuplot executable is on PATH.
bool gnuplot_available();

/// A gnuplot string in single quotes: only the quote itself needs doubling.
std::string gnuplot_quoted(const std::string& text);

/// Draws one PNG with gnuplot from `script`, which sets a PNG terminal and `set output`
/// without a file name: gnuplot hands the picture back on its standard output and it
/// is written to `png` (via a temporary file) only when it is one complete PNG. No
/// path reaches gnuplot or a shell. Throws WriteFailure naming `png` with gnuplot's
/// first message, or the cause of a failed write ("no space left on device").
void draw_with_gnuplot(const std::filesystem::path& png, const std::string& script);

/// While one is alive (on this thread), the figures above are queued instead of
/// drawn (they return true when gnuplot is on PATH), and finish() draws them all in
/// one gnuplot process, each from a `reset`: the same bytes as one process per figure
/// (tests/reports/plot_test.cpp), without gnuplot's start-up for each (loading its
/// libraries and fonts: ~0.07 s CPU a figure; an `ffp run` of an FFP draws six).
/// Should gnuplot fail in the batch, finish() throws WriteFailure naming the figure
/// it failed on (gnuplot stops at its first error). A batch that is destroyed
/// unfinished (a run that failed or was interrupted) draws nothing.
/// Batches do not nest.
class PlotBatch {
 public:
  PlotBatch();
  ~PlotBatch();
  PlotBatch(const PlotBatch&) = delete;
  PlotBatch& operator=(const PlotBatch&) = delete;
  /// Draw the queued figures; the batch stays active (and empty) afterwards.
  /// Throws WriteFailure as draw_with_gnuplot does.
  void finish();
  std::size_t queued() const { return items_.size(); }

  struct Item {
    std::string body;
    std::filesystem::path png;
    int width_px, height_px;
  };

 private:
  std::vector<Item> items_;
};

}  // namespace ffp
