#pragma once
/// One writer per output folder: an exclusive flock(2) on a hidden lock file
/// beside it, ".NAME.lock", held from before the run until its result is in
/// place.
///
/// Why: two runs into the same --out each wrote their own temporary folder and
/// then raced to rename it into place; the loser failed at its very end with a
/// raw "rename: Directory not empty", or one result silently replaced the
/// other. With the lock the second run is refused before it starts, naming the
/// process that holds the folder. The kernel drops the lock when its holder
/// dies, even by SIGKILL, so a stale lock file never blocks; the holder
/// removes the file when it lets go.
#include <filesystem>
#include <string>

#include "drivers/scene/scene_error.hpp"

namespace ffp {

/// Bad input of a kind: another process is writing the folder the user named.
class OutputFolderBusy : public SceneError {
 public:
  using SceneError::SceneError;
};

class OutputLock {
 public:
  /// Takes the lock of `target` (its parent folder must exist). Throws
  /// OutputFolderBusy naming `option` and the holder's process id when another
  /// process holds it, SceneError when the lock file cannot be made.
  OutputLock(const std::filesystem::path& target, const std::string& option);
  ~OutputLock();  ///< removes the lock file, then lets go
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

/// ".NAME.lock" beside `target`.
std::filesystem::path lock_file_of(const std::filesystem::path& target);

}  // namespace ffp
