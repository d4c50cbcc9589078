#pragma once
/// What an `ffp` or `cpt` run writes besides history.csv, the fields and the
/// summary: the figures of the paper's kind (Figs. 7, 8b,c, 9 and 14a) and, for an
/// ffp run, its deceleration interpreted as a measured drop is (record.csv).
#include <filesystem>
#include <span>
#include <string>

#include "drivers/app/ffp_summary.hpp"
#include "drivers/app/pore_pressure_summary.hpp"
#include "mpm/ffp_model.hpp"
#include "mpm/localisation_map.hpp"

namespace ffp {

/// Fig. 9: the soil's accumulated deviatoric strain with the outline on top,
/// plots/deviatoric_strain_tT.TTT.png at the run's current time.
void write_strain_map(const mpm::FfpRun& run, const std::string& name, double colour_max,
                      const std::filesystem::path& plots);

/// The soil's mean stress p = −tr σ/3 (kPa, compression positive) the same way,
/// plots/mean_stress_tT.TTT.png, coloured from 0 to the 98th percentile of p: the
/// pattern of the pressure around the cone (the bands docs/verification.md#mesh-convergence describes).
void write_pressure_map(const mpm::FfpRun& run, const std::string& name, const std::filesystem::path& plots);

/// A saturated sand's excess pore pressure p − p_h (kPa), plots/excess_pore_pressure_tT.TTT.png,
/// coloured on a scale symmetric about 0 up to the 98th percentile of |p − p_h|.
void write_excess_pore_pressure_map(const mpm::FfpRun& run, const std::string& name,
                                    const std::filesystem::path& plots);

/// With output.localisation: the soil's particles by where their stress sits (inside the
/// yield surface, on a face or an edge and elliptic, at the apex and not evaluated,
/// localised) with the outline, plots/localisation_tT.TTT.png.
void write_localisation_map(const mpm::FfpRun& run, const std::string& name, const mpm::LocalisationMap& map,
                            const std::filesystem::path& plots);

/// One history row of the localisation: the localised share of the particles on a face or an
/// edge, and the counts.
struct LocalisationRow {
  double time_s, fraction, face, edge, apex, localised_face, localised_edge;
};
/// The localised share against time over the counts (on a face, on an edge, localised, at
/// the apex): plots/localisation.png.
void write_localisation_plot(std::span<const LocalisationRow> rows, const std::string& name,
                             const std::filesystem::path& plots);

/// Fig. 7 (plots/time_histories.png: penetration, velocity, deceleration, reaction against time) and
/// Fig. 8b,c (plots/depth_profiles.png: velocity and deceleration against depth).
void write_ffp_plots(std::span<const FfpSample> samples, const std::string& name, const std::filesystem::path& plots);

/// Fig. 14a: the static reaction against depth, plots/reaction_profile.png.
void write_cpt_plot(std::span<const FfpSample> samples, const std::string& name, const std::filesystem::path& plots);

/// A flat punch's pressure–settlement curve normalised, p/c' against s/R, with the plateau
/// mean over its settlement window: plots/pressure_settlement.png.
struct PressureSettlement {
  double base_radius_m = 0.0, base_area_m2 = 0.0, cohesion_Pa = 0.0;
  double from_ratio = 0.0, to_ratio = 0.0;  ///< the plateau's settlement window / R
  double bearing_factor = 0.0;              ///< the plateau mean pressure / c'
};
void write_pressure_settlement_plot(std::span<const FfpSample> samples, const std::string& name,
                                    const PressureSettlement& curve, const std::filesystem::path& plots);

/// The run's deceleration read as a measured record would be (the `record` kind's
/// interpretation): out_dir/record.csv and plots/record_profiles.png, so a simulation
/// and a drop compare column for column.
/// Impact at t = 0 with the scene's impact velocity. On a saturated sand (`u2` one row per
/// sample, else empty) record.csv's pore_pressure_kPa is u2, as a BlueDrop's shoulder sensor reads.
void write_simulated_record(std::span<const FfpSample> samples, const mpm::FfpDescription& model, double mass_kg,
                            const std::string& name, const std::filesystem::path& out_dir,
                            const std::filesystem::path& plots, std::span<const ShoulderPressureRow> u2 = {});

/// Saturated sand: u2, its hydrostatic part (u2 − excess) and the excess against time,
/// plots/pore_pressure.png.
void write_pore_pressure_plot(std::span<const ShoulderPressureRow> rows, const std::string& name,
                              const std::filesystem::path& plots);

}  // namespace ffp
