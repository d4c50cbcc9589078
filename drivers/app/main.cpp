/// ffp: sand constitutive-model testbed and axisymmetric MPM solver for
/// free-fall penetrometer impacts.
#include <cstdio>
#include <cstdlib>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/thread_limit.hpp"
#include "drivers/output/checked_write.hpp"
#include "drivers/output/interrupt.hpp"

namespace {

/// OpenMP threads that spin while they wait take the cores other processes
/// need, and when those processes run, every barrier of the MPM step waits a
/// scheduler quantum (measured here: a 0.7 s FFP run took 10.8 s on two
/// threads beside one busy process, 0.7 s with passive waiting). libgomp reads
/// OMP_WAIT_POLICY when it is loaded, before main(), so the default is set from
/// the executable's .preinit_array, which runs before any shared library's
/// initialiser. A user's own OMP_WAIT_POLICY is kept.
void wait_passively_by_default(int, char**, char**) { ::setenv("OMP_WAIT_POLICY", "PASSIVE", 0); }
[[gnu::section(".preinit_array"), gnu::used]] void (*const k_wait_passively)(int, char**,
                                                                             char**) = &wait_passively_by_default;

}  // namespace

int main(int argc, char** argv) {
  ffp::install_interrupt_handlers();
  ffp::cap_environment_threads();
  const int code = ffp::exit_code_after_command(ffp::run_command_line(argc, argv));
  // What any command printed (help and version included) reached standard output, or the exit code says not.
  try {
    ffp::finish_standard_output();
  } catch (const ffp::WriteFailure& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return code == 0 ? 1 : code;
  }
  return code;
}
