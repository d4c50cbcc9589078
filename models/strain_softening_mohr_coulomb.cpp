#include "models/strain_softening_mohr_coulomb.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

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

StrengthSlopes StrainSofteningMohrCoulomb::strength_slopes(const State& state, double mean_pressure_Pa) const {
  const StrainSofteningParameters& p = parameters_;
  const double eta = p.softening_factor;
  const double decay = std::exp(-eta * state.plastic_deviatoric_strain);
  // d/dκ of x_r + (x_p − x_r) exp(−η κ) (Yerro et al. 2016): −η (x_p − x_r) exp(−η κ).
  return {-eta * (peaks(state, mean_pressure_Pa).friction_rad - p.friction_residual_rad) * decay,
          -eta * (p.cohesion_peak_Pa - p.cohesion_residual_Pa) * decay};
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
  ReturnRegion region = ReturnRegion::elastic;
  // A block of one: its work arrays hold one point, not kReturnBlock to initialise per call.
  update_block<1>({&stress, 1}, {&strain_increment, 1}, {&state, 1}, dt_s, &region);
  return region;
}

ReturnRegion StrainSofteningMohrCoulomb::update_general(Voigt& stress, const Voigt& strain_increment, State& state,
                                                        double peak_friction_rad) const {
  const Voigt trial = stress + elastic_stiffness_.stress_increment(strain_increment);
  const PrincipalStresses principal(trial);
  if (surely_elastic(principal.values()[0], principal.values()[2], peak_friction_rad,
                     state.plastic_deviatoric_strain)) {
    stress = trial;
    return ReturnRegion::elastic;
  }
  Eigen::Vector3d returned;
  const ReturnRegion region =
      plastic_return(principal.values(), peak_friction_rad, mean_pressure(stress), state, returned);
  stress = region == ReturnRegion::elastic ? trial : principal.with_values(returned);
  return region;
}

void StrainSofteningMohrCoulomb::update(std::span<Voigt> stress, std::span<const Voigt> strain_increment,
                                        std::span<State> state, double dt_s) const {
  assert(stress.size() == strain_increment.size() && stress.size() == state.size());
  for (std::size_t first = 0; first < stress.size(); first += kReturnBlock) {
    const std::size_t n = std::min(kReturnBlock, stress.size() - first);
    update_block<kReturnBlock>(stress.subspan(first, n), strain_increment.subspan(first, n), state.subspan(first, n),
                               dt_s, nullptr);
  }
}

// Why the returns are interleaved by hand. A softening return searches Δκ by regula falsi, 3–4 evaluations of g(Δκ)
// per point, and each evaluation is one chain of dependent latencies (division, square root, a compare and branch):
// making its libm calls cheaper (the strength by series) took the libm share of the profile from 22 % to 4 % and
// moved neither the benchmark nor the FFP run. What pays is giving the processor independent chains to overlap: the
// search is a machine that asks for one evaluation at a time (ReturnSearch), and each round below evaluates every
// search still going before any takes its answer. Measured when it went in (commit c6999d5, one thread, interleaved
// medians of 5): the benchmark ssmc_paper_sand 1.2–1.4 × the same returns one after another, the SSMC FFP to 0.06 s
// 1.11 ×. Each point still takes the same arithmetic in the same order, so the block gives the point update's bits
// (update() is this block with one point; tested in "SSMC's batch update gives the point update's bits, returns
// interleaved or not").
template <std::size_t Capacity>
void StrainSofteningMohrCoulomb::update_block(std::span<Voigt> stress, std::span<const Voigt> strain_increment,
                                              std::span<State> state, double dt_s, ReturnRegion* regions) const {
  static_assert(Capacity <= kReturnBlock);
  assert(stress.size() <= Capacity);
  auto set_region = [regions](std::size_t i, ReturnRegion region) {
    if (regions != nullptr) regions[i] = region;
  };
  // First the rates, trials and screens, then the returns of the yielding points side
  // by side (ReturnSearch). Most points of an MPM step are well inside the surface:
  // screened without exp or trigonometry, and (θθ principal) without the principal-space
  // object (ElasticTrial), on whose scalar principal values a yielding planar point also
  // returns (the same bits as PrincipalStresses, as in MohrCoulomb's batch).
  std::array<ElasticTrial, Capacity> trials;
  std::array<ReturnSearch, Capacity> searches;
  std::array<std::size_t, Capacity> point{};  // the search's point in the block
  std::array<unsigned char, Capacity> active{};
  std::size_t yielding = 0;
  for (std::size_t i = 0; i < stress.size(); ++i) {
    State& st = state[i];
    if (dt_s > 0.0)
      st.strain_rate_per_s =
          parameters_.rate.smoothed_rate(st.strain_rate_per_s, deviatoric_strain(strain_increment[i]) / dt_s);
    const double peak_friction = peak_friction_rad(st);
    const ElasticTrial quick(stress[i], strain_increment[i], elastic_stiffness_);
    if (!quick.planar) {
      set_region(i, update_general(stress[i], strain_increment[i], st, peak_friction));
      continue;
    }
    if (surely_elastic(quick.major, quick.minor, peak_friction, st.plastic_deviatoric_strain)) {
      quick.store(stress[i]);
      set_region(i, ReturnRegion::elastic);
      continue;
    }
    prepare_return(searches[yielding], quick.values(), peak_friction, mean_pressure(stress[i]), st);
    trials[yielding] = quick;
    point[yielding] = i;
    active[yielding] = static_cast<unsigned char>(yielding);
    ++yielding;
  }
  // Inside the surface at κ_n after all: elastic.
  const std::size_t going_first = start_returns(searches.data(), active.data(), yielding);
  for (std::size_t j = 0, k = 0; j < yielding; ++j) {
    if (k < going_first && active[k] == j) {
      ++k;
    } else {
      trials[j].store(stress[point[j]]);
      set_region(point[j], ReturnRegion::elastic);
    }
  }
  // Rounds: one evaluation of each search still going (independent: overlapped),
  // then each takes its answer; a finished one stores its stress.
  for (std::size_t going = going_first; going > 0;) {
    evaluate(searches.data(), active.data(), going);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < going; ++k) {
      const std::size_t j = active[k];
      if (advance(searches[j])) {
        active[kept++] = static_cast<unsigned char>(j);
        continue;
      }
      if (searches[j].region == ReturnRegion::elastic) {
        trials[j].store(stress[point[j]]);
      } else {
        trials[j].store_with_values(searches[j].returned, stress[point[j]]);
      }
      set_region(point[j], searches[j].region);
    }
    going = kept;
  }
}

}  // namespace ffp
