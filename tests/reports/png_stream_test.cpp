// PNG files in a byte stream: split where each ends (its IEND chunk), and nothing cut off passes for whole.
#include <string>

#include <catch2/catch.hpp>

#include "reports/png_stream.hpp"

namespace {

/// A chunk: [length, big-endian][type][data][CRC]. The CRC is not what is checked here: zeros.
std::string chunk(const std::string& type, const std::string& data) {
  std::string out;
  const auto n = static_cast<unsigned>(data.size());
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((n >> shift) & 0xff);
  return out + type + data + std::string(4, '\0');
}

/// A PNG's structure: the signature, a header, some image data, the end (ISO/IEC 15948, 5.2-5.3).
std::string png(const std::string& pixels) {
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", std::string(13, '\1')) + chunk("IDAT", pixels) +
         chunk("IEND", "");
}

}  // namespace

TEST_CASE("two PNG files back to back are split into both, whole", "[reports][png]") {
  // IEND inside the image data must not end the file: chunks are walked by their lengths.
  const std::string first = png("IEND inside the data"), second = png(std::string(70000, '\xff'));
  const std::string both = first + second;  // the stream's views point into it
  const ffp::PngStream stream = ffp::split_png_stream(both);
  REQUIRE(stream.complete.size() == 2);
  CHECK(stream.complete[0] == first);
  CHECK(stream.complete[1] == second);
  CHECK(stream.rest.empty());
  CHECK(ffp::is_complete_png(first));
  CHECK_FALSE(ffp::is_complete_png(first + second));
}

TEST_CASE("a PNG cut off anywhere is not complete", "[reports][png]") {
  const std::string whole = png("pixels");
  for (std::size_t length = 0; length < whole.size(); ++length) {
    INFO("cut after " << length << " of " << whole.size() << " bytes");
    const std::string cut = whole.substr(0, length);
    const ffp::PngStream stream = ffp::split_png_stream(cut);
    CHECK(stream.complete.empty());
    CHECK(stream.rest.size() == length);
    CHECK_FALSE(ffp::is_complete_png(cut));
  }
  const std::string and_a_piece = whole + whole.substr(0, 30);
  const ffp::PngStream after_one = ffp::split_png_stream(and_a_piece);
  CHECK(after_one.complete.size() == 1);
  CHECK(after_one.rest.size() == 30);
  CHECK_FALSE(ffp::is_complete_png("GIF89a, not a PNG"));
}
