#include "reports/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "drivers/output/checked_write.hpp"
#include "drivers/output/interrupt.hpp"
#include "reports/png_stream.hpp"
#include "reports/subprocess.hpp"

namespace ffp {

namespace fs = std::filesystem;

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

bool gnuplot_available() {
  static const bool found = [] {
    const char* path = std::getenv("PATH");
    if (path == nullptr) return false;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
      if (!dir.empty() && ::access((fs::path(dir) / "gnuplot").c_str(), X_OK) == 0) return true;
    }
    return false;
  }();
  return found;
}

namespace {

void write_panel(std::ostream& script, const Plot& plot, std::ostream& data, int& block) {
  script << "set title " << gnuplot_quoted(plot.title) << "\n";
  script << "set xlabel " << gnuplot_quoted(plot.x_label) << "\nset ylabel " << gnuplot_quoted(plot.y_label) << "\n";
  // Log axes in %g (1e-05, 0.001, 0.1): gnuplot's default prints 0.0000010.
  script << (plot.log_x ? "set logscale x\nset format x '%g'\n" : "unset logscale x\nset format x '% h'\n");
  script << (plot.log_y ? "set logscale y\nset format y '%g'\n" : "unset logscale y\nset format y '% h'\n");
  script << (plot.reverse_y ? "set yrange [*:*] reverse\n" : "set yrange [*:*] noreverse\n");
  script << "set key " << plot.key_position << "\n";
  script << "plot ";
  bool first = true;
  for (const auto& s : plot.series) {
    if (s.x.empty()) continue;
    if (!first) script << ", ";
    first = false;
    script << "$data" << block << " using 1:2 with " << s.style << " title " << gnuplot_quoted(s.title);
    data << "$data" << block << " << EOD\n";
    char line[64];
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        data << "\n";  // a gap, not a crash
        continue;
      }
      std::snprintf(line, sizeof line, "%.9g %.9g\n", s.x[i], s.y[i]);
      data << line;
    }
    data << "EOD\n";
    ++block;
  }
  if (first) script << "NaN notitle";
  script << "\n";
}

void write_colour_panel(std::ostream& script, const ColourMap& map, std::ostream& data, int& block) {
  script << "set title " << gnuplot_quoted(map.title) << "\n";
  script << "set xlabel " << gnuplot_quoted(map.x_label) << "\nset ylabel " << gnuplot_quoted(map.y_label) << "\n";
  script << "unset logscale x\nunset logscale y\nset yrange [*:*] noreverse\n";
  script << (map.equal_axes ? "set size ratio -1\n" : "set size noratio\n");
  script << "set cblabel " << gnuplot_quoted(map.colour_label) << "\n";
  script << "set palette " << map.palette << "\n";
  if (!map.colour_tics.empty()) script << "set cbtics " << map.colour_tics << "\n";
  if (map.colour_max > map.colour_min)
    script << "set cbrange [" << map.colour_min << ":" << map.colour_max << "]\n";
  else
    script << "set cbrange [*:*]\n";
  script << "set key off\n";
  const int points_block = block++;
  data << "$data" << points_block << " << EOD\n";
  char line[96];
  for (std::size_t i = 0; i < map.x.size() && i < map.y.size() && i < map.value.size(); ++i) {
    if (!std::isfinite(map.x[i]) || !std::isfinite(map.y[i]) || !std::isfinite(map.value[i])) continue;
    std::snprintf(line, sizeof line, "%.6g %.6g %.6g\n", map.x[i], map.y[i], map.value[i]);
    data << line;
  }
  data << "EOD\n";
  script << "plot $data" << points_block << " using 1:2:3 with points pt 5 ps " << map.point_size << " palette notitle";
  for (const auto& s : map.overlays) {
    data << "$data" << block << " << EOD\n";
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      std::snprintf(line, sizeof line, "%.9g %.9g\n", s.x[i], s.y[i]);
      data << line;
    }
    data << "EOD\n";
    script << ", $data" << block << " using 1:2 with " << s.style << " lc rgb 'black' lw 2 notitle";
    ++block;
  }
  script << "\nset size noratio\n";
  if (!map.colour_tics.empty()) script << "set cbtics autofreq\n";
}

/// The queue of the PlotBatch alive on this thread, if any.
thread_local std::vector<PlotBatch::Item>* active_batch = nullptr;

/// One figure's script: the terminal, its output (gnuplot's standard output) and the panels.
std::string figure_script(const std::string& body, int width, int height) {
  std::ostringstream script;
  script << "set terminal pngcairo size " << width << "," << height << " font 'Sans,10'\n";
  script << "set output\n";
  // Plain text: '_' in scene names must not turn into subscripts.
  script << "set termoption noenhanced\nset grid\nset encoding utf8\n" << body << "unset output\n";
  return script.str();
}

/// gnuplot run on a script: it reads the script from standard input and writes its
/// pictures to standard output, so that neither a path nor a quoting rule is involved,
/// and the PNG files are written by ffp, which checks every byte (pngcairo does not
/// report a failed write: on a full disk it left truncated files and exit status 0).
/// The script is loaded as the file /dev/stdin so that gnuplot's messages give its line.
ProgramOutput run_gnuplot(const std::string& script) { return run_program({"gnuplot", "/dev/stdin"}, script); }

/// Why gnuplot drew no complete picture for `png`: its last message (gnuplot stops at its
/// first error, after any warnings and the offending line), or its status. A gnuplot ended
/// by the user's Ctrl-C (it shares the terminal's signals) is an interruption.
WriteFailure plot_failure(const fs::path& png, const ProgramOutput& run) {
  throw_if_interrupted();
  if (run.status == -1) return WriteFailure(png, run.err);
  std::string message;
  std::istringstream lines(run.err);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(" \t^");
    if (first != std::string::npos) message = line.substr(first);
  }
  const std::string script_name = "\"/dev/stdin\" ";
  if (message.starts_with(script_name)) message = "script " + message.substr(script_name.size());
  if (run.status == 0)
    return WriteFailure(png, "gnuplot gave no complete PNG" + (message.empty() ? "" : ": " + message));
  return WriteFailure(
      png, "gnuplot failed (exit status " + std::to_string(run.status) + ")" + (message.empty() ? "" : ": " + message));
}

void render_now(const std::string& body, const fs::path& png, int width, int height) {
  draw_with_gnuplot(png, figure_script(body, width, height));
}

bool render(const std::string& body, const fs::path& png, int width, int height) {
  if (!gnuplot_available()) {
    static std::once_flag warned;
    std::call_once(warned, [] { std::fputs("warning: gnuplot not found: plots are skipped\n", stderr); });
    return false;
  }
  if (active_batch != nullptr) {
    active_batch->push_back({body, png, width, height});
    return true;
  }
  render_now(body, png, width, height);
  return true;
}

}  // namespace

void draw_with_gnuplot(const fs::path& png, const std::string& script) {
  const ProgramOutput run = run_gnuplot(script);
  const PngStream pictures = split_png_stream(run.out);
  if (run.status != 0 || pictures.complete.size() != 1 || !pictures.rest.empty()) throw plot_failure(png, run);
  write_file_atomically(png, pictures.complete.front());
}

bool write_png(const Plot& plot, const fs::path& png) {
  std::ostringstream data, script;
  int block = 0;
  write_panel(script, plot, data, block);
  return render(data.str() + script.str(), png, plot.width_px, plot.height_px);
}

bool write_png(const ColourMap& map, const fs::path& png) {
  std::ostringstream data, script;
  int block = 0;
  write_colour_panel(script, map, data, block);
  return render(data.str() + script.str(), png, map.width_px, map.height_px);
}

bool write_png_row(const std::vector<ColourMap>& maps, const fs::path& png, int panel_width_px, int height_px) {
  std::ostringstream data, script;
  int block = 0;
  script << "set multiplot layout 1," << maps.size() << "\n";
  for (const auto& m : maps) write_colour_panel(script, m, data, block);
  script << "unset multiplot\n";
  return render(data.str() + script.str(), png, panel_width_px * static_cast<int>(maps.size()), height_px);
}

bool write_png_stack(const std::vector<Plot>& plots, const fs::path& png, int width_px, int panel_height_px) {
  std::ostringstream data, script;
  int block = 0;
  script << "set multiplot layout " << plots.size() << ",1\n";
  for (const auto& p : plots) write_panel(script, p, data, block);
  script << "unset multiplot\n";
  return render(data.str() + script.str(), png, width_px, panel_height_px * static_cast<int>(plots.size()));
}

PlotBatch::PlotBatch() {
  if (active_batch != nullptr) throw std::logic_error("PlotBatch: batches do not nest");
  active_batch = &items_;
}

PlotBatch::~PlotBatch() { active_batch = nullptr; }

void PlotBatch::finish() {
  if (items_.empty()) return;
  const std::vector<Item> items = std::move(items_);
  items_.clear();
  std::string script;
  for (const Item& item : items) {
    // reset: every figure starts from gnuplot's defaults, as in a process of its own
    // (terminal and output are not reset, and each figure sets its own); its
    // data blocks go with it.
    script += "reset\n" + figure_script(item.body, item.width_px, item.height_px) + "undefine $*\n";
  }
  const ProgramOutput run = run_gnuplot(script);
  const PngStream pictures = split_png_stream(run.out);
  // gnuplot stops at its first error: the pictures before it are whole, the next one failed.
  if (run.status != 0 || pictures.complete.size() != items.size() || !pictures.rest.empty())
    throw plot_failure(items[std::min(pictures.complete.size(), items.size() - 1)].png, run);
  for (std::size_t i = 0; i < items.size(); ++i) write_file_atomically(items[i].png, pictures.complete[i]);
}

}  // namespace ffp
