#pragma once
/// Where a curve known at a few points crosses a level: the piecewise cubic
/// Hermite interpolant that keeps the data's monotonicity (Fritsch & Carlson
/// 1980, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17;
/// the slopes as in Moler's pchip). The calibration starts its fit there from
/// the scan of W over ln η: W(ln η) bends strongly over the bounds' decades
/// (its slope falls ~3× from η = 15 to 500 at 2 cm), so the chord between two
/// scan points a decade apart misses the crossing by most of that decade,
/// while the cubic uses the neighbours' slopes.
#include <vector>

namespace ffp {

/// The first x in the first interval [x_k, x_k+1] whose samples straddle
/// `level` (y_k − level and y_k+1 − level of opposite signs or one zero) at
/// which the interpolant equals `level`; x strictly increasing, ≥ 2 points.
/// Throws std::invalid_argument when no interval straddles it.
double monotone_crossing(const std::vector<double>& x, const std::vector<double>& y, double level);

}  // namespace ffp
