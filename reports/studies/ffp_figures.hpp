#pragma once
/// Figures and tables shared by the FFP studies: the paper's Fig. 7/8/10–12
/// panels drawn from several runs' history.csv, and a row of each run's figures.
#include <string>
#include <vector>

#include "reports/plot.hpp"
#include "reports/study.hpp"

namespace ffp {

/// One run of a comparison and how it is labelled in legends and tables.
struct LabelledRun {
  std::size_t index;
  std::string label;
};

/// Penetration against time, velocity and deceleration against penetration
/// (the paper's Fig. 8/10/11/12 panels), one curve per run.
void ffp_depth_profiles_figure(const StudyResults& results, const std::vector<LabelledRun>& runs,
                               const std::string& title, const std::string& png_name, StudyOutput& out);

/// Penetration, velocity, deceleration and reaction against time (Fig. 7).
void ffp_time_histories_figure(const StudyResults& results, const std::vector<LabelledRun>& runs,
                               const std::string& title, const std::string& png_name, StudyOutput& out);

/// Header and rows of the standard figures of each run (peak g, time and depth
/// of the peak, max/final penetration, rebound, steps, wall time).
std::vector<std::string> ffp_table_header();
std::vector<std::vector<std::string>> ffp_table_rows(const StudyResults& results, const std::vector<LabelledRun>& runs);

/// The overrides that turn ffp_reference.json's MC sand into the paper's section 5.5
/// SSMC (φ'_p = 60°, φ'_c = 32°, ψ_p = 5°) with softening factor η (as written).
std::vector<std::string> paper_softening_sand(const std::string& eta);

/// A summary number, NaN when the run failed or lacks it.
double figure(const StudyResults& results, std::size_t run, const std::string& key);

}  // namespace ffp
