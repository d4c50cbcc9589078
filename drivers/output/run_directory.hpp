#pragma once
/// A run's output directory, written under a temporary name beside the target
/// and renamed into place only when the run completes. An existing result is
/// replaced only by a complete one; a failed or interrupted run leaves nothing.
///
/// ffp never deletes what it did not write: every folder it makes carries a
/// manifest (kOutputManifest) listing the files it wrote, and a folder is
/// replaced only when it is absent, empty, or holds exactly what its manifest
/// lists. Anything else is refused (OutputFolderRefused, exit 2) unless the
/// user forces it. A run killed with SIGKILL leaves only hidden
/// ".NAME.tmp-PID" / ".NAME.old-PID" siblings, which the next run into the
/// same target removes once their process is gone.
///
/// What is never replaced, --force or not: a symbolic link (the name on the
/// command line would not be what changed; "latest -> run_old" is a pointer
/// meant to stay, and writing through it would overwrite a run the user did
/// not name), a file or anything else that is not a folder, "." and "..".
/// A folder ffp only adds to (a run cache, a sweep's folder) may be a link to
/// one: nothing is replaced there. One process writes a target at a time
/// (OutputLock); a name too long for ffp's siblings, or a place where folders
/// cannot be made, is refused before the run with the system's reason.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "drivers/output/checked_write.hpp"
#include "drivers/output/output_lock.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

/// Written last into every folder ffp makes, so its presence means "complete".
inline constexpr const char* kOutputManifest = ".ffp-output.json";
/// A sweep's table in its folder (ffp sweep, ffp collect); claim_persistent_folder removes a dead writer's temporary of
/// it.
inline constexpr const char* kSweepTable = "sweep.csv";

/// Bad input of a kind: the folder the user named holds files ffp did not write.
class OutputFolderRefused : public SceneError {
 public:
  using SceneError::SceneError;
};

/// The files and folders under `folder` (relative paths, sorted) that its
/// manifest does not list; every entry when it has no manifest. Empty when the
/// folder is absent or empty.
std::vector<std::string> files_not_written_by_ffp(const std::filesystem::path& folder);

/// Throws OutputFolderRefused naming `option` when `folder` is a symbolic link,
/// exists and is not a folder, is "." or "..", or (unless `force`) holds files
/// ffp did not write (see files_not_written_by_ffp).
void require_replaceable(const std::filesystem::path& folder, const std::string& option, bool force);

/// The manifest of a finished folder: every file under it, relative, sorted.
void write_manifest(const std::filesystem::path& folder, const std::string& what);

/// A folder ffp keeps adding to (a run cache, a sweep's folder): created with a
/// manifest when absent or empty, accepted when it carries one (or is a cache
/// written before manifests existed: only "<label>-<16 hex>" run folders and
/// ".<label>.log" files), refused otherwise unless `force`. A symbolic link to
/// a folder is followed; one to nothing, or anything not a folder, is refused.
void claim_persistent_folder(const std::filesystem::path& folder, const std::string& option, const std::string& what,
                             bool force);

/// Removes ".NAME.tmp-PID" and ".NAME.old-PID" siblings of `target` whose
/// process no longer runs (left by a run that was killed).
void remove_stale_siblings(const std::filesystem::path& target);

class RunDirectory {
 public:
  /// Throws OutputFolderRefused (naming `option`) when require_replaceable does,
  /// when the name leaves no room for ffp's ".NAME.tmp-PID" sibling, or when the
  /// folder cannot be made there; OutputFolderBusy when another process writes
  /// the same target. Holds the target's lock until destroyed.
  explicit RunDirectory(std::filesystem::path target, std::string option = "--out", bool force = false);
  ~RunDirectory();  // removes the temporary directory unless committed
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  /// Where to write now (the temporary directory).
  const std::filesystem::path& path() const { return working_; }
  const std::filesystem::path& target() const { return target_; }

  /// Write the manifest and move the finished output to the target
  /// (atomically replaces a previous result). Checks the target again: a file
  /// the user put there during the run is never deleted. The manifest and the
  /// rename are on the disk when this returns; a manifest that cannot be
  /// written (WriteFailure) leaves the target as it was.
  void commit(const std::string& what = "run");

 private:
  std::filesystem::path target_;
  std::filesystem::path working_;
  std::string option_;
  bool force_ = false;
  bool committed_ = false;
  std::unique_ptr<OutputLock> lock_;  ///< held while working_ exists, until destruction
};

}  // namespace ffp
