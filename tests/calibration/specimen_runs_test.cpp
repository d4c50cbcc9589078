/// No η is run twice (calibration/specimen_runs.hpp), and the meshed
/// calibration's cheaper path — scan start, secant slopes, compare_eta in the
/// scan — finds the η the central-difference fit from material.eta finds.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "calibration/mpm_triaxial_specimen.hpp"
#include "calibration/softening_calibration.hpp"
#include "calibration/specimen_runs.hpp"
#include "models/math_constants.hpp"

using namespace ffp;

namespace {

/// q = [q_r + (q_p − q_r) exp(−η ε)]·(1 − exp(−ε/ε0)) on 201 points to ε = 0.2:
/// W strictly decreasing in η, cheap, exact.
SpecimenCurve closed_form(double eta) {
  const double q_p = 6000.0, q_r = 4000.0;
  SpecimenCurve c;
  for (int i = 0; i <= 200; ++i) {
    const double e = 0.2 * i / 200.0;
    c.axial_strain.push_back(e);
    c.deviatoric_stress_Pa.push_back((q_r + (q_p - q_r) * std::exp(-eta * e)) * (1.0 - std::exp(-e / 0.002)));
  }
  return c;
}

/// Counts the calls per η (from any thread).
struct CallLog {
  std::mutex mutex;
  std::map<double, int> calls;
  NumericalTriaxial counted(NumericalTriaxial triaxial) {
    return [this, triaxial](double eta) {
      {
        const std::lock_guard lock(mutex);
        ++calls[eta];
      }
      return triaxial(eta);
    };
  }
  int total() const {
    int n = 0;
    for (const auto& [eta, k] : calls) n += k;
    return n;
  }
  int most_calls_of_one_eta() const {
    int most = 0;
    for (const auto& [eta, k] : calls) most = std::max(most, k);
    return most;
  }
};

StrainSofteningParameters dr15_sand() {
  StrainSofteningParameters p;
  p.elastic = {5e6, 0.33};
  p.friction_peak_rad = 40.0 * kDegree;
  p.friction_residual_rad = 32.0 * kDegree;
  p.dilatancy_peak_rad = 5.0 * kDegree;
  p.softening_factor = 8.0;
  return p;
}

/// W_lab of a lab curve, as the calibration integrates it (the default specimen).
double lab_work(const LabCurve& lab) {
  return dissipated_work_J(lab.axial_strain, lab.deviatoric_stress_Pa, TriaxialSpecimen{}, lab.axial_strain.front(),
                           lab.axial_strain.back());
}

}  // namespace

TEST_CASE("specimen runs: each η runs once, side by side or not, with the same curves", "[calibration][runs]") {
  CallLog log;
  SpecimenRuns serial(log.counted(closed_form), 1);
  SpecimenRuns parallel(closed_form, 3);
  const std::vector<double> etas = {0.5, 2.0, 8.0, 2.0, 32.0};
  serial.run_all(etas);
  parallel.run_all(etas);
  CHECK(serial.runs() == 4);
  CHECK(parallel.runs() == 4);
  CHECK(log.most_calls_of_one_eta() == 1);
  for (double eta : etas) {
    CHECK(parallel.has(eta));
    CHECK(parallel.at(eta).deviatoric_stress_Pa == serial.at(eta).deviatoric_stress_Pa);
  }
  CHECK(serial.runs() == 4);  // the at() above were all reuses
  CHECK(serial.reuses() == 5);
  CHECK(log.total() == 4);
}

TEST_CASE("specimen runs: a failing η is rethrown after the batch, the others are kept", "[calibration][runs]") {
  std::atomic<int> calls{0};
  SpecimenRuns runs(
      [&](double eta) {
        ++calls;
        if (eta == 3.0) throw std::runtime_error("η = 3 failed");
        return closed_form(eta);
      },
      2);
  const std::vector<double> etas = {1.0, 3.0, 9.0};
  CHECK_THROWS_WITH(runs.run_all(etas), "η = 3 failed");
  CHECK(calls == 3);
  CHECK(runs.runs() == 2);
  CHECK(runs.has(1.0));
  CHECK(runs.has(9.0));
  CHECK_FALSE(runs.has(3.0));
}

TEST_CASE("calibration: no η runs twice, and the fitted curve is a run the fit made", "[calibration][runs]") {
  const SpecimenCurve truth = closed_form(6.0);
  const LabCurve lab{"closed form", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
  for (FitDerivative derivative : {FitDerivative::central, FitDerivative::secant}) {
    CAPTURE(to_string(derivative));
    CallLog log;
    SpecimenRuns runs(log.counted(closed_form));
    CalibrationSettings s;
    s.derivative = derivative;
    s.derivative_step = 0.1;
    s.eta_start = 40.0;
    s.scan_extra_eta = {2.5, 15.0, 1e4};  // 1e4 lies outside the bounds: not scanned
    const CalibrationResult r = calibrate_softening_factor(lab, runs, s);
    CHECK(r.eta == Approx(6.0).epsilon(1e-6));
    CHECK(log.most_calls_of_one_eta() == 1);
    CHECK(r.model_runs == log.total());
    CHECK(r.reused_runs >= 1);  // at least the fitted η's curve
    CHECK(r.scan.size() == 11);
    CHECK(log.calls.contains(2.5));
    CHECK(log.calls.contains(15.0));
    CHECK_FALSE(log.calls.contains(1e4));
    // A second fit on the same runs makes only the runs the first did not.
    const int before = log.total();
    CalibrationSettings other = s;
    other.mode = CalibrationMode::curve_least_squares;
    const CalibrationResult second = calibrate_softening_factor(lab, runs, other);
    CHECK(second.model_runs == log.total() - before);
    CHECK(second.model_runs < r.model_runs);  // its 11-point scan was all reused
    CHECK(log.most_calls_of_one_eta() == 1);
  }
}

TEST_CASE("calibration: the secant from the scan's crossing needs fewer runs than central differences from η = 8",
          "[calibration][runs]") {
  // The closed form is smooth: both stop on Ceres' tolerances at the same root.
  const SpecimenCurve truth = closed_form(6.0);
  const LabCurve lab{"closed form", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
  CalibrationSettings central;
  central.derivative_step = 0.1;
  central.parameter_tolerance = 1e-4;
  central.work_tolerance = 2e-4;
  central.eta_start = 40.0;
  CalibrationSettings secant = central;
  secant.eta_start.reset();
  secant.derivative = FitDerivative::secant;
  secant.scan_points = 3;
  secant.scan_extra_eta = {2.5, 15.0};
  const CalibrationResult a = calibrate_softening_factor(lab, closed_form, central);
  const CalibrationResult b = calibrate_softening_factor(lab, closed_form, secant);
  INFO("central: " << a.model_runs << " runs, η = " << a.eta << "; secant: " << b.model_runs << " runs, η = " << b.eta);
  // |r| ≤ 2e-4 with dW/d ln η ≈ −0.05 W here: η within ~0.4 % of 6 each.
  CHECK(a.eta == Approx(6.0).epsilon(5e-3));
  CHECK(b.eta == Approx(6.0).epsilon(5e-3));
  CHECK(std::abs(b.relative_work_residual) <= 2e-4);
  CHECK(b.model_runs <= a.model_runs / 2);
}

TEST_CASE("meshed calibration at 2 cm: the fast path finds the specimen's own η within 1 % in a few runs",
          "[calibration][runs][mpm]") {
  // The 2 cm specimen (64 particles; W jitters ~1e-5 between neighbouring η) fitted to its
  // own curve at η = 66, so the root is 66 (measured: the central-difference fit from
  // η = 50 after a 9-point scan of [20, 200] finds 66.0001 in 18 runs). The fast path:
  // 3-point scan plus two extra η, the cubic's crossing, secant slopes. It stops at
  // |W/W_lab − 1| ≤ 2e-4, and W changes by ~4 % per unit ln η near the match: within
  // ~0.5 % of the root.
  MpmTriaxialConfig config;
  config.cell_m = 0.02;
  const NumericalTriaxial specimen = mpm_triaxial_specimen(dr15_sand(), config);
  const SpecimenCurve truth = specimen(66.0);
  const LabCurve lab{"2 cm specimen at η = 66", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
  CalibrationSettings s;
  s.eta_min = 20.0;
  s.eta_max = 200.0;
  s.derivative_step = 0.1;
  s.parameter_tolerance = 1e-4;
  s.work_tolerance = 2e-4;
  s.derivative = FitDerivative::secant;
  s.scan_points = 3;
  s.scan_extra_eta = {30.0, 100.0};
  SpecimenRuns runs(specimen, 2);
  const CalibrationResult r = calibrate_softening_factor(lab, runs, s);
  INFO(r.model_runs << " runs, η = " << r.eta);
  CHECK(r.eta == Approx(66.0).epsilon(0.01));
  CHECK(std::abs(r.relative_work_residual) <= 2e-4);
  CHECK(r.model_runs <= 8);  // 5 scan runs, then one per iteration (measured: 6)
}

TEST_CASE("calibration with secants on a jittery specimen: no run within the reuse radius of another, a few runs",
          "[calibration][runs]") {
  // The 0.5 cm specimen's W jitters by up to ±2e-3 from one η to the next: here q is
  // scaled by 1 + 2e-3·sin(1e4 ln η + phase), ten phases. Near the root the closed
  // form's W changes by ~5 % per unit ln η, so the jitter blurs the root over
  // ±0.04 in ln η (±4 % in η): what any fit can promise. Measured before the reuse
  // radius: 11 to 29 runs (Ceres' projected line search and its shrinking steps made
  // a run each, 1e-5 apart in ln η); with it, 6 to 8.
  for (int phase = 0; phase < 10; ++phase) {
    CAPTURE(phase);
    auto jitter = [phase](double eta) { return 1.0 + 2e-3 * std::sin(1e4 * std::log(eta) + phase); };
    CallLog log;
    const NumericalTriaxial jittery = log.counted([&](double eta) {
      SpecimenCurve c = closed_form(eta);
      for (double& q : c.deviatoric_stress_Pa) q *= jitter(eta);
      return c;
    });
    const SpecimenCurve truth = closed_form(6.0);
    const LabCurve lab{"closed form", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
    CalibrationSettings s;
    s.derivative = FitDerivative::secant;
    s.derivative_step = 0.1;
    s.parameter_tolerance = 1e-4;
    s.work_tolerance = 2e-4;
    s.scan_points = 3;
    s.scan_extra_eta = {2.5, 15.0};
    s.reuse_radius_ln_eta = 0.005;
    SpecimenRuns runs(jittery);
    const CalibrationResult r = calibrate_softening_factor(lab, runs, s);
    INFO(r.model_runs << " runs, " << r.iterations << " iterations, η = " << r.eta
                      << ", r = " << r.relative_work_residual << ": " << r.termination);
    CHECK(r.model_runs <= 5 + 4);
    CHECK(r.eta == Approx(6.0).epsilon(0.04));
    CHECK(runs.has(r.eta));  // the fitted η is a run's
    double previous = -INFINITY;
    for (const auto& [eta, calls] : log.calls) {
      CHECK(std::log(eta) - previous > 0.005);
      previous = std::log(eta);
    }
  }
}

TEST_CASE("bracket scan: from a start near the root, two more runs straddle W_lab and the fit finds the bounds' η",
          "[calibration][runs][bracket]") {
  // Root η = 6. The bounds' scan runs 0.1, 7.07, 500 and the extra 15; the bracket runs the
  // start and the extra 15 (both past the root: W below W_lab), then one step down along
  // their secant, past the crossing it predicts.
  const SpecimenCurve truth = closed_form(6.0);
  const LabCurve lab{"closed form", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
  CalibrationSettings bounds;
  bounds.derivative = FitDerivative::secant;
  bounds.derivative_step = 0.1;
  bounds.parameter_tolerance = 1e-4;
  bounds.work_tolerance = 2e-4;
  bounds.scan_points = 3;
  bounds.scan_extra_eta = {15.0};
  CalibrationSettings bracket = bounds;
  bracket.scan = WorkScan::bracket;
  bracket.bracket_start_eta = 7.0;
  const CalibrationResult a = calibrate_softening_factor(lab, closed_form, bounds);
  const CalibrationResult b = calibrate_softening_factor(lab, closed_form, bracket);
  INFO("bounds: " << a.model_runs << " runs, η = " << a.eta << "; bracket: " << b.model_runs << " runs, η = " << b.eta);
  REQUIRE(b.scan.size() == 3);  // 7, 15 and one step down
  CHECK(b.scan[0].eta < 6.0);   // the step went past the root
  CHECK(b.scan[0].work_J > lab_work(lab));
  CHECK(b.work_decreases_with_eta);
  // |r| ≤ 2e-4 with dW/d ln η ≈ −0.05 W here: each within ~0.4 % of 6.
  CHECK(a.eta == Approx(6.0).epsilon(5e-3));
  CHECK(b.eta == Approx(6.0).epsilon(5e-3));
  CHECK(b.model_runs < a.model_runs);
}

TEST_CASE("bracket scan: a W_lab beyond a bound is found at the bound and refused as with the bounds' scan",
          "[calibration][runs][bracket][errors]") {
  // η = 0.05 softens less than η_min = 0.1 allows: W_lab lies above W(0.1).
  const SpecimenCurve truth = closed_form(0.05);
  const LabCurve lab{"closed form", truth.axial_strain, truth.deviatoric_stress_Pa, {}};
  CalibrationSettings s;
  s.derivative = FitDerivative::secant;
  s.derivative_step = 0.1;
  s.scan = WorkScan::bracket;
  s.bracket_start_eta = 50.0;
  SpecimenRuns runs(closed_form);
  CHECK_THROWS_AS(calibrate_softening_factor(lab, runs, s), CalibrationFailure);
  CHECK(runs.has(0.1));      // it widened down to the bound
  CHECK(runs.runs() <= 10);  // steps of up to ln 4 from 50 to 0.1: ln(500)/ln 4 ≈ 4.5, then the bound
  s.mode = CalibrationMode::curve_least_squares;
  CHECK_THROWS_AS(calibrate_softening_factor(lab, closed_form, s), std::invalid_argument);
}
