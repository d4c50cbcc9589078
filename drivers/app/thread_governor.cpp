#include "drivers/app/thread_governor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "mpm/parallel.hpp"

namespace ffp {

namespace {

/// Runnable tasks on the machine now ("procs_running" of /proc/stat), this one included.
int runnable_tasks() {
  std::ifstream in("/proc/stat");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("procs_running ", 0) == 0) return std::atoi(line.c_str() + 14);
  return 1;
}

// A process using less than this share of a core (a shell, an editor) costs no thread.
constexpr double kIgnoredLoad_cores = 0.2;

}  // namespace

ThreadGovernor::CpuTimes ThreadGovernor::read_cpu_times() {
  CpuTimes t;
  std::ifstream stat("/proc/stat");
  std::string cpu;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) {
    t.all_busy = user + nice + system + irq + softirq + steal;
    t.all_total = t.all_busy + idle + iowait;
  }
  // /proc/self/stat: fields 14 and 15 are utime and stime; the name (field 2) may hold spaces.
  std::ifstream self("/proc/self/stat");
  std::string text((std::istreambuf_iterator<char>(self)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close != std::string::npos) {
    std::istringstream fields(text.substr(close + 2));
    std::string skip;
    for (int field = 3; field < 14; ++field) fields >> skip;
    double utime = 0, stime = 0;
    if (fields >> utime >> stime) t.own = utime + stime;
  }
  return t;
}

ThreadGovernor::ThreadGovernor(std::chrono::milliseconds interval) : interval_(interval) {
  cores_ = std::max(1, mpm::thread_count());
  active_ = cores_ > 1 && std::getenv("OMP_NUM_THREADS") == nullptr;
  threads_ = cores_;
  if (!active_) return;
  choose(static_cast<double>(std::max(0, runnable_tasks() - 1)));
  last_ = std::chrono::steady_clock::now();
  last_times_ = read_cpu_times();
}

ThreadGovernor::~ThreadGovernor() {
  if (active_ && threads_ != cores_) mpm::set_thread_count(cores_);
}

void ThreadGovernor::choose(double others_cores) {
  const int taken = static_cast<int>(std::ceil(std::max(0.0, others_cores - kIgnoredLoad_cores)));
  const int wanted = std::clamp(cores_ - taken, 1, cores_);
  if (wanted != threads_) mpm::set_thread_count(wanted);
  threads_ = wanted;
}

void ThreadGovernor::poll() {
  if (!active_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < interval_) return;
  const CpuTimes times = read_cpu_times();
  const double total = times.all_total - last_times_.all_total;
  if (total > 0.0) {
    const double others = std::max(0.0, (times.all_busy - last_times_.all_busy) - (times.own - last_times_.own));
    choose(others / total * cores_);
  }
  last_ = now;
  last_times_ = times;
}

}  // namespace ffp
