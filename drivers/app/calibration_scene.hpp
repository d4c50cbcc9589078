#pragma once
/// Reading a `calibration` scene: the SSMC softening factor η fitted to a lab
/// triaxial curve so that the numerical triaxial dissipates the lab's work
/// (paper section 4.2, Fig. 3; calibration/softening_calibration.hpp).
/// Reading only; calibration_job runs it.
///
/// Scene (geotechnical units, compression positive):
///   lab_curve_csv        the lab curve, relative to the scene file (data/lab/README.md)
///   material             an ssmc material (no density: weightless specimen); its eta
///                        is where the fit starts
///   mode                 dissipated_work (the paper's, default) | curve_least_squares
///   compare_modes        also fit with the other criterion, reported under other_mode (default
///                        true; false with an mpm specimen, where it doubles the cost)
///   fit_peak_friction    replace phi_peak_deg by the lab peak's, asin((N−1)/(N+1)),
///                        N = 1 + q_peak/σ3 (c' = 0 only; default false)
///   eta_min, eta_max     bounds of η (default 0.1, 500)
///   compare_eta          η of the extra curves in the figure (default the paper's [2.5, 15])
///   cell_pressure_kPa    σ3 (default 1.72)
///   specimen             the numerical triaxial, {type, height_m: 0.15, diameter_m: 0.07, ...}:
///     type: element      (default) the single-point element test (drivers/triaxial_test.hpp),
///                        with the top-level keys
///       increments         over the lab's strain range (default 1000)
///       strain_rate_per_s  only the rate law sees it (default 1e-4)
///     type: mpm          the meshed axisymmetric MPM specimen (calibration/mpm_triaxial_specimen.hpp),
///                        whose own keys sit in the specimen object:
///       cell_m              nominal cell size (default 0.01, the paper's FFP mesh)
///       platen_velocity_m_s after the ramp (default 0.01: halving it moves W by < 1 %)
///       platens             rough (default) | smooth
///       shape_function      gimp (default) | linear
///       courant             (default 0.9)
///       flip_fraction       FLIP share of the particle velocity update (default 0.9)
///       particles_per_cell  per direction (default 2)
///       density_kg_m3       sets the time scale only (default 14.6 kN/m³ / g)
///       output_strain_step  ε_a between the curve's points (default 0.001)
///       radial_margin       empty grid beyond the radius, fraction of it (default 0.5)
///                        Each key belongs to one type: an element scene with mpm keys (or
///                        the other way round) is bad input.
///   scan                 the W(η) check before the fit: bounds (default: scan_points log-spaced
///                        η, the bounds included) | bracket (material.eta and the compare_eta,
///                        then a run at a time outward until two runs straddle W_lab; for a
///                        start near the answer, e.g. a coarser mesh's η; dissipated_work only)
///   scan_points          log-spaced η of the W(η) check, the bounds included (default: element
///                        9; mpm 3); the compare_eta inside the bounds are scanned as well
///   fit_start            where Ceres starts: material_eta | scan, where the scan's W crosses
///                        W_lab (log-linear; default: element material_eta; mpm scan)
///   derivative           the fit's dr/d ln η: central (two runs a point) | secant (through the
///                        run made nearest, at least derivative_step_ln_eta away: no run; default:
///                        element central; mpm secant)
///   reuse_radius_ln_eta  a trial η this near (in ln η) to a run made takes that run (default:
///                        element 0, only the same η; mpm 0.005 — below the MPM's jitter)
///   max_iterations       Ceres iterations (default 50)
///   derivative_step_ln_eta  central-difference step of the fit in ln η (default: element
///                        1e-4; mpm 0.1 — the MPM's W jitters by up to ±0.2 % between
///                        neighbouring η at 0.5 cm, and the slope must stand above that)
///   parameter_tolerance  Ceres stops when ln η changes by less (relative; element 1e-8, mpm 1e-4)
///   work_tolerance       dissipated_work: stop once |W_model/W_lab − 1| is below (element 0:
///                        off; mpm 2e-4). Set it near the specimen's jitter in W: tighter
///                        costs runs, looser costs η where W is flat in η (at 2 cm
///                        1e-3 of W is ±20 % of η)
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "calibration/lab_curve.hpp"
#include "calibration/mpm_triaxial_specimen.hpp"
#include "calibration/softening_calibration.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "mpm/model_size.hpp"

namespace ffp {

/// Where the fit starts (`fit_start`).
enum class FitStart { material_eta, scan };
using FitStartName = std::pair<FitStart, std::string_view>;
inline constexpr auto kFitStartNames =
    std::to_array<FitStartName>({{FitStart::material_eta, "material_eta"}, {FitStart::scan, "scan"}});
std::string to_string(FitStart start);

/// The numerical triaxial the calibration fits with (`specimen.type`).
enum class SpecimenType { element, mpm };
using SpecimenTypeName = std::pair<SpecimenType, std::string_view>;
inline constexpr auto kSpecimenTypeNames =
    std::to_array<SpecimenTypeName>({{SpecimenType::element, "element"}, {SpecimenType::mpm, "mpm"}});
std::string to_string(SpecimenType type);

struct CalibrationScene {
  std::filesystem::path lab_file;  ///< resolved against the scene's folder
  LabCurve lab;
  StrainSofteningParameters material;  ///< φ'_p replaced by the lab peak's with fit_peak_friction
  bool fitted_peak_friction = false;
  double eta_start = 8.0;  ///< material.eta (where the fit starts with fit_start = material_eta)
  FitStart fit_start = FitStart::material_eta;
  SpecimenType specimen = SpecimenType::element;
  TriaxialTestConfig test;  ///< the element test (σ3 and the specimen's size serve both types)
  MpmTriaxialConfig mpm;    ///< the MPM specimen (type mpm)
  CalibrationSettings settings;
  bool compare_modes = true;
  std::vector<double> compare_eta;
};

/// Reads every key after kind/name and finish()es the scene. SceneError on bad input.
CalibrationScene read_calibration_scene(SceneReader& scene, const std::filesystem::path& scene_dir);

/// The MPM specimen's size before it is built (for the memory check and `ffp check`).
mpm::ModelSize specimen_size(const MpmTriaxialConfig& m);

/// `v` with `digits` significant digits (%g), as messages and figure labels print it.
std::string format_significant(double v, int digits = 4);

}  // namespace ffp
