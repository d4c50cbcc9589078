#pragma once
/// A run's output directory, written under a temporary name beside the target
/// and renamed into place only when the run completes. An existing result is
/// replaced only by a complete one; a failed or interrupted run leaves nothing.
#include <filesystem>

namespace ffp {

class RunDirectory {
 public:
  explicit RunDirectory(std::filesystem::path target);
  ~RunDirectory();  // removes the temporary directory unless committed
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  /// Where to write now (the temporary directory).
  const std::filesystem::path& path() const { return working_; }
  const std::filesystem::path& target() const { return target_; }

  /// Move the finished output to the target (atomically replaces a previous result).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path working_;
  bool committed_ = false;
};

/// Write a file via a temporary name and rename (no half-written files).
void write_file_atomically(const std::filesystem::path& file, const std::string& content);

}  // namespace ffp
