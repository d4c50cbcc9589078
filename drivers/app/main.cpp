/// ffp: sand constitutive-model testbed and axisymmetric MPM solver for
/// free-fall penetrometer impacts.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "drivers/app/commands.hpp"
#include "drivers/app/job.hpp"
#include "drivers/output/interrupt.hpp"

namespace {

constexpr const char* kUsage = R"(usage: ffp <command> [options]

Commands:
  run SCENE.json [--out DIR] [--force] [--set key=value ...] [--quiet]
        [--jobs N] [--scheduler local|slurm]
        Run a scene; write DIR/summary.json, DIR/history.csv, DIR/plots/
        (default DIR: results/<scene name>). --set overrides any scene key,
        e.g. --set material.E_kPa=5000. A DIR holding files ffp did not
        write is refused unless --force. An inverse fit runs its model runs
        N at a time (default: one per core), or as Slurm job arrays.
  check SCENE.json [--set key=value ...]
        Validate a scene and print it with defaults filled in.
  sweep SCENE.json --set key=v1,v2,... [--set ...] [--jobs N] [--out DIR] [--force]
        Run every combination as an independent process; DIR/sweep.csv.
        --emit DIR: write the cases for a scheduler instead (DIR/cases.tsv, one scene
        per case, slurm.sbatch, parallel.sh); --scheduler slurm: submit that job
        array with sbatch, wait, collect; --threads N: OpenMP threads per case.
  collect DIR
        Build DIR/sweep.csv from an emitted sweep's finished cases; list the missing
        and failed ones (exit 1 while any is).
  report [--out DIR] [--cache DIR] [--jobs N] [--only TEXT] [--force] [--scheduler local|slurm]
        Run the validation study (cached) and write DIR/report.md with figures;
        N runs side by side (default: one per core), or the uncached runs as one
        Slurm job array (--scheduler slurm).
  bench
        Measure the speed of the constitutive updates and the MPM step.
  --help, --version

Scene kinds: point, triaxial, calibration, integration_error, mpm, ffp, cpt, record, inverse
(see README.md).
Exit codes: 0 done, 1 run failed, 2 bad input, 130 interrupted.
)";

/// OpenMP threads that spin while they wait take the cores other processes
/// need, and when those processes run, every barrier of the MPM step waits a
/// scheduler quantum (measured here: a 0.7 s FFP run took 10.8 s on two
/// threads beside one busy process, 0.7 s with passive waiting). libgomp reads
/// OMP_WAIT_POLICY when it is loaded, before main(), so the default is set from
/// the executable's .preinit_array, which runs before any shared library's
/// initialiser. A user's own OMP_WAIT_POLICY is kept.
void wait_passively_by_default(int, char**, char**) { ::setenv("OMP_WAIT_POLICY", "PASSIVE", 0); }
[[gnu::section(".preinit_array"), gnu::used]] void (*const k_wait_passively)(int, char**, char**) =
    &wait_passively_by_default;

}  // namespace

int main(int argc, char** argv) {
  ffp::install_interrupt_handlers();
  ffp::Arguments args(argv + 1, argv + argc);
  if (args.empty()) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string command = args.front();
  args.erase(args.begin());
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  if (command == "--version") {
    std::puts(ffp::version_string().c_str());
    return 0;
  }
  if (command == "run") return ffp::command_run(args);
  if (command == "check") return ffp::command_check(args);
  if (command == "sweep") return ffp::command_sweep(args);
  if (command == "collect") return ffp::command_collect(args);
  if (command == "report") return ffp::command_report(args);
  if (command == "bench") return ffp::command_bench(args);
  std::fprintf(stderr, "ffp: unknown command '%s' (try ffp --help)\n", command.c_str());
  return 2;
}
