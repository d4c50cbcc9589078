#pragma once
/// PNG files one after another in a byte stream (what gnuplot's pngcairo
/// terminal writes to standard output, one file per figure), split and checked
/// for completeness: a PNG is complete when its chunks run, length by length,
/// from the signature to the IEND chunk (PNG specification, ISO/IEC 15948, 5.2-5.3).
#include <string_view>
#include <vector>

namespace ffp {

struct PngStream {
  std::vector<std::string_view> complete;  ///< each a whole PNG file, in order
  std::string_view rest;                   ///< what follows the last complete one (a cut-off file, or not a PNG)
};

/// The parts are views into `bytes`: keep it alive while they are used.
PngStream split_png_stream(std::string_view bytes);

/// True when `bytes` is exactly one complete PNG file.
bool is_complete_png(std::string_view bytes);

}  // namespace ffp
