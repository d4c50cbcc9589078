#include "reports/subprocess.hpp"

#include <cerrno>

#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "drivers/output/checked_write.hpp"

extern char** environ;

namespace ffp {

namespace {

/// Owns a descriptor: closed on every path out.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

/// An anonymous file in memory, closed in the child at exec unless dup2'ed onto 0, 1 or 2.
int memory_file(const char* name) { return ::memfd_create(name, MFD_CLOEXEC); }

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::string read_all(int fd) {
  std::string out;
  char buffer[65536];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return out;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

ProgramOutput not_started(const std::string& program, int error_number) {
  return {-1, {}, "cannot start " + program + ": " + cause_of(error_number)};
}

}  // namespace

ProgramOutput run_program(const std::vector<std::string>& argv, std::string_view input) {
  if (argv.empty()) return not_started("a program", EINVAL);
  Fd in(memory_file("ffp-program-input")), err(memory_file("ffp-program-errors"));
  int pipe_ends[2];
  if (in.get() < 0 || err.get() < 0 || ::pipe2(pipe_ends, O_CLOEXEC) != 0) return not_started(argv[0], errno);
  Fd out_read(pipe_ends[0]), out_write(pipe_ends[1]);
  if (!write_all(in.get(), input) || ::lseek(in.get(), 0, SEEK_SET) != 0) return not_started(argv[0], errno);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out_write.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.get(), STDERR_FILENO);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  out_write.reset();  // the child's copy is the only writer left: its exit ends our read
  if (spawn_error != 0) return not_started(argv[0], spawn_error);

  ProgramOutput result;
  result.out = read_all(out_read.get());
  result.status = wait_for(pid);
  if (::lseek(err.get(), 0, SEEK_SET) == 0) result.err = read_all(err.get());
  return result;
}

}  // namespace ffp
