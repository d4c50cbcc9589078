#pragma once
/// Small helpers the study writers share.
#include <filesystem>
#include <string>
#include <vector>

#include "reports/study.hpp"

namespace ffp {

/// Copy a run's PNG into the report's figures folder under `name` and add it
/// to the document. Returns false (and says so in the text) when it is missing.
bool include_run_figure(const StudyResults& results, std::size_t run, const std::string& relative_png,
                        const std::string& name, const std::string& caption, StudyOutput& out);

/// Scientific notation for error tables, e.g. "2.3e-05".
std::string scientific(double value, int digits = 2);

/// Request for a scene in the scenes folder, with overrides.
RunRequest scene_run(const std::filesystem::path& scenes_dir, const std::string& scene_file, const std::string& label,
                     std::vector<std::string> overrides = {});

/// The reference drop, data/scenes/ffp_reference.json as shipped (`overrides` only restating its
/// own values), with the soil's localisation written (output.localisation: the run's other
/// outputs are the same bits with it). Several studies ask for it (the summary, E' = 2500 kPa,
/// δ = 20°, the localisation study): through this request their keys agree and the cache runs
/// it once (tests/reports/report_runs_test.cpp).
RunRequest reference_drop_run(const std::filesystem::path& scenes_dir, const std::string& label,
                              std::vector<std::string> overrides = {});

/// The reference drop in the micropolar sand, data/scenes/ffp_micropolar.json as shipped, with the
/// soil's localisation written, as reference_drop_run: the summary's table and the side-by-side
/// section share one run (about a minute: the grain's rotational inertia sets a step 34 times
/// shorter than the classical one).
RunRequest micropolar_drop_run(const std::filesystem::path& scenes_dir, const std::string& label);

/// The history row whose time_s is nearest `time_s`.
std::size_t history_row_at(const CsvData& history, double time_s);

/// Linear interpolation of y(x) on a table sorted by x (NaN outside).
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at);

/// A value extrapolated from three meshes halving in size, and its observed order.
struct Extrapolation {
  double value;
  double order;  ///< NaN when the finest value is used instead
};

/// Richardson from three meshes halving in size: order p = log2((Q_2h − Q_h)/(Q_h − Q_h/2)).
/// Accepted only for a monotone sequence with 0.3 < p < 4; else the finest value.
Extrapolation richardson(double coarse, double medium, double fine);

}  // namespace ffp
