/// One calibration of η on each reconstructed lab curve (data/lab/), as the
/// `calibration` scenes run it: 9-point W(η) scan, Ceres fit, final curve; the
/// element test at 1000 increments. Also one element test alone. Wall time per
/// calibration is what a user waits for (under a second).
#include <filesystem>
#include <stdexcept>
#include <string>

#include <benchmark/benchmark.h>

#include "calibration/lab_curve.hpp"
#include "calibration/mpm_triaxial_specimen.hpp"
#include "calibration/numerical_triaxial.hpp"
#include "calibration/softening_calibration.hpp"
#include "models/math_constants.hpp"

namespace {

using namespace ffp;

/// The scenes' materials: data/scenes/calibration_dr00.json and _dr15.json.
StrainSofteningParameters sand(bool dense) {
  StrainSofteningParameters p;
  p.elastic = {dense ? 5e6 : 1e6, 0.33};
  p.friction_peak_rad = (dense ? 40 : 38) * kDegree;
  p.friction_residual_rad = 32 * kDegree;
  p.dilatancy_peak_rad = (dense ? 5 : 2) * kDegree;
  p.softening_factor = 8;
  return p;
}

LabCurve lab(bool dense) {
  const char* name = dense ? "triaxial_dr15.csv" : "triaxial_dr00.csv";
  // The source tree this file was compiled from (CMake passes absolute paths), else the working directory.
  const std::filesystem::path source_tree = std::filesystem::path(__FILE__).parent_path().parent_path();
  for (const std::filesystem::path& base : {source_tree, std::filesystem::path(".")})
    if (std::filesystem::exists(base / "data" / "lab" / name)) return read_lab_curve(base / "data" / "lab" / name);
  throw std::runtime_error(std::string("calibration_bench: cannot find data/lab/") + name);
}

void BM_Calibration(benchmark::State& bench) {
  const bool dense = bench.range(0) == 15;
  const CalibrationMode mode =
      bench.range(1) == 0 ? CalibrationMode::dissipated_work : CalibrationMode::curve_least_squares;
  const LabCurve curve = lab(dense);
  TriaxialTestConfig test;
  test.axial_strain_max = curve.axial_strain.back();
  test.increments = 1000;
  const NumericalTriaxial triaxial = element_test_triaxial(sand(dense), test);
  CalibrationSettings settings;
  settings.mode = mode;
  settings.eta_start = 8.0;  // as the scenes start
  int runs = 0, iterations = 0;
  double eta = 0.0;
  for (auto _ : bench) {
    const CalibrationResult r = calibrate_softening_factor(curve, triaxial, settings);
    benchmark::DoNotOptimize(r.eta);
    runs = r.model_runs;
    iterations = r.iterations;
    eta = r.eta;
  }
  bench.counters["eta"] = eta;
  bench.counters["element_tests"] = runs;
  bench.counters["iterations"] = iterations;
}
BENCHMARK(BM_Calibration)
    ->ArgNames({"Dr_percent", "curve_mode"})
    ->Args({0, 0})
    ->Args({15, 0})
    ->Args({0, 1})
    ->Args({15, 1})
    ->Unit(benchmark::kMillisecond);

void BM_ElementTest(benchmark::State& bench) {
  TriaxialTestConfig test;
  test.axial_strain_max = 0.2;
  test.increments = static_cast<int>(bench.range(0));
  const NumericalTriaxial triaxial = element_test_triaxial(sand(true), test);
  for (auto _ : bench) benchmark::DoNotOptimize(triaxial(17.0).deviatoric_stress_Pa.back());
  bench.SetItemsProcessed(bench.iterations() * bench.range(0));  // increments/s
}
BENCHMARK(BM_ElementTest)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

/// The meshed calibration's two paths on the lab curve at D_r = 15 % with the 2 cm
/// specimen (64 particles, the cheapest meshed one): 0 = central differences from
/// η = 8 after a 9-point scan (the scenes before the fast path), 1 = the scenes'
/// mpm defaults (3-point scan with the compare_eta 2.5 and 15, Ceres from the scan's
/// crossing, secant slopes), runs side by side on range(1) threads.
void BM_MeshedCalibration(benchmark::State& bench) {
  const bool fast = bench.range(0) == 1;
  const LabCurve curve = lab(true);
  MpmTriaxialConfig config;
  config.cell_m = 0.02;
  config.axial_strain_max = curve.axial_strain.back();
  const NumericalTriaxial triaxial = mpm_triaxial_specimen(sand(true), config);
  CalibrationSettings settings;
  settings.derivative_step = 0.1;
  settings.parameter_tolerance = 1e-4;
  settings.work_tolerance = 2e-4;
  if (fast) {
    settings.scan_points = 3;
    settings.scan_extra_eta = {2.5, 15.0};
    settings.derivative = FitDerivative::secant;
  } else {
    settings.eta_start = 8.0;
  }
  int runs = 0;
  double eta = 0.0;
  for (auto _ : bench) {
    SpecimenRuns store(triaxial, static_cast<int>(bench.range(1)));
    const CalibrationResult r = calibrate_softening_factor(curve, store, settings);
    if (!fast) store.run_all(std::vector<double>{2.5, 15.0});  // the compare_eta the scene draws
    runs = store.runs();
    eta = r.eta;
  }
  bench.counters["eta"] = eta;
  bench.counters["specimen_runs"] = runs;
}
BENCHMARK(BM_MeshedCalibration)
    ->ArgNames({"fast", "threads"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
