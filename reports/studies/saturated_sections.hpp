#pragma once
/// The parts of the saturated-sand verification (saturated_verification_study.cpp): the
/// runs' places in the study's results and the sections written from them.
#include <cstddef>
#include <string>

#include "reports/plot.hpp"
#include "reports/study.hpp"

namespace ffp {

/// The runs, in the order the study asks for them.
enum SaturatedRunIndex : std::size_t {
  kHydrostatic,
  kUndrained,
  kDrained,
  kTerzaghiCoarse,  ///< then the two finer levels
  kVerruijtCoarse = kTerzaghiCoarse + 3,
  kVerruijtFine,
  kRadialCoarse,
  kRadialFine,
};

/// Verruijt's column: both waves' arrivals and the slow front's decay against the exact solution.
void write_saturated_waves(const StudyResults& results, StudyOutput& out);
/// Radial consolidation at two levels against the Bessel series.
void write_radial_consolidation(const StudyResults& results, StudyOutput& out);

/// "*(The <what> run failed: no figures.)*"
inline std::string missing_run(const std::string& what) { return "*(The " + what + " run failed: no figures.)*"; }

/// Draws a plot and adds it to the document with its caption (nothing without gnuplot).
inline void add_plot(StudyOutput& out, const Plot& plot, const std::string& png, const std::string& caption) {
  if (write_png(plot, out.figures_dir / png)) out.document.figure(out.figures_relative + "/" + png, caption);
}

}  // namespace ffp
