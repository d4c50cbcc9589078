#include "drivers/output/output_lock.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ffp {

namespace fs = std::filesystem;

namespace {

/// The process id a holder wrote into the lock file; "" when unreadable.
std::string holder_of(int fd) {
  char text[24] = {};
  const ssize_t got = ::pread(fd, text, sizeof text - 1, 0);
  if (got <= 0) return "";
  std::string pid(text, static_cast<std::size_t>(got));
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid;
}

/// Whether `fd` is still the file at `path`: a holder removes the file before it lets go, so a lock
/// taken on a file already removed guards nothing.
bool still_named(int fd, const fs::path& path) {
  struct stat opened {
  }, named{};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_dev == named.st_dev &&
         opened.st_ino == named.st_ino;
}

}  // namespace

fs::path lock_file_of(const fs::path& target) {
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string name = ".";  // built step by step: GCC 12 warns falsely (-Wrestrict) on "." + string
  name += target.filename().string();
  name += ".lock";
  return parent / name;
}

OutputLock::OutputLock(const fs::path& target, const std::string& option) : file_(lock_file_of(target)) {
  while (true) {
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw SceneError(option + ": cannot write in '" + file_.parent_path().string() + "' (making its lock file " +
                       file_.filename().string() + ": " + std::strerror(errno) + ")");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = holder_of(fd_);
      ::close(fd_);
      fd_ = -1;
      if (error != EWOULDBLOCK)
        throw SceneError(option + ": cannot lock '" + file_.string() + "': " + std::strerror(error));
      throw OutputFolderBusy(option + ": '" + target.string() + "' is being written by another ffp" +
                             (holder.empty() ? "" : " (process " + holder + ")") +
                             ": wait for it to finish, or choose another folder");
    }
    if (still_named(fd_, file_)) break;
    ::close(fd_);  // its holder removed it meanwhile: lock the file now at that name
  }
  // The holder's id, for a second run's message; the lock holds whether or not it is written.
  const std::string pid = std::to_string(::getpid()) + "\n";
  const bool written = ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) == ssize_t(pid.size());
  (void)written;
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());  // while still held: no other process can hold this file at this name now
  ::close(fd_);
}

}  // namespace ffp
