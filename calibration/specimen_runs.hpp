#pragma once
/// The runs of a numerical triaxial a calibration has made, kept by η so that
/// no η is run twice: the scan, the fit's trial points and derivatives, the
/// fitted η's final curve, the other criterion's fit and the compare_eta curves
/// all draw on the same runs. A meshed MPM specimen costs seconds to minutes a
/// run (calibration/mpm_triaxial_specimen.hpp), an element test milliseconds.
///
/// A batch of η not yet run (`run_all`) runs side by side on up to
/// `concurrency` threads: each run is its own model and the specimen's runs
/// are single-threaded (fewer particles than the MPM's parallel minimum,
/// mpm/parallel.hpp), so a batch of n runs takes ⌈n/concurrency⌉ run times and
/// gives the same curves as one after the other.
#include <cstddef>
#include <map>
#include <span>

#include "calibration/numerical_triaxial.hpp"

namespace ffp {

class SpecimenRuns {
 public:
  /// `concurrency` ≥ 1: runs of one batch at once. The triaxial (and whatever it
  /// calls, e.g. an observer) must then be safe to call from several threads.
  explicit SpecimenRuns(NumericalTriaxial triaxial, int concurrency = 1);

  /// The curve at η, run now if it has not been. Throws what the triaxial throws
  /// (nothing is kept for that η).
  const SpecimenCurve& at(double eta);

  /// Runs every η of `etas` not yet run, side by side; the first failure (in the
  /// order of `etas`) is rethrown once all have ended, the successful runs kept.
  void run_all(std::span<const double> etas);

  bool has(double eta) const { return curves_.contains(eta); }
  /// Numerical triaxials actually run (each η once).
  int runs() const { return runs_; }
  /// Requests answered from what was run already.
  int reuses() const { return reuses_; }
  int concurrency() const { return concurrency_; }
  /// Every η run, ascending, with its curve.
  const std::map<double, SpecimenCurve>& curves() const { return curves_; }

 private:
  NumericalTriaxial triaxial_;
  int concurrency_;
  std::map<double, SpecimenCurve> curves_;
  int runs_ = 0;
  int reuses_ = 0;
};

}  // namespace ffp
