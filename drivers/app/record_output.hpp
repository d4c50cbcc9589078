#pragma once
/// What an interpreted FFP record writes: the same table, summary and plots
/// for a measured drop (`record` kind, history.csv) and for every `ffp` run
/// (record.csv), so both go through one interpretation.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/ffp_record.hpp"
#include "drivers/output/csv_writer.hpp"

namespace ffp {

/// The three rate laws with their usual factors: log K = 0.1, Brilli K = 0.31,
/// asinh K = 0.1 (for v ≫ v_ref it tends to the log law's 1 + K log10(2v/v_ref)).
std::vector<RateCorrection> default_rate_laws();

/// time_s, penetration_m, velocity_m_s, deceleration_g, q_dyn_projected_kPa,
/// q_dyn_mantle_kPa, q_sbc_<law>_kPa for each law, then `extra` columns
/// (one value per row, e.g. pore_pressure_kPa).
CsvTable record_table(const InterpretedRecord& record, const RecordSettings& settings,
                      const std::vector<std::pair<std::string, std::vector<double>>>& extra = {});

/// peak_deceleration_g, depth_of_peak_m, time_of_peak_s, max_penetration_m,
/// final_penetration_m, impact_velocity_m_s, impact_time_s and how each was found.
nlohmann::json record_summary(const InterpretedRecord& record, const RecordSettings& settings);

/// Deceleration, velocity, q_dyn (projected and mantle) and q_sbc (one curve
/// per law) against depth, depth positive downward.
void write_record_plots(const InterpretedRecord& record, const RecordSettings& settings, const std::string& name,
                        const std::filesystem::path& png);

}  // namespace ffp
