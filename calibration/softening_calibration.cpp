#include "calibration/softening_calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

#include <ceres/cost_function.h>
#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/types.h>

#include "calibration/monotone_crossing.hpp"

namespace ffp {

double dissipated_work_J(const std::vector<double>& axial_strain, const std::vector<double>& deviatoric_stress_Pa,
                         const TriaxialSpecimen& specimen, double from, double to) {
  // ∫ F dδ with F = qA, δ = ε_a H: the same trapezoid as on the F–δ points, scaled by V = AH.
  return specimen.volume_m3() * area_under(axial_strain, deviatoric_stress_Pa, from, to);
}

double peak_friction_from_peak_q(double peak_q_Pa, double cell_pressure_Pa) {
  if (!(peak_q_Pa > 0.0 && cell_pressure_Pa > 0.0))
    throw std::invalid_argument("peak_friction_from_peak_q: needs q_peak > 0 and σ3 > 0");
  // σ1/σ3 = N at the peak with c' = 0: q = σ3 (N − 1), sin φ = (N − 1)/(N + 1).
  const double n = 1.0 + peak_q_Pa / cell_pressure_Pa;
  return std::asin((n - 1.0) / (n + 1.0));
}

namespace {

using Clock = std::chrono::steady_clock;

std::string format(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

/// Residuals of one scalar parameter x = ln η, with a Jacobian of fixed
/// absolute step in x (Ceres' own numeric differences scale the step with |x|,
/// which vanishes at η = 1): central differences, or the secant to a run
/// already made. The last point evaluated is cached with its Jacobian: Ceres
/// evaluates a trial step, then asks for the Jacobian at it once accepted, and
/// again before it reports convergence (measured: 5 numerical triaxials per
/// iteration without the Jacobian cached, 3 with; the runs are memoised as well).
/// The step is the settings' derivative_step: 1e-4 for the element test gives a
/// truncation error ~1e-8 relative, while W's rounding (Newton stops at 1e-10 of
/// the stress) perturbs the slope by ~1e-6 at most.
class LogEtaCost final : public ceres::CostFunction {
 public:
  using Residuals = std::function<bool(double x, double* residuals)>;
  /// Makes the runs at x − h and x + h side by side (a failure is left for Residuals to meet).
  using Prefetch = std::function<void(double x_minus, double x_plus)>;
  /// A run already made to draw the secant to: its x (at least h from `x`) and
  /// residuals; false if there is none.
  using SecantPartner = std::function<bool(double x, double& x_partner, double* residuals)>;

  LogEtaCost(int residual_count, double step, Residuals residuals, Prefetch prefetch, SecantPartner partner)
      : step_(step),
        residuals_(std::move(residuals)),
        prefetch_(std::move(prefetch)),
        partner_(std::move(partner)),
        cache_(static_cast<std::size_t>(residual_count)) {
    set_num_residuals(residual_count);
    mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double x = parameters[0][0];
    if (!(has_cache_ && x == cached_x_)) {
      has_cache_ = has_jacobian_ = false;
      if (!residuals_(x, cache_.data())) return false;
      cached_x_ = x;
      has_cache_ = true;
    }
    std::copy(cache_.begin(), cache_.end(), residuals);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      if (!has_jacobian_ && !(partner_ ? secant(x) : central(x))) return false;
      std::copy(jacobian_.begin(), jacobian_.end(), jacobians[0]);
    }
    return true;
  }

 private:
  // dr/dx ≈ (r(x + h) − r(x − h)) / 2h.
  bool central(double x) const {
    std::vector<double> plus(cache_.size()), minus(cache_.size());
    if (prefetch_) prefetch_(x - step_, x + step_);
    if (!residuals_(x + step_, plus.data()) || !residuals_(x - step_, minus.data())) return false;
    jacobian_.resize(cache_.size());
    for (std::size_t i = 0; i < cache_.size(); ++i) jacobian_[i] = (plus[i] - minus[i]) / (2.0 * step_);
    has_jacobian_ = true;
    return true;
  }

  // dr/dx ≈ (r(x_k) − r(x)) / (x_k − x) through a run x_k already made, else x_k = x + h.
  bool secant(double x) const {
    std::vector<double> other(cache_.size());
    double x_other = x + step_;
    if (!partner_(x, x_other, other.data()) && !residuals_(x_other, other.data())) return false;
    jacobian_.resize(cache_.size());
    for (std::size_t i = 0; i < cache_.size(); ++i) jacobian_[i] = (other[i] - cache_[i]) / (x_other - x);
    has_jacobian_ = true;
    return true;
  }

  double step_;
  Residuals residuals_;
  Prefetch prefetch_;
  SecantPartner partner_;
  mutable std::vector<double> cache_;
  mutable std::vector<double> jacobian_;
  mutable double cached_x_ = 0.0;
  mutable bool has_cache_ = false;
  mutable bool has_jacobian_ = false;
};

/// Stops Ceres after the iteration in which the numerical triaxial threw.
class AbortOnPendingException final : public ceres::IterationCallback {
 public:
  explicit AbortOnPendingException(const std::exception_ptr& pending) : pending_(pending) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return pending_ ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const std::exception_ptr& pending_;
};

/// Ends the fit once the work residual r = (W_model − W_lab)/W_lab is within the
/// tolerance (cost = r²/2 at the current point).
class StopWithinWorkTolerance final : public ceres::IterationCallback {
 public:
  explicit StopWithinWorkTolerance(double tolerance) : tolerance_(tolerance) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    return std::sqrt(2.0 * summary.cost) <= tolerance_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  double tolerance_;
};

class Calibration {
 public:
  Calibration(const LabCurve& lab, SpecimenRuns& runs, const CalibrationSettings& settings)
      : lab_(lab), runs_(runs), settings_(settings) {
    from_ = lab.axial_strain.front();
    to_ = lab.axial_strain.back();
    work_lab_ = dissipated_work_J(lab.axial_strain, lab.deviatoric_stress_Pa, settings.specimen, from_, to_);
    q_scale_ = lab.peak_q_Pa();
  }

  CalibrationResult run() {
    const auto start = Clock::now();
    const int runs_before = runs_.runs(), reuses_before = runs_.reuses();
    CalibrationResult result;
    result.mode = settings_.mode;
    result.dissipated_work_lab_J = work_lab_;
    result.displacement_range_m[0] = from_ * settings_.specimen.height_m;
    result.displacement_range_m[1] = to_ * settings_.specimen.height_m;
    if (!(work_lab_ > 0.0))
      throw CalibrationFailure(lab_.source + ": the lab curve's dissipated work is " + format(work_lab_) +
                               " J; it must be > 0 to be matched");

    scan(result);
    // The bracket check runs whatever the start: it is what says W_lab can be matched at all.
    const double x_scan = settings_.mode == CalibrationMode::dissipated_work ? work_start(result) : curve_start(result);
    const double x_start = settings_.eta_start ? std::log(*settings_.eta_start) : x_scan;

    const int residual_count =
        settings_.mode == CalibrationMode::dissipated_work ? 1 : static_cast<int>(lab_.axial_strain.size());
    auto residuals = [this](double x, double* r) {
      try {
        residuals_of(evaluate(nearby_run(std::exp(x))), r);
        return true;
      } catch (const PointIntegrationFailure&) {
        // A trial η the element test cannot integrate: Ceres rejects the step and shrinks the region.
        return false;
      } catch (...) {
        // Anything else (bad configuration, an interrupt) ends the fit and is rethrown after it.
        if (!pending_) pending_ = std::current_exception();
        return false;
      }
    };

    // Runs that fail here are run again (and reported) by `residuals`.
    auto prefetch = [this](double x_minus, double x_plus) {
      try {
        const double etas[] = {std::exp(x_minus), std::exp(x_plus)};
        runs_.run_all(etas);
      } catch (...) {
      }
    };
    auto partner = [this](double x, double& x_partner, double* r) {
      const double* eta = secant_partner(x);
      if (eta == nullptr) return false;
      x_partner = std::log(*eta);
      try {
        residuals_of(evaluate(*eta), r);  // made already: no run
        return true;
      } catch (...) {
        return false;
      }
    };
    double x = x_start;
    ceres::Problem problem;
    problem.AddResidualBlock(
        settings_.derivative == FitDerivative::secant
            ? new LogEtaCost(residual_count, settings_.derivative_step, residuals, nullptr, partner)
            : new LogEtaCost(residual_count, settings_.derivative_step, residuals, prefetch, nullptr),
        nullptr, &x);
    problem.SetParameterLowerBound(&x, 0, std::log(settings_.eta_min));
    problem.SetParameterUpperBound(&x, 0, std::log(settings_.eta_max));
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.logging_type = ceres::SILENT;
    options.minimizer_progress_to_stdout = false;
    options.max_num_iterations = settings_.max_iterations;
    options.num_threads = 1;
    // η to 1e-8 relative by default: far below what the element test resolves (W to
    // ~1e-5 at 1000 increments); a noisy (MPM) specimen sets a coarser tolerance.
    // The curve criterion is a large-residual problem on which Gauss-Newton
    // converges only linearly (~×0.3 per step) until the cost's relative changes
    // reach the model's rounding (~1e-11: Newton stops at 1e-10 of the stress);
    // the function tolerance stops it there instead of letting it shrink the trust
    // region on noise.
    options.parameter_tolerance = settings_.parameter_tolerance;
    options.function_tolerance = 1e-10;
    options.gradient_tolerance = 1e-16;
    // With bounds, Ceres follows each trust-region step by a projected Armijo line search
    // (trust_region_minimizer.cc, DoLineSearch) whose trial points are runs of their own. On
    // a specimen whose W jitters (the MPM's, ±2e-3 at 0.5 cm) Armijo fails on noise and
    // each rejected step cost up to 3 extra runs (measured: 16 runs in 5 iterations at
    // 0.5 cm). The secant path drops it: a rejected step shrinks the region, one run each.
    // The central path keeps Ceres' default, as the element test's fits have always run.
    if (settings_.derivative == FitDerivative::secant) options.max_num_line_search_step_size_iterations = 0;
    AbortOnPendingException abort(pending_);
    options.callbacks.push_back(&abort);
    StopWithinWorkTolerance within(settings_.work_tolerance);
    if (settings_.mode == CalibrationMode::dissipated_work && settings_.work_tolerance > 0.0)
      options.callbacks.push_back(&within);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    if (pending_) std::rethrow_exception(pending_);

    result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
    result.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
    result.converged =
        summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
    if (summary.termination_type == ceres::FAILURE || !std::isfinite(x))
      throw CalibrationFailure("the fit of η failed: " + result.termination);

    result.eta = nearby_run(std::exp(x));  // the run Ceres' last point took
    const double x_fit = std::log(result.eta);
    result.at_bound =
        std::abs(x_fit - std::log(settings_.eta_min)) < 1e-6 || std::abs(x_fit - std::log(settings_.eta_max)) < 1e-6;
    result.fitted = evaluate(result.eta);
    result.dissipated_work_model_J = work_of(result.fitted);
    result.relative_work_residual = (result.dissipated_work_model_J - work_lab_) / work_lab_;
    result.plastic_work_model_J = result.fitted.plastic_work_J;
    std::vector<double> r(lab_.axial_strain.size());
    curve_residuals(result.fitted, r.data());
    double squares = 0.0;
    for (double v : r) squares += v * v;
    result.rms_q_error_Pa = q_scale_ * std::sqrt(squares / static_cast<double>(r.size()));
    result.model_runs = runs_.runs() - runs_before;
    result.reused_runs = runs_.reuses() - reuses_before;
    result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  }

 private:
  const SpecimenCurve& evaluate(double eta) {
    const SpecimenCurve& curve = runs_.at(eta);
    const std::size_t n = curve.axial_strain.size();
    if (n < 2 || curve.deviatoric_stress_Pa.size() != n)
      throw CalibrationFailure("the numerical triaxial returned " + std::to_string(n) +
                               " points (needs ≥ 2, with as many stresses as strains)");
    const double slack = 1e-12 * std::max(1.0, to_);
    if (curve.axial_strain.front() > from_ + slack || curve.axial_strain.back() < to_ - slack)
      throw CalibrationFailure("the numerical triaxial covers ε_a ∈ [" + format(curve.axial_strain.front()) + ", " +
                               format(curve.axial_strain.back()) + "], not the lab's [" + format(from_) + ", " +
                               format(to_) + "]: run it to the lab's last strain");
    return curve;
  }

  void residuals_of(const SpecimenCurve& curve, double* r) const {
    if (settings_.mode == CalibrationMode::dissipated_work) {
      r[0] = (work_of(curve) - work_lab_) / work_lab_;
    } else {
      curve_residuals(curve, r);
    }
  }

  /// The η of the run made nearest to η within the reuse radius in ln η, else η itself.
  double nearby_run(double eta) const {
    if (!(settings_.reuse_radius_ln_eta > 0.0) || runs_.has(eta)) return eta;
    double best = eta, best_distance = settings_.reuse_radius_ln_eta;
    for (const auto& [made, curve] : runs_.curves()) {
      const double distance = std::abs(std::log(made / eta));
      if (distance <= best_distance) {
        best = made;
        best_distance = distance;
      }
    }
    return best;
  }

  /// The η of the run nearest to ln η = x among those at least h away (null: none).
  const double* secant_partner(double x) const {
    const double* best = nullptr;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const auto& [eta, curve] : runs_.curves()) {
      const double distance = std::abs(std::log(eta) - x);
      if (distance >= settings_.derivative_step * (1.0 - 1e-9) && distance < best_distance) {
        best = &eta;
        best_distance = distance;
      }
    }
    return best;
  }

  double work_of(const SpecimenCurve& curve) const {
    return dissipated_work_J(curve.axial_strain, curve.deviatoric_stress_Pa, settings_.specimen, from_, to_);
  }

  void curve_residuals(const SpecimenCurve& curve, double* r) const {
    for (std::size_t i = 0; i < lab_.axial_strain.size(); ++i) {
      const double eps = std::clamp(lab_.axial_strain[i], curve.axial_strain.front(), curve.axial_strain.back());
      r[i] = (interpolate_linear(curve.axial_strain, curve.deviatoric_stress_Pa, eps) - lab_.deviatoric_stress_Pa[i]) /
             q_scale_;
    }
  }

  void scan(CalibrationResult& result) {
    std::vector<double> etas;
    if (settings_.scan == WorkScan::bounds) {
      const int n = settings_.scan_points;
      const double lo = std::log(settings_.eta_min), hi = std::log(settings_.eta_max);
      for (int k = 0; k < n; ++k) etas.push_back(std::exp(lo + (hi - lo) * k / (n - 1)));
      etas.front() = settings_.eta_min;  // exactly the bounds, not their rounded exp(log)
      etas.back() = settings_.eta_max;
    } else {
      etas.push_back(settings_.bracket_start_eta.value_or(
          settings_.eta_start.value_or(std::sqrt(settings_.eta_min * settings_.eta_max))));
    }
    for (double eta : settings_.scan_extra_eta)
      if (eta >= settings_.eta_min && eta <= settings_.eta_max) etas.push_back(eta);
    std::sort(etas.begin(), etas.end());
    etas.erase(std::unique(etas.begin(), etas.end()), etas.end());
    runs_.run_all(etas);  // side by side
    if (settings_.scan == WorkScan::bracket) widen_until_bracketed(etas);
    std::vector<double> r(lab_.axial_strain.size());
    for (double eta : etas) {
      WorkSample s;
      s.eta = eta;
      const SpecimenCurve& curve = evaluate(s.eta);
      s.work_J = work_of(curve);
      curve_residuals(curve, r.data());
      for (double v : r) s.sum_of_squares += v * v;
      result.scan.push_back(s);
    }
    result.work_decreases_with_eta = true;
    for (std::size_t k = 1; k < result.scan.size(); ++k)
      if (!(result.scan[k].work_J < result.scan[k - 1].work_J)) result.work_decreases_with_eta = false;
  }

  /// WorkScan::bracket: one run at a time outward from the runs in `etas` (ascending)
  /// until two of them straddle W_lab or the bound on the side it lies is run.
  /// W decreases with η: W_lab above every run's W lies at smaller η, below at larger.
  void widen_until_bracketed(std::vector<double>& etas) {
    const double max_step = std::log(4.0), min_step = 0.1;
    for (;;) {
      std::vector<double> w;
      for (double eta : etas) w.push_back(work_of(evaluate(eta)));
      const bool above_all = work_lab_ > *std::max_element(w.begin(), w.end());
      const bool below_all = work_lab_ < *std::min_element(w.begin(), w.end());
      if (!above_all && !below_all) return;
      // The edge run on W_lab's side and its neighbour; the bound ends the search.
      const std::size_t n = etas.size();
      const std::size_t edge = below_all ? n - 1 : 0;
      const double bound = below_all ? settings_.eta_max : settings_.eta_min;
      if (etas[edge] == bound) return;  // work_start reports W_lab beyond the bound
      const double direction = below_all ? 1.0 : -1.0;
      const double x_edge = std::log(etas[edge]);
      double step = max_step;
      if (n >= 2) {
        // The secant through the edge and its neighbour, continued to W_lab (when it
        // decreases, as W must); half as far again so that the next run lies past it.
        const std::size_t next_in = below_all ? n - 2 : 1;
        const double slope = (w[edge] - w[next_in]) / (x_edge - std::log(etas[next_in]));
        if (slope < 0.0) step = std::clamp(1.5 * direction * (work_lab_ - w[edge]) / slope, min_step, max_step);
      }
      const double x_next = x_edge + direction * step;
      const double eta = below_all ? (x_next >= std::log(bound) ? bound : std::exp(x_next))
                                   : (x_next <= std::log(bound) ? bound : std::exp(x_next));
      runs_.at(eta);
      etas.insert(below_all ? etas.end() : etas.begin(), eta);
    }
  }

  /// ln η where the scan's W crosses W_lab: the monotone cubic through W(ln η) at the
  /// scan's points (calibration/monotone_crossing.hpp).
  double work_start(const CalibrationResult& result) const {
    const WorkSample& slowest = result.scan.front();
    const WorkSample& fastest = result.scan.back();
    const std::string bounds = "η ∈ [" + format(settings_.eta_min) + ", " + format(settings_.eta_max) + "]";
    // The bounds' scan asks its ends; the bracket's, any two runs (its widening stops once
    // two straddle W_lab, or at the bound, which is then an end).
    double most = std::max(slowest.work_J, fastest.work_J), least = std::min(slowest.work_J, fastest.work_J);
    if (settings_.scan == WorkScan::bracket)
      for (const WorkSample& s : result.scan) {
        most = std::max(most, s.work_J);
        least = std::min(least, s.work_J);
      }
    if (work_lab_ > most)
      throw CalibrationFailure("the lab curve dissipates W_lab = " + format(work_lab_) +
                               " J, more than the model with " + "the slowest softening, W(η = " + format(slowest.eta) +
                               ") = " + format(slowest.work_J) + " J: no " + bounds +
                               " matches it (check E', φ'_p, φ'_c and ψ against the lab curve)");
    if (work_lab_ < least)
      throw CalibrationFailure("the lab curve dissipates W_lab = " + format(work_lab_) +
                               " J, less than the model with " + "the fastest softening, W(η = " + format(fastest.eta) +
                               ") = " + format(fastest.work_J) + " J: no " + bounds +
                               " matches it (check E', φ'_p, φ'_c and ψ against the lab curve)");
    std::vector<double> x, w;
    for (const WorkSample& s : result.scan) {
      x.push_back(std::log(s.eta));
      w.push_back(s.work_J);
    }
    return monotone_crossing(x, w, work_lab_);  // two runs straddle W_lab: a crossing exists
  }

  double curve_start(const CalibrationResult& result) const {
    const auto best =
        std::min_element(result.scan.begin(), result.scan.end(),
                         [](const WorkSample& a, const WorkSample& b) { return a.sum_of_squares < b.sum_of_squares; });
    return std::log(best->eta);
  }

  const LabCurve& lab_;
  SpecimenRuns& runs_;
  const CalibrationSettings& settings_;
  double from_ = 0.0, to_ = 0.0;
  double work_lab_ = 0.0;
  double q_scale_ = 1.0;
  std::exception_ptr pending_;
};

}  // namespace

CalibrationResult calibrate_softening_factor(const LabCurve& lab, const NumericalTriaxial& triaxial,
                                             const CalibrationSettings& settings) {
  if (!triaxial) throw std::invalid_argument("calibrate_softening_factor: no numerical triaxial");
  SpecimenRuns runs(triaxial);
  return calibrate_softening_factor(lab, runs, settings);
}

CalibrationResult calibrate_softening_factor(const LabCurve& lab, SpecimenRuns& runs,
                                             const CalibrationSettings& settings) {
  if (!(settings.eta_min > 0.0 && settings.eta_max > settings.eta_min))
    throw std::invalid_argument("calibrate_softening_factor: needs 0 < eta_min < eta_max");
  if (settings.scan_points < 2) throw std::invalid_argument("calibrate_softening_factor: scan_points must be ≥ 2");
  if (settings.scan == WorkScan::bracket && settings.mode != CalibrationMode::dissipated_work)
    throw std::invalid_argument("calibrate_softening_factor: the bracket scan needs the dissipated_work mode");
  if (settings.max_iterations < 1)
    throw std::invalid_argument("calibrate_softening_factor: max_iterations must be ≥ 1");
  if (!(settings.derivative_step > 0.0 && settings.derivative_step <= 0.5))
    throw std::invalid_argument("calibrate_softening_factor: derivative_step must be in (0, 0.5]");
  if (!(settings.parameter_tolerance > 0.0 && settings.parameter_tolerance < 1.0))
    throw std::invalid_argument("calibrate_softening_factor: parameter_tolerance must be in (0, 1)");
  if (!(settings.work_tolerance >= 0.0 && settings.work_tolerance < 1.0))
    throw std::invalid_argument("calibrate_softening_factor: work_tolerance must be in [0, 1)");
  if (settings.eta_start && !(*settings.eta_start >= settings.eta_min && *settings.eta_start <= settings.eta_max))
    throw std::invalid_argument("calibrate_softening_factor: eta_start must lie in [eta_min, eta_max]");
  if (settings.bracket_start_eta &&
      !(*settings.bracket_start_eta >= settings.eta_min && *settings.bracket_start_eta <= settings.eta_max))
    throw std::invalid_argument("calibrate_softening_factor: bracket_start_eta must lie in [eta_min, eta_max]");
  check_lab_curve(lab);
  return Calibration(lab, runs, settings).run();
}

}  // namespace ffp
