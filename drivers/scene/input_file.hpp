#pragma once
/// Files the user names as input (scenes, lab curves, records, path tables),
/// checked before they are read: a regular file no larger than a cap.
///
/// Why before: a named pipe blocks its reader until some writer opens it, which
/// for a mistyped name is forever; a device such as /dev/zero never ends, so
/// reading it whole took 4.2 GB of memory before the JSON parser gave up; a
/// directory reads as empty. The type comes from stat(), which never opens the
/// file, and is checked again on the open descriptor (opened non-blocking), so
/// a file swapped in between cannot hang the reader either. Reading stops one
/// byte past the cap: a file that grows meanwhile is refused, not swallowed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ffp {

/// What an input is (for messages: "a scene file") and the most it may hold.
struct InputFileLimit {
  std::string_view what;
  std::uintmax_t max_bytes;
};

/// A scene is JSON written by hand: the largest shipped one is 2.3 kB, so
/// 16 MiB is about 7000 times that and still parses in well under a second.
inline constexpr InputFileLimit kSceneFileLimit{"a scene file", 16ull << 20};

/// The largest CSV a user gives is a sensor record: 100 kHz for 10 s is 10⁶
/// rows, about 45 bytes each with time, deceleration and pore pressure at ten
/// digits (45 MB), and 128 MB if a logger writes eight channels. 256 MiB holds
/// twice that; its numbers then take under 256 MiB as doubles.
inline constexpr InputFileLimit kCsvFileLimit{"a CSV file", 256ull << 20};

/// Why `file` cannot be read as an input: "is a directory", "is a named pipe",
/// "is a device", "is a socket", "does not exist", "cannot be read: <reason>",
/// or "is 20 MiB: a scene file may be at most 16 MiB" when it exceeds
/// `limit.max_bytes`. Empty when it is a regular file within the cap. Uses
/// stat() only: nothing is opened.
std::string input_file_problem(const std::filesystem::path& file, const InputFileLimit& limit);

/// The whole content of `file`, a UTF-8 byte-order mark at its start removed.
/// Throws SceneError "<file>: <problem>" (exit 2) when it is not a regular
/// file within the cap, or cannot be read.
std::string read_input_file(const std::filesystem::path& file, const InputFileLimit& limit);

}  // namespace ffp
