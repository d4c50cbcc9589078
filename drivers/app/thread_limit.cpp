#include "drivers/app/thread_limit.hpp"

#include <sched.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "mpm/parallel.hpp"

namespace ffp {

int max_useful_threads() {
  cpu_set_t cpus;
  CPU_ZERO(&cpus);
  const int cores = ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus) : 1;
  return 4 * (cores > 0 ? cores : 1);
}

void cap_environment_threads() {
  const char* asked = std::getenv("OMP_NUM_THREADS");
  if (asked == nullptr) return;
  // The first entry of the list (OMP_NUM_THREADS=8,2 sets nested levels too); libgomp itself
  // warns about a value that is not a positive number and ignores it.
  char* end = nullptr;
  errno = 0;
  const long first = std::strtol(asked, &end, 10);
  if (end == asked || (*end != '\0' && *end != ',')) return;
  const int cap = max_useful_threads();
  if (errno != ERANGE && first <= cap) return;
  std::fprintf(stderr, "warning: OMP_NUM_THREADS=%s is more than 4 × the %d cores here: using %d threads\n", asked,
               cap / 4, cap);
  ::setenv("OMP_NUM_THREADS", std::to_string(cap).c_str(), 1);
  mpm::set_thread_count(cap);
}

}  // namespace ffp
