#include "reports/heatmap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <sstream>

#include "reports/plot.hpp"

namespace ffp {

namespace fs = std::filesystem;

bool write_heatmap_png(const HeatMap& map, const fs::path& png) {
  if (!gnuplot_available()) {
    static std::once_flag warned;
    std::call_once(warned, [] { std::fputs("warning: gnuplot not found: plots are skipped\n", stderr); });
    return false;
  }
  const std::size_t nx = map.x.size(), ny = map.y.size();
  if (nx < 2 || ny < 2 || map.values.size() != nx * ny) return false;

  // A floor for log scales: zero error (an elastic increment) shows as the lowest colour.
  double smallest_positive = std::numeric_limits<double>::max();
  for (double v : map.values)
    if (v > 0.0 && std::isfinite(v)) smallest_positive = std::min(smallest_positive, v);
  const double floor = smallest_positive == std::numeric_limits<double>::max() ? 1e-16 : smallest_positive;
  auto shown = [&](double v) { return map.log_values ? std::log10(std::max(v, floor)) : v; };

  std::ostringstream script;
  script << "$grid << EOD\n";
  char line[96];
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", map.x[i], map.y[j], shown(map.values[j * nx + i]));
      script << line;
    }
    script << "\n";  // gnuplot's grid format: a blank line ends each row
  }
  script << "EOD\n";
  script << "set termoption noenhanced\n";  // labels are plain text: '_' is not a subscript
  script << "set title " << gnuplot_quoted(map.title) << "\n";
  script << "set xlabel " << gnuplot_quoted(map.x_label) << "\nset ylabel " << gnuplot_quoted(map.y_label) << "\n";
  script << "set cblabel " << gnuplot_quoted(map.log_values ? "log10(" + map.value_label + ")" : map.value_label)
         << "\n";
  script << "set view map\nset pm3d map interpolate 0,0\nset palette rgbformulae 33,13,10\n";
  script << "set xrange [" << map.x.front() << ":" << map.x.back() << "]\n";
  script << "set yrange [" << map.y.front() << ":" << map.y.back() << "]\n";
  if (!map.contour_levels.empty()) {
    script << "set contour base\nset cntrparam levels discrete ";
    for (std::size_t k = 0; k < map.contour_levels.size(); ++k)
      script << (k ? "," : "") << shown(map.contour_levels[k]);
    script << "\nset cntrlabel onecolor format '%.0f'\nunset clabel\n";
    script << "unset surface\nset table $contours\nsplot $grid using 1:2:3 with lines notitle\nunset table\nunset "
              "contour\n";
    script << "plot $grid using 1:2:3 with image notitle, $contours using 1:2 with lines lc rgb 'black' lw 1 "
              "title 'decades'\n";
  } else {
    script << "plot $grid using 1:2:3 with image notitle\n";
  }

  std::ostringstream figure;
  figure << "set terminal pngcairo size " << map.width_px << "," << map.height_px << " font 'Sans,10'\n";
  figure << "set output\nset encoding utf8\n" << script.str() << "unset output\n";
  draw_with_gnuplot(png, figure.str());
  return true;
}

}  // namespace ffp
