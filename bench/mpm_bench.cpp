/// MPM step throughput: particle-steps per second for a Mohr-Coulomb sand
/// block of about 10^5 particles under gravity (the paper's sand, K0 = 0.39),
/// 1 and 2 threads, linear and GIMP weights; plus a size sweep (1 thread) that
/// shows whether memory traffic or arithmetic limits the step.
///
///   ffp_mpm_bench
/// The counter `particle_steps_per_s` is the figure of merit, over a fixed 300 steps
/// after the first five (kMeasuredSteps). The block slumps at its free side and more
/// and more points yield, so a step's work grows over its first ~300 steps (by about
/// a quarter, the Mohr–Coulomb returns): with Google Benchmark's own count (as many
/// steps as fit in its time) a faster build ran further into the slump, on heavier
/// steps, than a slower one. Per-stage times are printed once to stderr to show
/// where time goes: FFP_MPM_BENCH_STAGES=1 over 50 steps after the first five,
/// FFP_MPM_BENCH_STAGES=N over N steps (the reference FFP's too, after its first 200);
/// the measured steps then follow those.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "models/math_constants.hpp"
#include "mpm/ffp_model.hpp"
#include "mpm/parallel.hpp"
#include "mpm/simulation.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// `cells` × `cells` cells filled with 2 × 2 particles in a 0.4 m × 0.4 m block
/// (160: 102,400 particles), a few empty cells around it.
Simulation sand_block(ShapeFunction shape, int cells) {
  const double h = 0.4 / cells;
  ModelDescription m;
  for (int i = 0; i <= cells + 2; ++i) m.r_nodes_m.push_back(i * h);
  for (int j = 0; j <= cells + 4; ++j) m.z_nodes_m.push_back(j * h);
  const MohrCoulombParameters sand{ElasticConstants{2.5e6, 0.33}, 39.0 * kDegree, 0.0, 0.0};
  m.bodies.push_back(BodyDescription{"sand", MohrCoulomb(sand), 1488.3, BoxRegion{0.0, 0.4, 0.0, 0.4}, 2, 2, 0.0, 0.0,
                                     GeostaticStress{0.39, 0.4}});
  m.gravity_m_s2 = 9.81;
  m.solver.shape_function = shape;
  return Simulation(m);
}

void print_stage_times(Simulation& s, const char* label, int steps) {
  std::vector<double> seconds(s.stages.items().size(), 0.0);
  StageList timed;
  for (std::size_t k = 0; k < s.stages.items().size(); ++k) {
    const Stage& stage = s.stages.items()[k];
    timed.append({stage.name, [run = stage.run, slot = &seconds[k]](Simulation& sim) {
                    const auto start = std::chrono::steady_clock::now();
                    run(sim);
                    *slot += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                  }});
  }
  const StageList original = s.stages;
  s.stages = timed;
  for (int k = 0; k < steps; ++k) s.advance();
  s.stages = original;
  std::fprintf(stderr, "%s: ns per particle-step by stage\n", label);
  double total = 0.0;
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    const double ns = 1e9 * seconds[k] / steps / static_cast<double>(s.particles.size());
    total += ns;
    std::fprintf(stderr, "  %-28s %6.1f\n", s.stages.items()[k].name.c_str(), ns);
  }
  std::fprintf(stderr, "  %-28s %6.1f\n", "total", total);
}

/// The steps each BM_MpmStep measures: the same work for every build (see above).
constexpr int kMeasuredSteps = 300;

void BM_MpmStep(benchmark::State& state) {
  const auto shape = state.range(0) == 0 ? ShapeFunction::linear : ShapeFunction::gimp;
  const int threads = static_cast<int>(state.range(1));
  const int previous = thread_count();
  set_thread_count(threads);
  Simulation s = sand_block(shape, static_cast<int>(state.range(2)));
  for (int k = 0; k < 5; ++k) s.advance();         // warm caches and the page tables
  static std::set<std::pair<long, long>> printed;  // benchmark calls this once per trial size
  const char* stage_steps = std::getenv("FFP_MPM_BENCH_STAGES");
  if (stage_steps && printed.insert({state.range(0) * 10 + threads, state.range(2)}).second)
    print_stage_times(
        s,
        (std::string(shape == ShapeFunction::gimp ? "GIMP" : "linear") + ", " + std::to_string(threads) + " thread(s)")
            .c_str(),
        std::max(50, std::atoi(stage_steps)));
  for (auto _ : state) s.advance();
  const double particle_steps = static_cast<double>(state.iterations()) * static_cast<double>(s.particles.size());
  state.counters["particles"] = static_cast<double>(s.particles.size());
  state.counters["particle_steps_per_s"] = benchmark::Counter(particle_steps, benchmark::Counter::kIsRate);
  set_thread_count(previous);
}

}  // namespace

// The figure of merit: ~10^5 particles, 1 and 2 threads.
BENCHMARK(BM_MpmStep)
    ->ArgNames({"gimp", "threads", "cells"})
    ->Args({0, 1, 160})
    ->Args({0, 2, 160})
    ->Args({1, 1, 160})
    ->Args({1, 2, 160})
    ->Iterations(kMeasuredSteps)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// What limits it: the same work per particle on 1,600 particles (all data in L1/L2)
// and on 409,600 (well past L2). Throughput that barely changes from 1,600 to 10^5
// particles means the step is bound by arithmetic and scattered updates, not memory.
BENCHMARK(BM_MpmStep)
    ->ArgNames({"gimp", "threads", "cells"})
    ->Args({0, 1, 20})
    ->Args({0, 1, 320})
    ->Args({1, 1, 20})
    ->Args({1, 1, 320})
    ->Iterations(kMeasuredSteps)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The reference FFP scene (paper section 4, 1 cm minimum cell, rigid body,
// contact, moving mesh): steps per second during penetration, 1 and 2 threads.
// 200 steps first, so that the body is in the sand and the contact is active.
void BM_FfpReferenceStep(benchmark::State& state) {
  const int previous = thread_count();
  set_thread_count(static_cast<int>(state.range(0)));
  FfpDescription d;
  d.soil.law = MohrCoulomb(MohrCoulombParameters{ElasticConstants{2.5e6, 0.33}, 39.0 * kDegree, 0.0, 0.0});
  d.contact.friction = std::tan(20.0 * kDegree);
  FfpRun run(d);
  for (int k = 0; k < 200; ++k) run.advance();
  static std::set<long> printed;
  const char* stage_steps = std::getenv("FFP_MPM_BENCH_STAGES");
  if (stage_steps && printed.insert(state.range(0)).second)
    print_stage_times(run.simulation(), ("FFP reference, " + std::to_string(state.range(0)) + " thread(s)").c_str(),
                      std::max(50, std::atoi(stage_steps)));
  for (auto _ : state) run.advance();
  state.counters["particles"] = static_cast<double>(run.simulation().particles.size());
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  set_thread_count(previous);
}
BENCHMARK(BM_FfpReferenceStep)->ArgNames({"threads"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
