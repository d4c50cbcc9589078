#pragma once
/// Calibration of the SSMC softening factor η on a lab triaxial curve (paper
/// section 4.2, Fig. 3). Pure numerics: nothing here prints or reads files.
///
/// Two criteria, one parameter, both solved by Ceres on x = ln η with the box
/// ln η_min ≤ x ≤ ln η_max (central numeric differences of the numerical
/// triaxial, or secants through runs already made):
///
/// - dissipated_work (the paper's): the smeared-crack idea (Rots et al. 1985) —
///   the area under the axial force–displacement curve of the numerical
///   specimen equals the lab's, over the lab's displacement range:
///     r(x) = (W_model(e^x) − W_lab) / W_lab,  W = ∫ F dδ = V ∫ q dε_a,
///   each curve integrated by the trapezoid rule on its own points
///   (drivers/triaxial_test.hpp: area_under), F = q·A and δ = ε_a·H with the
///   same specimen for both. Before the fit, W is evaluated on a log-spaced
///   scan of η over the bounds: it must decrease with η (more softening, less
///   area), and W_lab must lie in [W(η_max), W(η_min)], else the curve cannot
///   be matched inside the bounds (CalibrationFailure). Or (WorkScan::bracket)
///   only as far out from the start as it takes for two runs to straddle W_lab.
/// - curve_least_squares (for comparison): r_i = (q_model(ε_i) − q_lab(ε_i)) /
///   q_peak,lab at every lab strain ε_i, the model curve interpolated linearly.
///
/// No η is run twice (calibration/specimen_runs.hpp): the fit's trial points,
/// derivatives and final curve reuse the scan's runs and each other's, and a
/// caller's SpecimenRuns carries them on to a second fit or extra curves.
///
/// W_lab and W_model are both ∫F dδ, the piston's deviatoric work. What the
/// law dissipates (plastic work) differs from it by the elastic energy still
/// stored and by the cell pressure's work on the specimen's volume change
/// (drivers/triaxial_test.hpp); the result reports the model's plastic work
/// beside W for comparison.
#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "calibration/lab_curve.hpp"
#include "calibration/numerical_triaxial.hpp"
#include "calibration/specimen_runs.hpp"
#include "drivers/triaxial_test.hpp"

namespace ffp {

enum class CalibrationMode { dissipated_work, curve_least_squares };
using CalibrationModeName = std::pair<CalibrationMode, std::string_view>;
/// The scene's names of CalibrationMode, in the order messages list them.
inline constexpr auto kCalibrationModeNames =
    std::to_array<CalibrationModeName>({{CalibrationMode::dissipated_work, "dissipated_work"},
                                        {CalibrationMode::curve_least_squares, "curve_least_squares"}});
inline std::string to_string(CalibrationMode mode) {
  return std::string(std::ranges::find(kCalibrationModeNames, mode, &CalibrationModeName::first)->second);
}

/// How the fit gets dr/d ln η at a point x.
enum class FitDerivative {
  /// (r(x + h) − r(x − h)) / 2h: two runs a point (side by side with concurrency).
  central,
  /// The secant through x and the run already made nearest to x but at least h
  /// away (the scan's, the fit's earlier points): no run, unless none is made yet
  /// (then one at x ± h). For a specimen whose runs cost minutes: Ceres then
  /// makes one run per iteration instead of three.
  secant
};
using FitDerivativeName = std::pair<FitDerivative, std::string_view>;
inline constexpr auto kFitDerivativeNames =
    std::to_array<FitDerivativeName>({{FitDerivative::central, "central"}, {FitDerivative::secant, "secant"}});
inline std::string to_string(FitDerivative derivative) {
  return std::string(std::ranges::find(kFitDerivativeNames, derivative, &FitDerivativeName::first)->second);
}

/// Which η the dissipated-work check of W(η) runs before the fit (`scan`).
enum class WorkScan {
  /// scan_points log-spaced η over [η_min, η_max], bounds included, and scan_extra_eta:
  /// W(η) seen over the whole range, whatever the start.
  bounds,
  /// bracket_start_eta (unset: eta_start, else √(η_min η_max)) and scan_extra_eta, then outward steps only while W_lab
  /// is not yet between two runs: a step beyond the outermost run continues the secant
  /// through it and its neighbour past the predicted crossing (by half as far again,
  /// at least 0.1 and at most ln 4 in ln η), clamped to the bound; once the bound
  /// is run and W_lab still lies beyond it, the same CalibrationFailure as `bounds`.
  /// From a start near the answer (e.g. a coarser mesh's η) this runs 1–2 η beyond
  /// the extra ones, where `bounds` runs scan_points. dissipated_work only.
  bracket
};
using WorkScanName = std::pair<WorkScan, std::string_view>;
inline constexpr auto kWorkScanNames =
    std::to_array<WorkScanName>({{WorkScan::bounds, "bounds"}, {WorkScan::bracket, "bracket"}});
inline std::string to_string(WorkScan scan) {
  return std::string(std::ranges::find(kWorkScanNames, scan, &WorkScanName::first)->second);
}

struct CalibrationSettings {
  CalibrationMode mode = CalibrationMode::dissipated_work;
  double eta_min = 0.1;
  double eta_max = 500.0;
  /// Where Ceres starts. Unset: from the scan — where its W crosses W_lab
  /// (log-linear), or its point of least squares for the curve criterion.
  std::optional<double> eta_start;
  WorkScan scan = WorkScan::bounds;
  std::optional<double> bracket_start_eta;  ///< bracket: the first η besides the extra ones
  int scan_points = 9;                      ///< bounds: log-spaced η over [η_min, η_max], ends included (≥ 2)
  /// η the scan runs as well (those inside the bounds): curves the caller draws
  /// anyway (a scene's compare_eta), so their runs also bracket W_lab.
  std::vector<double> scan_extra_eta;
  FitDerivative derivative = FitDerivative::central;
  int max_iterations = 50;  ///< Ceres iterations
  /// Step h in ln η of the central differences (and the secant's least span). It must be large enough that the
  /// numerical triaxial's noise is small against W'·step: the element test's W is
  /// smooth to ~1e-10 (1e-4 is plenty); a dynamic MPM specimen's W jitters from
  /// one η to the next, by ~1e-5 relative at 2 cm and up to ±2e-3 at 0.5 cm,
  /// against W' ≈ 0.04 W per unit ln η near the match (0.1 lifts the slope above it).
  double derivative_step = 1e-4;
  /// A trial η within this distance in ln η of a run already made takes that run (0: only
  /// the same η). Below the specimen's noise a nearer run tells nothing new: at 0.5 cm W
  /// jitters by ±2e-3, i.e. ±0.025 in ln η at W' ≈ 0.08 W per unit ln η, and Ceres, once
  /// a step fails on that noise, shrinks its region to steps of 1e-5 in ln η, a run each.
  /// The fitted η is then the η of the run it took (0.5 % at most from Ceres' point with 0.005).
  double reuse_radius_ln_eta = 0.0;
  /// Ceres' parameter tolerance: the fit stops when a step changes ln η by less
  /// than this (relative). 1e-8 for the element test; an MPM specimen's noise
  /// makes anything below ~1e-4 a random walk.
  double parameter_tolerance = 1e-8;
  /// dissipated_work only: the fit stops as soon as |W_model − W_lab| ≤
  /// work_tolerance·W_lab (0: never; Ceres' tolerances decide). A specimen whose
  /// W jitters by ±0.2 % from one η to the next (the 0.5 cm MPM specimen) has no
  /// better answer than its jitter, and Ceres' step tests, which assume a smooth
  /// cost, may otherwise stop on a trust region shrunk by noise, away from W_lab.
  double work_tolerance = 0.0;
  TriaxialSpecimen specimen;  ///< turns q–ε_a into F–δ, the same for the lab and the model
};

struct WorkSample {
  double eta = 0.0;
  double work_J = 0.0;          ///< W_model(η) over the lab's range
  double sum_of_squares = 0.0;  ///< Σ r_i² of the curve criterion at this η
};

struct CalibrationResult {
  CalibrationMode mode = CalibrationMode::dissipated_work;
  double eta = 0.0;
  double dissipated_work_lab_J = 0.0;
  double dissipated_work_model_J = 0.0;         ///< at the fitted η, over the lab's range
  double relative_work_residual = 0.0;          ///< (W_model − W_lab) / W_lab at the fitted η
  double plastic_work_model_J = 0.0;            ///< the law's V Σ σ:Δε^p at the fitted η (NaN if unknown)
  double rms_q_error_Pa = 0.0;                  ///< model against lab at the lab's strains
  double displacement_range_m[2] = {0.0, 0.0};  ///< the lab's δ range both works cover
  int iterations = 0;                           ///< Ceres iterations (successful + unsuccessful steps)
  int model_runs = 0;        ///< numerical triaxials this fit ran, scan and derivatives included (each η once)
  int reused_runs = 0;       ///< requests answered by a run already made (this fit's or the SpecimenRuns' earlier ones)
  std::string termination;   ///< Ceres' termination type and message
  bool converged = false;    ///< Ceres reported CONVERGENCE (or the work tolerance was met)
  bool at_bound = false;     ///< η within 1e-6 (relative) of η_min or η_max
  double wall_time_s = 0.0;  ///< the whole calibration, scan included
  std::vector<WorkSample> scan;          ///< W(η) on the scan, ascending η (log-spaced and extra η)
  bool work_decreases_with_eta = false;  ///< W strictly decreasing along the scan
  SpecimenCurve fitted;                  ///< the response at the fitted η
};

/// The calibration cannot be done as asked (W_lab outside the bounds' range, the
/// numerical triaxial failing, a response too short for the lab's range, ...).
class CalibrationFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `lab` must pass check_lab_curve. Throws CalibrationFailure, or
/// std::invalid_argument for settings out of range.
CalibrationResult calibrate_softening_factor(const LabCurve& lab, const NumericalTriaxial& triaxial,
                                             const CalibrationSettings& settings);
/// The same, on runs that may have been made already (and that keep this fit's).
CalibrationResult calibrate_softening_factor(const LabCurve& lab, SpecimenRuns& runs,
                                             const CalibrationSettings& settings);

/// W = ∫ F dδ = A·H ∫ q dε_a over ε_a ∈ [from, to], trapezoid on the given points.
double dissipated_work_J(const std::vector<double>& axial_strain, const std::vector<double>& deviatoric_stress_Pa,
                         const TriaxialSpecimen& specimen, double from, double to);

/// φ'_p implied by a peak q at cell pressure σ3 with c' = 0:
/// N = 1 + q_peak/σ3, sin φ'_p = (N − 1)/(N + 1) (the Mohr-Coulomb triaxial-compression peak).
double peak_friction_from_peak_q(double peak_q_Pa, double cell_pressure_Pa);

}  // namespace ffp
