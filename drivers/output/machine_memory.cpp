#include "drivers/output/machine_memory.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/resource.h>

namespace ffp {

namespace {

void tighten(MemoryLimit& limit, double bytes, const char* source) {
  if (bytes > 0.0 && bytes < limit.bytes) limit = MemoryLimit{bytes, source};
}

double meminfo_bytes(const std::string& field) {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(field + ":", 0) != 0) continue;
    std::istringstream values(line.substr(field.size() + 1));
    double kilobytes = 0.0;
    values >> kilobytes;
    return kilobytes * 1024.0;
  }
  return 0.0;
}

double cgroup_limit_bytes() {
  std::ifstream in("/sys/fs/cgroup/memory.max");  // cgroup v2; "max" when unlimited
  std::string value;
  if (!(in >> value) || value == "max") return 0.0;
  try {
    return std::stod(value);
  } catch (...) {
    return 0.0;
  }
}

double rlimit_bytes(int resource) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0.0;
  return static_cast<double>(limit.rlim_cur);
}

}  // namespace

MemoryLimit usable_memory() {
  MemoryLimit limit{std::numeric_limits<double>::infinity(), "unlimited"};
  tighten(limit, meminfo_bytes("MemAvailable"), "available memory");
  tighten(limit, cgroup_limit_bytes(), "cgroup memory.max");
  tighten(limit, rlimit_bytes(RLIMIT_AS), "ulimit -v");
  tighten(limit, rlimit_bytes(RLIMIT_DATA), "ulimit -d");
  // A budget of one's own: a cluster job's memory request, or the fuzzers' limit.
  if (const char* mb = std::getenv("FFP_MEMORY_LIMIT_MB")) {
    char* end = nullptr;
    const double value = std::strtod(mb, &end);
    if (end != mb && *end == '\0' && value > 0.0) tighten(limit, value * 1e6, "FFP_MEMORY_LIMIT_MB");
  }
  return limit;
}

std::string format_bytes(double bytes) {
  char text[32];
  if (bytes >= 1e9) {
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  } else if (bytes >= 1e6) {
    std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  } else {
    std::snprintf(text, sizeof text, "%.0f kB", bytes / 1e3);
  }
  return text;
}

}  // namespace ffp
