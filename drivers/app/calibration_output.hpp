#pragma once
/// What a calibration run writes: summary.json's figures, history.csv (the lab
/// and the fitted model side by side at the lab's points), model_curve.csv,
/// work_scan.csv and the plots (the paper's Fig. 3, force–displacement and
/// volumetric strain, W against η).
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/app/calibration_scene.hpp"

namespace ffp {

/// What one MPM specimen run cost and how it went (its curve is the calibration's).
struct MpmRunRecord {
  double eta = 0.0;
  long steps = 0;
  double wall_time_s = 0.0;
  double platen_force_imbalance = 0.0;
  double bulge_at_peak[2] = {0.0, 0.0};
  double bulge_at_end[2] = {0.0, 0.0};
  double work_steps_J = 0.0, work_curve_J = 0.0, work_piston_J = 0.0;
  long wall_clamps = 0;
};

/// The MPM specimen's grid, as its runs built it.
struct SpecimenGrid {
  int cells_r = 0, cells_z = 0;
  double cell_r_m = 0.0, cell_z_m = 0.0;
  std::size_t particles = 0;
  double ramp_time_s = 0.0;
};

/// Everything a calibration run found.
struct CalibrationOutcome {
  CalibrationResult result;
  std::optional<CalibrationResult> second;                 ///< the other mode's fit (compare_modes)
  std::vector<std::pair<double, SpecimenCurve>> compared;  ///< the compare_eta curves
  std::vector<MpmRunRecord> runs;                          ///< every MPM specimen run, in order (mpm only)
  SpecimenGrid grid;                                       ///< mpm only
  int specimen_runs = 0;    ///< numerical triaxials run in all (fits and compare_eta; each η once)
  int concurrent_runs = 1;  ///< at most this many side by side
};

void write_calibration_summary(const CalibrationScene& scene, const CalibrationOutcome& outcome,
                               nlohmann::json& summary);
void write_calibration_tables(const CalibrationScene& scene, const CalibrationOutcome& outcome,
                              const std::filesystem::path& out_dir);
void write_calibration_plots(const CalibrationScene& scene, const CalibrationOutcome& outcome,
                             const std::filesystem::path& out_dir);

}  // namespace ffp
