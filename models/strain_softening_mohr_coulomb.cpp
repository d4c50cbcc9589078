#include "models/strain_softening_mohr_coulomb.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "models/bracketed_root.hpp"
#include "models/math_constants.hpp"
#include "models/principal_stress.hpp"

namespace ffp {

StrainSofteningMohrCoulomb::StrainSofteningMohrCoulomb(const StrainSofteningParameters& parameters)
    : parameters_(parameters),
      stiffness_(PrincipalStiffness::of(parameters.elastic)),
      elastic_stiffness_(ElasticStiffness::of(parameters.elastic)),
      deviatoric_compliance_(std::sqrt(2.0 / 3.0) / (2.0 * parameters.elastic.shear_modulus())) {
  const StrainSofteningParameters& p = parameters_;
  // strength(peaks, 0) term by term: φ'_r, c'_r and ψ_r (ψ capped at φ'_r), the same sines.
  residual_ = MohrCoulombStrength::of(
      p.friction_residual_rad, std::min(p.dilatancy_residual_rad, p.friction_residual_rad), p.cohesion_residual_Pa);
  // φ'_p ≤ the rate law's cap; below it φ' stays in [φ'_r, φ'_max] (strength() is a
  // convex combination), where sin is increasing and concave, and c' cos φ' ≥ 0.
  screen_peak_max_rad_ =
      p.rate.alpha_phi == 0.0 ? p.friction_peak_rad : std::max(p.rate.max_friction_angle_rad, p.friction_peak_rad);
  sin_residual_ = std::sin(p.friction_residual_rad);
  if (screen_peak_max_rad_ > p.friction_residual_rad)
    sin_chord_slope_ =
        (std::sin(screen_peak_max_rad_) - sin_residual_) / (screen_peak_max_rad_ - p.friction_residual_rad);
  screen_ = p.friction_residual_rad >= 0.0 && screen_peak_max_rad_ <= 0.5 * kPi && p.softening_factor >= 0.0 &&
            std::min(p.cohesion_peak_Pa, p.cohesion_residual_Pa) >= 0.0;
}

double StrainSofteningMohrCoulomb::peak_friction_rad(const State& state) const {
  return parameters_.rate.peak_friction_rad(parameters_.friction_peak_rad, state.strain_rate_per_s);
}

double StrainSofteningMohrCoulomb::peak_dilatancy_rad(double mean_pressure_Pa) const {
  const StrainSofteningParameters& p = parameters_;
  return p.relative_density ? bolton_peak_dilatancy_rad(*p.relative_density, 1e-3 * mean_pressure_Pa)
                            : p.dilatancy_peak_rad;
}

StrainSofteningMohrCoulomb::Peaks StrainSofteningMohrCoulomb::peaks(const State& state, double mean_pressure_Pa) const {
  return {peak_friction_rad(state), peak_dilatancy_rad(mean_pressure_Pa)};
}

MohrCoulombStrength StrainSofteningMohrCoulomb::strength(const Peaks& peaks, double decay) const {
  const StrainSofteningParameters& p = parameters_;
  // Yerro et al. (2016): x = x_r + (x_p − x_r) exp(−η ε_d^p) for φ', c' and ψ.
  const double phi = p.friction_residual_rad + (peaks.friction_rad - p.friction_residual_rad) * decay;
  const double cohesion = p.cohesion_residual_Pa + (p.cohesion_peak_Pa - p.cohesion_residual_Pa) * decay;
  // Dilatancy only dies out towards the critical state: where Bolton's ψ_p has
  // fallen below ψ_r (loose sand, high p'), ψ stays at ψ_p instead of growing.
  const double psi_residual = std::min(p.dilatancy_residual_rad, peaks.dilatancy_rad);
  const double psi = psi_residual + (peaks.dilatancy_rad - psi_residual) * decay;
  return MohrCoulombStrength::of(phi, std::min(psi, phi), cohesion);
}

MohrCoulombStrength StrainSofteningMohrCoulomb::residual_strength(const Peaks& peaks) const {
  // With ψ_p ≥ ψ_r, strength(peaks, 0) is the precomputed residual_ bit for bit.
  return peaks.dilatancy_rad >= parameters_.dilatancy_residual_rad ? residual_ : strength(peaks, 0.0);
}

bool StrainSofteningMohrCoulomb::surely_elastic(double major, double minor, double peak_friction_rad,
                                                double plastic_deviatoric_strain) const {
  const double residual = parameters_.friction_residual_rad;
  if (!screen_ || !(peak_friction_rad >= residual && peak_friction_rad <= screen_peak_max_rad_)) return false;
  const double sum = major + minor;
  if (!(sum < 0.0)) return false;  // f grows with sin φ' only under mean compression
  // exp(−x) ≥ (1 − x/4)⁴ on [0, 4] (and ≥ 0 beyond), so φ' ≥ φ'_r + (φ'_p − φ'_r)(1 − x/4)⁴
  // with x = η ε_d^p; the chord of sin from φ'_r to φ'_max lies below sin on that range.
  const double root = std::max(0.0, 1.0 - 0.25 * parameters_.softening_factor * plastic_deviatoric_strain);
  const double decay_low = (root * root) * (root * root);
  const double sin_low = sin_residual_ + sin_chord_slope_ * (peak_friction_rad - residual) * decay_low;
  // f ≤ (σ1 − σ3) + (σ1 + σ3) sin_low (the − 2c' cos φ' term is ≤ 0). The margin, far
  // above the rounding of f and of the sines, leaves every doubtful point to the exact test.
  const double f_high = (major - minor) + sum * sin_low;
  return f_high < -1e-12 * (std::abs(major) + std::abs(minor));
}

MohrCoulombParameters StrainSofteningMohrCoulomb::current_strength(const State& state, double mean_pressure_Pa) const {
  const Peaks pk = peaks(state, mean_pressure_Pa);
  const double decay = std::exp(-parameters_.softening_factor * state.plastic_deviatoric_strain);
  const MohrCoulombStrength s = strength(pk, decay);
  MohrCoulombParameters out;
  out.elastic = parameters_.elastic;
  out.friction_angle_rad = std::atan2(s.sin_phi, s.cos_phi);
  out.dilatancy_angle_rad = std::asin(s.sin_psi);
  out.cohesion_Pa = s.cohesion_Pa;
  return out;
}

double StrainSofteningMohrCoulomb::output(const State& state, double mean_pressure_Pa, StateOutput output) const {
  switch (output) {
    case StateOutput::plastic_deviatoric_strain:
      return state.plastic_deviatoric_strain;
    case StateOutput::friction_angle:
      return current_strength(state, mean_pressure_Pa).friction_angle_rad;
    case StateOutput::dilatancy_angle:
      return current_strength(state, mean_pressure_Pa).dilatancy_angle_rad;
    case StateOutput::strain_rate:
      return state.strain_rate_per_s;
  }
  return 0.0;
}

ReturnRegion StrainSofteningMohrCoulomb::update(Voigt& stress, const Voigt& strain_increment, State& state,
                                                double dt_s) const {
  if (dt_s > 0.0)
    state.strain_rate_per_s =
        parameters_.rate.smoothed_rate(state.strain_rate_per_s, deviatoric_strain(strain_increment) / dt_s);
  // Most points of an MPM step are well inside the surface: screened without exp or
  // trigonometry, and (θθ principal) without the principal-space object (ElasticTrial),
  // on whose scalar principal values a yielding planar point also returns (the same
  // bits as PrincipalStresses, as in MohrCoulomb's batch).
  const double peak_friction = peak_friction_rad(state);
  if (const ElasticTrial quick(stress, strain_increment, elastic_stiffness_); quick.planar) {
    if (surely_elastic(quick.major, quick.minor, peak_friction, state.plastic_deviatoric_strain)) {
      quick.store(stress);
      return ReturnRegion::elastic;
    }
    Eigen::Vector3d returned;
    const ReturnRegion region = plastic_return(quick.values(), peak_friction, mean_pressure(stress), state, returned);
    if (region == ReturnRegion::elastic) {
      quick.store(stress);
    } else {
      quick.store_with_values(returned, stress);
    }
    return region;
  }
  const Voigt trial = stress + elastic_stiffness_.stress_increment(strain_increment);
  const PrincipalStresses principal(trial);
  if (surely_elastic(principal.values()[0], principal.values()[2], peak_friction, state.plastic_deviatoric_strain)) {
    stress = trial;
    return ReturnRegion::elastic;
  }
  Eigen::Vector3d returned;
  const ReturnRegion region = plastic_return(principal.values(), peak_friction, mean_pressure(stress), state, returned);
  stress = region == ReturnRegion::elastic ? trial : principal.with_values(returned);
  return region;
}

ReturnRegion StrainSofteningMohrCoulomb::plastic_return(const Eigen::Vector3d& trial_values, double peak_friction_rad,
                                                        double mean_pressure_Pa, State& state,
                                                        Eigen::Vector3d& returned) const {
  const Peaks pk{peak_friction_rad, peak_dilatancy_rad(mean_pressure_Pa)};
  const double eta = parameters_.softening_factor;
  const double decay_start = std::exp(-eta * state.plastic_deviatoric_strain);
  const MohrCoulombStrength strength_start = strength(pk, decay_start);
  if (!(strength_start.yield(trial_values) > 0.0)) return ReturnRegion::elastic;

  // g(Δκ): plastic deviatoric strain of the return with the strength at κ_n + Δκ.
  // The plastic strain is coaxial with the trial: Δε^p = D⁻¹(σ_tr − σ), so its
  // deviatoric norm is √(2/3) |dev(σ_tr − σ)| / 2G.
  ReturnRegion region = ReturnRegion::elastic;
  auto plastic_strain = [&](const MohrCoulombStrength& s) {
    returned = trial_values;
    region = return_to_mohr_coulomb(returned, s, stiffness_);
    Eigen::Vector3d correction = trial_values - returned;
    correction.array() -= correction.mean();
    return deviatoric_compliance_ * correction.norm();
  };
  auto residual = [&](double increment) {
    return plastic_strain(strength(pk, decay_start * std::exp(-eta * increment))) - increment;
  };

  const double residual_start = plastic_strain(strength_start);  // r(0) = g(0)
  double accepted = 0.0;
  if (residual_start > 0.0) {
    // Δκ to 1e-12 of the explicit estimate g(0), but never finer than the rounding of g itself.
    const double rounding =
        8.0 * std::numeric_limits<double>::epsilon() * deviatoric_compliance_ * trial_values.cwiseAbs().maxCoeff();
    const double tolerance = 1e-12 * residual_start + rounding;
    // r = g − Δκ falls from r(0) > 0 and is concave where g saturates with softening.
    // From the explicit estimate Δκ = g(0) secants extrapolate from below the root:
    // close to it in one or two steps (the step changes the strength by η Δκ ≪ 1),
    // and past it on a concave r, which brackets the root. Whatever is not bracketed
    // after a few steps takes the residual strength's bound below.
    double low = 0.0;  // the largest Δκ with r > 0
    double residual_low = residual_start;
    double high = residual_start;
    double residual_high = residual(high);
    for (int step = 0; residual_high > tolerance && step < 4; ++step) {
      const double next = high - residual_high * (high - low) / (residual_high - residual_low);
      if (!(next > high)) break;  // r not falling: no extrapolation
      low = high;
      residual_low = residual_high;
      high = next;
      residual_high = residual(high);
    }
    if (std::abs(residual_high) <= tolerance) {
      accepted = high;
    } else {
      if (!(residual_high < 0.0)) {
        // Upper end: the return with the residual strength. Softening makes g grow
        // with Δκ, so g(∞) usually bounds the root; widen if dilatancy decay says otherwise.
        if (residual_high > 0.0) {
          low = high;
          residual_low = residual_high;
        }
        high = std::max(low, plastic_strain(residual_strength(pk)));
        residual_high = residual(high);
        for (int widen = 0; residual_high > 0.0 && widen < 60; ++widen) {
          high = std::max(2.0 * high, high + residual_high);
          residual_high = residual(high);
        }
      }
      accepted = illinois_root(
                     residual, high, residual_high, low, residual_low, tolerance,
                     [tolerance](double) { return tolerance; }, 200)
                     .x;
    }
  }
  state.plastic_deviatoric_strain += accepted;
  // `returned` and `region` are those of the last evaluation, at the accepted Δκ.
  return region;
}

void StrainSofteningMohrCoulomb::update(std::span<Voigt> stress, std::span<const Voigt> strain_increment,
                                        std::span<State> state, double dt_s) const {
  assert(stress.size() == strain_increment.size() && stress.size() == state.size());
  for (std::size_t i = 0; i < stress.size(); ++i) update(stress[i], strain_increment[i], state[i], dt_s);
}

}  // namespace ffp
