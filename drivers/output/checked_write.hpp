#pragma once
/// Writing so that a result which says "done" is complete. Every byte written
/// and every close is checked; a failure names the file and its cause as the
/// system gave it ("no space left on device"). A file whose presence marks a
/// result as finished (a run's summary, a folder's manifest, a sweep's or a
/// report's table) is forced to the disk before it takes its name, so that a
/// crash cannot leave the mark without its content.
///
/// Why not std::ofstream: its last buffer is written by close(), whose failure
/// the destructor swallows: a summary of a few kB on a full disk came out empty
/// and the run still said done.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ffp {

/// A file (or standard output) that could not be written completely: the run
/// failed (exit code 1), and nothing may mark it as finished.
class WriteFailure : public std::runtime_error {
 public:
  WriteFailure(std::filesystem::path file, std::string cause);
  /// Standard output could not be written (its file() is empty).
  static WriteFailure of_standard_output(std::string cause);
  const std::filesystem::path& file() const { return file_; }
  const std::string& cause() const { return cause_; }
  /// The same failure told for where the file was going to be: `file` under
  /// `from` (a run's temporary folder) named under `to` (the folder the user asked for).
  WriteFailure moved(const std::filesystem::path& from, const std::filesystem::path& to) const;

 private:
  WriteFailure(const std::string& message, std::filesystem::path file, std::string cause);
  std::filesystem::path file_;
  std::string cause_;
};

/// The system's text for an errno value as a clause: "no space left on device".
std::string cause_of(int error_number);

/// Whether write_file_atomically forces the file (and its rename) to the disk.
/// One fsync costs a few milliseconds on a disk: kept for the files that mark
/// completion, not spent on every frame of a run's fields.
enum class Durability { cached, synced };

/// Writes `content` to a temporary name beside `file` ("FILE.tmp-PID") and
/// renames it into place: `file` is either absent, its old content, or all of
/// `content`. Throws WriteFailure naming `file`; the temporary is removed.
void write_file_atomically(const std::filesystem::path& file, std::string_view content,
                           Durability durability = Durability::cached);

/// Copies `from` to `to` as write_file_atomically writes it. A source that
/// cannot be read throws std::runtime_error naming it; the write, WriteFailure.
void copy_file_atomically(const std::filesystem::path& from, const std::filesystem::path& to);

/// Forces a folder's entries (a file or folder renamed into it) to the disk.
void sync_folder(const std::filesystem::path& folder);

/// Writes a command's result to standard output (after anything printed
/// before it): throws WriteFailure::of_standard_output with the cause when any
/// of it could not be written, e.g. `ffp check SCENE > /dev/full`.
void write_standard_output(std::string_view text);

/// Flushes standard output (C and C++ streams both): throws
/// WriteFailure::of_standard_output when any of it could not be written.
/// stdio may have dropped the failed bytes and the error's cause by then (glibc
/// does): a result meant for standard output goes through write_standard_output.
void finish_standard_output();

}  // namespace ffp
