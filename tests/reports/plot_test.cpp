// Figures go through gnuplot: a PNG when it is installed, a clean skip when not.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
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

TEST_CASE("a batch of figures draws the same bytes as one gnuplot per figure, and nothing unfinished",
          "[reports][plot]") {
  if (!ffp::gnuplot_available()) return;
  const fs::path dir = fs::temp_directory_path() / ("ffp_plot_batch_" + std::to_string(::getpid()));
  fs::create_directories(dir / "one");
  fs::create_directories(dir / "batch");
  // Figures that leave settings behind (log axes, reversed y, equal axes, a palette and a
  // colour range, multiplot), in an order where each would change the next without `reset`.
  ffp::Plot log_plot{"log", "x", "y", {}, true, true, false, "bottom left"};
  log_plot.series.push_back({{1e-3, 1e-2, 1.0}, {1.0, 1e-2, 1e-5}, "decay", "linespoints"});
  ffp::Plot depth{"depth", "velocity (m/s)", "depth (m)", {}, false, false, true, "top right"};
  depth.series.push_back({{5.6, 3.0, 0.0}, {0.0, 0.1, 0.19}, "profile", "lines"});
  ffp::ColourMap map;
  map.title = "strain";
  map.colour_label = "ε";
  map.colour_max = 0.5;
  for (int i = 0; i < 200; ++i) {
    map.x.push_back(0.002 * (i % 20));
    map.y.push_back(-0.002 * (i / 20));
    map.value.push_back(0.0025 * i);
  }
  map.overlays.push_back({{0.0, 0.04, 0.04}, {0.0, -0.02, 0.0}, "outline", "lines"});
  const auto draw = [&](const fs::path& to) {
    ffp::write_png(map, to / "map.png");
    ffp::write_png(log_plot, to / "log.png");
    ffp::write_png_row({map, map}, to / "row.png");
    ffp::write_png_stack({depth, log_plot}, to / "stack.png");
    ffp::write_png(depth, to / "depth.png");
  };
  draw(dir / "one");
  {
    ffp::PlotBatch batch;
    draw(dir / "batch");
    CHECK(batch.queued() == 5);
    CHECK_FALSE(fs::exists(dir / "batch" / "map.png"));  // queued, not drawn yet
    batch.finish();
    CHECK(batch.queued() == 0);
  }
  const auto bytes = [](const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* name : {"map.png", "log.png", "row.png", "stack.png", "depth.png"}) {
    INFO(name);
    REQUIRE(fs::exists(dir / "batch" / name));
    CHECK(bytes(dir / "batch" / name) == bytes(dir / "one" / name));
  }
  int leftovers = 0;  // no script or temporary PNG left behind
  for (const auto& entry : fs::directory_iterator(dir / "batch")) leftovers += entry.path().extension() != ".png";
  CHECK(leftovers == 0);
  {
    ffp::PlotBatch unfinished;  // a failed run: its figures are dropped
    ffp::write_png(depth, dir / "dropped.png");
  }
  CHECK_FALSE(fs::exists(dir / "dropped.png"));
  ffp::write_png(depth, dir / "after.png");  // no batch alive: drawn at once again
  CHECK(fs::exists(dir / "after.png"));
  fs::remove_all(dir);
}
