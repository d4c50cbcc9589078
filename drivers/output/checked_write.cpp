#include "drivers/output/checked_write.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace ffp {

namespace fs = std::filesystem;

WriteFailure::WriteFailure(fs::path file, std::string cause)
    : WriteFailure("cannot write '" + file.string() + "': " + cause, file, cause) {}

WriteFailure::WriteFailure(const std::string& message, fs::path file, std::string cause)
    : std::runtime_error(message), file_(std::move(file)), cause_(std::move(cause)) {}

WriteFailure WriteFailure::of_standard_output(std::string cause) {
  return WriteFailure("cannot write to standard output: " + cause, {}, cause);
}

WriteFailure WriteFailure::moved(const fs::path& from, const fs::path& to) const {
  const fs::path relative = file_.lexically_relative(from);
  if (file_.empty() || relative.empty() || *relative.begin() == "..") return *this;
  return WriteFailure(relative == "." ? to : to / relative, cause_);
}

std::string cause_of(int error_number) {
  std::string text = std::generic_category().message(error_number);  // "No space left on device"
  // A clause inside our own sentence: lower case, unless the word is an abbreviation.
  if (text.size() > 1 && std::islower(static_cast<unsigned char>(text[1])))
    text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

namespace {

/// Closes its descriptor once, on every path out; close() itself is checked by release().
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  /// close(): its status, which a write cached by the file system may report only here (NFS).
  int release() {
    const int status = ::close(fd_);
    fd_ = -1;
    return status;
  }

 private:
  int fd_;
};

/// write() until every byte is out: a short write is not an error, the next call says why it stopped.
int write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
  return 0;
}

/// Writes and closes `temporary`; 0, or the errno of the first step that failed.
int write_temporary(const fs::path& temporary, std::string_view content, Durability durability) {
  Descriptor file(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
  if (file.get() < 0) return errno;
  if (const int error = write_all(file.get(), content)) return error;
  if (durability == Durability::synced && ::fsync(file.get()) != 0) return errno;
  return file.release() == 0 ? 0 : errno;
}

}  // namespace

void write_file_atomically(const fs::path& file, std::string_view content, Durability durability) {
  const fs::path temporary = file.string() + ".tmp-" + std::to_string(::getpid());
  int error = write_temporary(temporary, content, durability);
  if (error == 0 && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    throw WriteFailure(file, cause_of(error));
  }
  if (durability == Durability::synced) sync_folder(file.has_parent_path() ? file.parent_path() : fs::path("."));
}

void copy_file_atomically(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  std::ostringstream content;
  if (in) content << in.rdbuf();
  if (!in || in.bad()) throw std::runtime_error("cannot read '" + from.string() + "'");
  write_file_atomically(to, content.view());
}

void sync_folder(const fs::path& folder) {
  Descriptor directory(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (directory.get() < 0 || ::fsync(directory.get()) != 0) throw WriteFailure(folder, cause_of(errno));
}

void write_standard_output(std::string_view text) {
  finish_standard_output();
  if (const int error = write_all(STDOUT_FILENO, text)) throw WriteFailure::of_standard_output(cause_of(error));
}

void finish_standard_output() {
  // std::cout writes through stdout's buffer (synchronised with stdio): one fflush sends both.
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  std::cout.flush();
  if (flushed && !std::ferror(stdout) && std::cout.good()) return;
  // A write that failed earlier left only stdio's error flag: its errno is gone.
  throw WriteFailure::of_standard_output(flushed || error == 0 ? "a write failed" : cause_of(error));
}

}  // namespace ffp
