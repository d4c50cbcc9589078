#pragma once
/// Rate-dependent peak friction angle (the high-strain-rate strengthening the
/// paper discusses in sections 4.2 and 5.5) and the smoothing of the strain rate
/// that drives it.

namespace ffp {

/// φ'_p(ε̇) = φ'_p,ref (1 + α_φ log10(ε̇/ε̇_ref)) for ε̇ > ε̇_ref, else φ'_p,ref.
struct FrictionRateLaw {
  double alpha_phi = 0.0;                              ///< 0: rate independent
  double reference_strain_rate_per_s = 1e-5;           ///< ε̇_ref
  int smoothing_increments = 1;                        ///< N: ε̇ averaged over about N increments
  double max_friction_angle_rad = 1.2217304763960306;  ///< cap (70°) so tan φ stays finite

  /// The peak friction angle at deviatoric strain rate ε̇ (capped, never below the reference).
  double peak_friction_rad(double reference_peak_rad, double strain_rate_per_s) const;

  /// Exponential moving average with weight w = 2/(N + 1) on the newest rate
  /// (the usual N-period EMA: its centre of mass lies (N − 1)/2 increments back,
  /// as for a true window of N). N = 1 returns the newest rate unchanged.
  double smoothed_rate(double previous_smoothed_per_s, double newest_per_s) const;
};

}  // namespace ffp
