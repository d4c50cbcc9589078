#include "drivers/output/interrupt.hpp"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <mutex>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace ffp {

namespace {
std::atomic<int> g_signal_count{0};
std::mutex g_paths_mutex;
std::vector<std::filesystem::path> g_cleanup_paths;

void handle_signal(int signal_number) {
  // First signal: ask the run to stop at its next poll (unwinding removes the
  // temporary output). Second signal: stop at once; only a hidden
  // ".NAME.tmp-PID" directory can remain, never a half-written result.
  (void)signal_number;
  if (g_signal_count.fetch_add(1) >= 1) _exit(130);
}

void remove_registered_paths() {
  std::lock_guard lock(g_paths_mutex);
  for (const auto& p : g_cleanup_paths) {
    std::error_code ignored;
    std::filesystem::remove_all(p, ignored);
  }
  g_cleanup_paths.clear();
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = handle_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::atexit(remove_registered_paths);
}

bool interrupt_requested() { return g_signal_count.load(std::memory_order_relaxed) > 0; }

void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

void register_cleanup_path(const std::filesystem::path& path) {
  std::lock_guard lock(g_paths_mutex);
  g_cleanup_paths.push_back(path);
}

void unregister_cleanup_path(const std::filesystem::path& path) {
  std::lock_guard lock(g_paths_mutex);
  g_cleanup_paths.erase(std::remove(g_cleanup_paths.begin(), g_cleanup_paths.end(), path), g_cleanup_paths.end());
}

}  // namespace ffp
