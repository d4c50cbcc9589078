#pragma once
/// OMP_NUM_THREADS, capped to what can help before the first parallel region.
///
/// Why: libgomp makes a team of the size asked at the first parallel region.
/// OMP_NUM_THREADS=100000 crashed it there (SIGSEGV in GOMP_parallel), and
/// 1000 threads on a 2-core machine made a short FFP run (the reference to
/// 2 ms) take 4.0–4.7 s against 0.7–1.0 s on 8: every MPM step passes a dozen
/// barriers, and threads beyond the cores only wait at them. The cap, 4 × the cores this process may run on, leaves
/// room to oversubscribe on purpose (a measurement, a core count a container hides) while refusing what is certainly a
/// mistake. ffp reads no thread count of its own from the environment: --jobs and --threads are range-checked options,
/// and a Slurm task's SLURM_CPUS_PER_TASK reaches it as OMP_NUM_THREADS.
namespace ffp {

/// The most OpenMP threads a run uses: 4 × the cores of this process's CPU affinity.
int max_useful_threads();

/// When OMP_NUM_THREADS asks for more than max_useful_threads(), uses that
/// many instead, sets OMP_NUM_THREADS to it (so runs this one starts inherit
/// the cap) and says so in one line on stderr. Call at the start of main().
void cap_environment_threads();

}  // namespace ffp
