// Figures go through gnuplot: a PNG when it is installed, a clean skip when not.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "reports/plot.hpp"

namespace fs = std::filesystem;

TEST_CASE("a log-log plot is written as a PNG, or skipped cleanly without gnuplot", "[reports][plot]") {
  const fs::path dir = fs::temp_directory_path() / ("ffp_plot_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ffp::Plot plot{"error against wall time", "wall time (s)", "relative error", {}, true, true, false, "top right"};
  plot.series.push_back({{1e-6, 1e-4, 1e-2}, {1.0, 1e-3, 1e-6}, "a series", "linespoints"});
  plot.series.push_back({{1.0, 2.0}, {std::nan(""), 1.0}, "a gap is no crash", "lines"});
  const fs::path png = dir / "plot.png";
  const bool written = ffp::write_png(plot, png);
  if (ffp::gnuplot_available()) {
    REQUIRE(written);
    std::ifstream in(png, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    CHECK(std::string(magic + 1, 3) == "PNG");
  } else {
    CHECK_FALSE(written);
    CHECK_FALSE(fs::exists(png));
  }
  int leftovers = 0;  // the temporary script and data files are gone
  for (const auto& entry : fs::directory_iterator(dir)) leftovers += entry.path() != png;
  CHECK(leftovers == 0);
  fs::remove_all(dir);
}
