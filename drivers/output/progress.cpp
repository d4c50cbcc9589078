#include "drivers/output/progress.hpp"

#include <cstdio>

#include <unistd.h>

#include "drivers/output/interrupt.hpp"

namespace ffp {

Progress::Progress(std::string label, double total, bool enabled)
    : label_(std::move(label)),
      total_(total > 0 ? total : 1.0),
      enabled_(enabled),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  if (terminal_ && enabled_ && !finished_ && calls_ > 0) std::fputc('\n', stderr);
}

void Progress::update(double done, long steps) {
  ++calls_;
  if ((calls_ & 63) == 0 || done >= total_) throw_if_interrupted();
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double fraction = done / total_;
  if (terminal_) {
    if (now - last_draw_ < std::chrono::milliseconds(200) && fraction < 1.0) return;
  } else {
    // A log is never silent for long: the first line within seconds of the start (a long run's
    // first 10 % can take hours), then one per 10 % and at least one a minute.
    const auto silence = lines_ == 0 ? std::chrono::seconds(2) : std::chrono::seconds(60);
    if (fraction * 10.0 < next_decile_ && now - last_draw_ < silence) return;
    while (fraction * 10.0 >= next_decile_) ++next_decile_;
  }
  ++lines_;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? steps / elapsed : 0.0;
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "%s%s %5.1f%%  t = %.4g of %.4g  %.0f steps/s  ETA %.0f s%s", terminal_ ? "\r" : "",
               label_.c_str(), 100.0 * fraction, done, total_, rate, eta, terminal_ ? "   " : "\n");
  std::fflush(stderr);
}

void Progress::finish() {
  if (terminal_ && enabled_ && calls_ > 0 && !finished_) std::fputc('\n', stderr);
  finished_ = true;
}

}  // namespace ffp
