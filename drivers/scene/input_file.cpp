#include "drivers/scene/input_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "drivers/scene/scene_error.hpp"

namespace ffp {

namespace {

/// "16 MiB", "4.2 GiB", "812 bytes": binary units, as the caps are set.
std::string size_text(std::uintmax_t bytes) {
  char text[40];
  const double mib = static_cast<double>(bytes) / (1024.0 * 1024.0);
  if (mib >= 1024.0) {
    std::snprintf(text, sizeof text, "%.1f GiB", mib / 1024.0);
  } else if (mib >= 1.0) {
    const bool whole = bytes % (1024 * 1024) == 0;
    std::snprintf(text, sizeof text, whole ? "%.0f MiB" : "%.1f MiB", mib);
  } else {
    std::snprintf(text, sizeof text, "%ju bytes", bytes);
  }
  return text;
}

std::string type_problem(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a named pipe";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

std::string size_problem(std::uintmax_t bytes, const InputFileLimit& limit) {
  if (bytes <= limit.max_bytes) return "";
  return "is " + size_text(bytes) + ": " + std::string(limit.what) + " may be at most " + size_text(limit.max_bytes);
}

/// Closes the descriptor however the read ends.
struct OpenFile {
  int fd = -1;
  ~OpenFile() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string input_file_problem(const std::filesystem::path& file, const InputFileLimit& limit) {
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0)
    return errno == ENOENT ? "does not exist" : std::string("cannot be read: ") + std::strerror(errno);
  const std::string type = type_problem(status.st_mode);
  if (!type.empty()) return type + " (" + std::string(limit.what) + " must be a regular file)";
  return size_problem(static_cast<std::uintmax_t>(status.st_size), limit);
}

std::string read_input_file(const std::filesystem::path& file, const InputFileLimit& limit) {
  const std::string name = file.string();
  if (const std::string problem = input_file_problem(file, limit); !problem.empty())
    throw SceneError(name + ": " + problem);
  // Non-blocking: should a named pipe have taken the file's place since stat(), opening it returns at once.
  OpenFile in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (in.fd < 0) throw SceneError(name + ": cannot be read: " + std::strerror(errno));
  struct stat opened {};
  if (::fstat(in.fd, &opened) != 0) throw SceneError(name + ": cannot be read: " + std::strerror(errno));
  if (!S_ISREG(opened.st_mode)) throw SceneError(name + ": " + type_problem(opened.st_mode));
  std::string content;
  content.reserve(static_cast<std::size_t>(std::min<std::uintmax_t>(opened.st_size, limit.max_bytes)));
  char buffer[1 << 16];
  while (true) {
    const ssize_t got = ::read(in.fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw SceneError(name + ": cannot be read: " + std::strerror(errno));
    if (got == 0) break;
    content.append(buffer, static_cast<std::size_t>(got));
    if (content.size() > limit.max_bytes)
      throw SceneError(name + ": " + std::string(limit.what) + " may be at most " + size_text(limit.max_bytes) +
                       " (it grew past that while being read)");
  }
  static constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (content.starts_with(kByteOrderMark)) content.erase(0, kByteOrderMark.size());
  return content;
}

}  // namespace ffp
