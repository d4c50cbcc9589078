#pragma once
/// Peak dilatancy of sand from its relative density and mean effective stress
/// (Bolton 1986, as used by Zambrano-Cruzatty & Yerro 2020, section 4.2).

namespace ffp {

/// Relative dilatancy index, paper eq. 5: I_R = D_r (10 − ln p'[kPa]) − 1, clamped to [0, 4].
/// p' ≤ 0 (a stress-free or tensile point) reads as ln p' → −∞: I_R = 4 for D_r > 0, else 0.
double bolton_dilatancy_index(double relative_density, double mean_pressure_kPa);

/// Paper eq. 4: tan ψ_p = D_max = 0.3 I_R.
double bolton_peak_dilatancy_rad(double relative_density, double mean_pressure_kPa);

}  // namespace ffp
