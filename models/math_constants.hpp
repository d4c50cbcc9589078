#pragma once
/// π and the degree, declared once for the whole project (models is the bottom
/// layer, so every library and test can use them).
#include <numbers>

namespace ffp {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;     ///< an axisymmetric slice's full turn
inline constexpr double kDegree = std::numbers::pi / 180.0;  ///< one degree in radians: φ_rad = φ_deg · kDegree

}  // namespace ffp
