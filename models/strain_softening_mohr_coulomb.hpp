#pragma once
/// Strain-softening Mohr-Coulomb (SSMC, Yerro et al. 2016): φ', c' and ψ decay
/// exponentially with the accumulated plastic deviatoric strain; optional
/// transient Bolton dilatancy and a rate-dependent peak friction angle.
#include <optional>
#include <span>

#include "models/elastic.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/voigt.hpp"

namespace ffp {

/// Rate law for the peak friction angle:
/// φ'_p(ε̇) = φ'_p,ref (1 + α_φ log10(ε̇/ε̇_ref)) for ε̇ > ε̇_ref, else φ'_p,ref.
struct FrictionRateLaw {
  double alpha_phi = 0.0;                         ///< 0: rate independent
  double reference_strain_rate_per_s = 1e-5;      ///< ε̇_ref
  int smoothing_increments = 1;                   ///< ε̇ averaged over about this many increments
  double max_friction_angle_rad = 1.2217304763960306;  ///< cap (70°) so tan φ stays finite
};

struct StrainSofteningParameters {
  ElasticConstants elastic;
  double friction_peak_rad = 0.0;      ///< φ'_p (the rate law's reference value)
  double friction_residual_rad = 0.0;  ///< φ'_r (critical state)
  double cohesion_peak_Pa = 0.0;
  double cohesion_residual_Pa = 0.0;
  double dilatancy_peak_rad = 0.0;     ///< ψ_p, used when relative_density is empty
  double dilatancy_residual_rad = 0.0; ///< ψ_r (0 by default)
  double softening_factor = 1.0;       ///< η
  /// Transient dilatancy from Bolton (paper eqs. 4–5): when set, ψ_p follows p'.
  std::optional<double> relative_density;
  FrictionRateLaw rate;
};

class StrainSofteningMohrCoulomb {
 public:
  struct State {
    double plastic_deviatoric_strain = 0.0;  ///< ε_d^p, monotone
    double strain_rate_per_s = 0.0;          ///< smoothed deviatoric strain-rate norm
  };

  explicit StrainSofteningMohrCoulomb(const StrainSofteningParameters& parameters);

  const StrainSofteningParameters& parameters() const { return parameters_; }
  double p_wave_speed(double density_kg_m3) const { return parameters_.elastic.p_wave_speed(density_kg_m3); }

  /// The strength (φ', c', ψ) a state currently has at mean pressure p'.
  MohrCoulombParameters current_strength(const State& state, double mean_pressure_Pa) const;

  ReturnRegion update(Voigt& stress, const Voigt& strain_increment, State& state, double dt_s) const;
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment, std::span<State> state,
              double dt_s) const;

 private:
  StrainSofteningParameters parameters_;
};

/// Bolton (1986) relative dilatancy index, paper eq. 5: I_R = D_r (10 − ln p'[kPa]) − 1, clamped to [0, 4].
double bolton_dilatancy_index(double relative_density, double mean_pressure_kPa);
/// Paper eq. 4: tan ψ_p = D_max = 0.3 I_R.
double bolton_peak_dilatancy_rad(double relative_density, double mean_pressure_kPa);

}  // namespace ffp
