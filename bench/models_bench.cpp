/// Constitutive updates per second, batches of 10^4 points (one core).
/// Each benchmark reports items_per_second = updates/s. States are reset from
/// a saved copy outside the timed region so every update does the same work.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "models/elastic.hpp"
#include "models/math_constants.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"

namespace {

using namespace ffp;

constexpr std::size_t kBatch = 10000;

MohrCoulombParameters paper_mc() {
  MohrCoulombParameters p;
  p.elastic = {2.5e6, 0.33};
  p.friction_angle_rad = 39 * kDegree;
  p.dilatancy_angle_rad = 5 * kDegree;
  return p;
}

/// Stresses near 1.72 kPa confinement; `three_d` adds the 23 and 13 shears
/// (general eigen-solver path), otherwise axisymmetric (closed-form 2×2 path).
std::vector<Voigt> stresses(bool three_d, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 100.0);
  std::vector<Voigt> out(kBatch);
  for (auto& s : out) {
    s << -1.72e3 + noise(rng), -3e3 + noise(rng), -1.72e3 + noise(rng), noise(rng), 0, 0;
    if (three_d) s[4] = noise(rng), s[5] = noise(rng);
  }
  return out;
}

/// Isochoric axial compression 10× the yield strain: every update returns to the plane/edge.
std::vector<Voigt> shearing_increments(bool three_d, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 2e-4);
  std::vector<Voigt> out(kBatch);
  for (auto& e : out) {
    e << 5e-3 + noise(rng), -1e-2 + noise(rng), 5e-3 + noise(rng), noise(rng), 0, 0;
    if (three_d) e[4] = noise(rng), e[5] = noise(rng);
  }
  return out;
}

/// Volumetric extension: every c' = 0 update ends at the apex.
std::vector<Voigt> tensile_increments(std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 2e-4);
  std::vector<Voigt> out(kBatch);
  for (auto& e : out) e << 5e-3 + noise(rng), 5e-3 + noise(rng), 5e-3 + noise(rng), noise(rng), 0, 0;
  return out;
}

template <class Update>
void run(benchmark::State& bench, const std::vector<Voigt>& start, Update update) {
  std::vector<Voigt> stress = start;
  for (auto _ : bench) {
    bench.PauseTiming();
    stress = start;
    bench.ResumeTiming();
    update(stress);
    benchmark::DoNotOptimize(stress.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<int64_t>(bench.iterations() * kBatch));
}

void elastic(benchmark::State& bench) {
  std::mt19937_64 rng(1);
  const auto start = stresses(false, rng);
  const auto increments = shearing_increments(false, rng);
  const LinearElastic law(paper_mc().elastic);
  run(bench, start, [&](std::vector<Voigt>& s) { law.update(s, increments); });
}

void mc_plane_return(benchmark::State& bench) {
  std::mt19937_64 rng(2);
  const bool three_d = bench.range(0) != 0;
  const auto start = stresses(three_d, rng);
  const auto increments = shearing_increments(three_d, rng);
  const MohrCoulomb law(paper_mc());
  run(bench, start, [&](std::vector<Voigt>& s) { law.update(s, increments); });
}

/// The Mohr-Coulomb update where no point yields (increments a thousand times smaller
/// than shearing_increments): its elastic screen alone, most of an MPM step's updates.
void mc_elastic_screen(benchmark::State& bench) {
  std::mt19937_64 rng(2);
  const auto start = stresses(false, rng);
  auto increments = shearing_increments(false, rng);
  for (auto& e : increments) e *= 1e-3;
  const MohrCoulomb law(paper_mc());
  run(bench, start, [&](std::vector<Voigt>& s) { law.update(s, increments); });
}

void mc_apex_return(benchmark::State& bench) {
  std::mt19937_64 rng(3);
  const auto start = stresses(false, rng);
  const auto increments = tensile_increments(rng);
  const MohrCoulomb law(paper_mc());
  run(bench, start, [&](std::vector<Voigt>& s) { law.update(s, increments); });
}

/// As run(), with the SSMC state reset to `fresh` as well before each batch.
void run_ssmc(benchmark::State& bench, const StrainSofteningMohrCoulomb& law, const std::vector<Voigt>& start,
              const std::vector<Voigt>& increments, const std::vector<StrainSofteningMohrCoulomb::State>& fresh,
              double dt_s) {
  std::vector<StrainSofteningMohrCoulomb::State> state = fresh;
  std::vector<Voigt> stress = start;
  for (auto _ : bench) {
    bench.PauseTiming();
    stress = start;
    state = fresh;
    bench.ResumeTiming();
    law.update(stress, increments, state, dt_s);
    benchmark::DoNotOptimize(stress.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<int64_t>(bench.iterations() * kBatch));
}

void ssmc_with_rate_law(benchmark::State& bench) {
  std::mt19937_64 rng(4);
  const bool three_d = bench.range(0) != 0;
  const auto start = stresses(three_d, rng);
  const auto increments = shearing_increments(three_d, rng);
  StrainSofteningParameters p;
  p.elastic = paper_mc().elastic;
  p.friction_peak_rad = 39 * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = 5 * kDegree;
  p.softening_factor = 8;
  p.relative_density = 0.15;  // Bolton transient dilatancy as well
  p.rate.alpha_phi = 0.1;
  p.rate.reference_strain_rate_per_s = 1.0;
  p.rate.smoothing_increments = 10;
  const StrainSofteningMohrCoulomb law(p);
  run_ssmc(bench, law, start, increments, std::vector<StrainSofteningMohrCoulomb::State>(kBatch),
           1e-4);  // ε̇ ≈ 100/s: the rate law is active
}

/// The paper's section 5.5 sand as the FFP runs it (φ'_p = 60°, φ'_c = 32°, ψ_p = 5°,
/// η = 8; no rate law, no Bolton).
StrainSofteningParameters paper_ssmc_sand() {
  StrainSofteningParameters p;
  p.elastic = paper_mc().elastic;
  p.friction_peak_rad = 60 * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = 5 * kDegree;
  p.softening_factor = 8;
  return p;
}

/// Two points in three of shearing_increments reversed and small: elastic unloading.
void unload_two_in_three(std::vector<Voigt>& increments) {
  for (std::size_t i = 0; i < increments.size(); ++i)
    if (i % 3 != 0) increments[i] *= -0.01;
}

/// A softened start (κ = 0.05) as in the soil around the penetrometer.
std::vector<StrainSofteningMohrCoulomb::State> softened_states() {
  return std::vector<StrainSofteningMohrCoulomb::State>(kBatch, {0.05, 0.0});
}

/// paper_ssmc_sand from softened_states. `mixed` = 0: every point shears plastically;
/// 1: two points in three unload elastically, about the FFP run's share of elastic updates;
/// 2: every point shears by increments a hundred times smaller, as in an MPM step.
void ssmc_paper_sand(benchmark::State& bench) {
  std::mt19937_64 rng(5);
  auto start = stresses(false, rng);
  auto increments = shearing_increments(false, rng);
  if (bench.range(0) == 1) unload_two_in_three(increments);
  const StrainSofteningMohrCoulomb law(paper_ssmc_sand());
  std::vector<StrainSofteningMohrCoulomb::State> fresh = softened_states();
  if (bench.range(0) == 2) {
    law.update(start, increments, fresh, 1e-5);  // on the surface, then further along
    for (auto& e : increments) e *= 0.01;
  }
  run_ssmc(bench, law, start, increments, fresh, 1e-5);
}

/// ssmc_paper_sand's mixed:1 points updated one by one (update(stress, ...) per point),
/// as the point integrator and the triaxial test drive the law.
void ssmc_point_by_point(benchmark::State& bench) {
  std::mt19937_64 rng(5);
  auto start = stresses(false, rng);
  auto increments = shearing_increments(false, rng);
  unload_two_in_three(increments);
  const StrainSofteningMohrCoulomb law(paper_ssmc_sand());
  const std::vector<StrainSofteningMohrCoulomb::State> fresh = softened_states();
  std::vector<StrainSofteningMohrCoulomb::State> state = fresh;
  std::vector<Voigt> stress = start;
  for (auto _ : bench) {
    bench.PauseTiming();
    stress = start;
    state = fresh;
    bench.ResumeTiming();
    for (std::size_t i = 0; i < kBatch; ++i) law.update(stress[i], increments[i], state[i], 1e-5);
    benchmark::DoNotOptimize(stress.data());
    benchmark::ClobberMemory();
  }
  bench.SetItemsProcessed(static_cast<int64_t>(bench.iterations() * kBatch));
}

}  // namespace

BENCHMARK(elastic)->Unit(benchmark::kMicrosecond);
BENCHMARK(mc_plane_return)->Arg(0)->Arg(1)->ArgName("three_d")->Unit(benchmark::kMicrosecond);
BENCHMARK(mc_elastic_screen)->Unit(benchmark::kMicrosecond);
BENCHMARK(mc_apex_return)->Unit(benchmark::kMicrosecond);
BENCHMARK(ssmc_with_rate_law)->Arg(0)->Arg(1)->ArgName("three_d")->Unit(benchmark::kMicrosecond);
BENCHMARK(ssmc_paper_sand)->Arg(0)->Arg(1)->Arg(2)->ArgName("mixed")->Unit(benchmark::kMicrosecond);

BENCHMARK(ssmc_point_by_point)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
