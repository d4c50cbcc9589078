#include "reports/png_stream.hpp"

#include <cstdint>

namespace ffp {

namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

std::uint32_t big_endian_u32(std::string_view bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[static_cast<std::size_t>(i)]);
  return v;
}

/// The length of the complete PNG that `bytes` starts with, or 0 when it does not start with one.
/// A chunk is [length: 4][type: 4][data: length][CRC: 4]; the file ends with the chunk of type IEND.
std::size_t complete_png_length(std::string_view bytes) {
  if (!bytes.starts_with(kSignature)) return 0;
  std::size_t at = kSignature.size();
  while (bytes.size() - at >= 12) {
    const std::uint64_t chunk = 12ull + big_endian_u32(bytes.substr(at, 4));
    if (chunk > bytes.size() - at) return 0;
    const bool last = bytes.substr(at + 4, 4) == "IEND";
    at += static_cast<std::size_t>(chunk);
    if (last) return at;
  }
  return 0;
}

}  // namespace

PngStream split_png_stream(std::string_view bytes) {
  PngStream stream;
  while (const std::size_t length = complete_png_length(bytes)) {
    stream.complete.push_back(bytes.substr(0, length));
    bytes.remove_prefix(length);
  }
  stream.rest = bytes;
  return stream;
}

bool is_complete_png(std::string_view bytes) {
  const PngStream stream = split_png_stream(bytes);
  return stream.complete.size() == 1 && stream.rest.empty();
}

}  // namespace ffp
