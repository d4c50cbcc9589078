/// The SSMC's implicit return: the search for Δκ = g(Δκ), one evaluation of g at a time.
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "models/strain_softening_mohr_coulomb.hpp"

namespace ffp {

ReturnRegion StrainSofteningMohrCoulomb::plastic_return(const Eigen::Vector3d& trial_values, double peak_friction_rad,
                                                        double mean_pressure_Pa, State& state,
                                                        Eigen::Vector3d& returned) const {
  ReturnSearch search;
  prepare_return(search, trial_values, peak_friction_rad, mean_pressure_Pa, state);
  unsigned char only = 0;
  if (start_returns(&search, &only, 1) == 0) return ReturnRegion::elastic;
  do {
    evaluate(&search, &only, 1);
  } while (advance(search));
  returned = search.returned;
  return search.region;
}

void StrainSofteningMohrCoulomb::prepare_return(ReturnSearch& search, const Eigen::Vector3d& trial_values,
                                                double peak_friction_rad, double mean_pressure_Pa, State& state) const {
  search.trial = trial_values;
  search.peaks = {peak_friction_rad, peak_dilatancy_rad(mean_pressure_Pa)};
  search.state = &state;
}

// In passes over the searches, as evaluate() below.
std::size_t StrainSofteningMohrCoulomb::start_returns(ReturnSearch* searches, unsigned char* active,
                                                      std::size_t count) const {
  assert(count <= kReturnBlock);
  const double eta = parameters_.softening_factor;
  for (std::size_t k = 0; k < count; ++k) {
    ReturnSearch& s = searches[active[k]];
    s.decay_start = std::exp(-eta * s.state->plastic_deviatoric_strain);
  }
  for (std::size_t k = 0; k < count; ++k) {
    ReturnSearch& s = searches[active[k]];
    s.given = strength(s.peaks, s.decay_start);
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < count; ++k) {
    ReturnSearch& s = searches[active[k]];
    if (!(s.given.yield(s.trial) > 0.0)) continue;  // inside at κ_n: elastic
    s.with_given = true;                            // r(0) = g(0) with the strength at κ_n
    s.phase = ReturnSearch::Phase::start;
    active[kept++] = active[k];
  }
  return kept;
}

// g(Δκ): plastic deviatoric strain of the return with the strength at κ_n + Δκ.
// The plastic strain is coaxial with the trial: Δε^p = D⁻¹(σ_tr − σ), so its
// deviatoric norm is √(2/3) |dev(σ_tr − σ)| / 2G.
// In three passes over the searches (the decay, the strength, the return), each a
// short chain per search, so that the processor overlaps many searches: one pass of
// the whole chain per search overlaps hardly two.
void StrainSofteningMohrCoulomb::evaluate(ReturnSearch* searches, const unsigned char* active,
                                          std::size_t count) const {
  assert(count <= kReturnBlock);
  const double eta = parameters_.softening_factor;
  std::array<double, kReturnBlock> decay;
  for (std::size_t k = 0; k < count; ++k) {
    const ReturnSearch& s = searches[active[k]];
    decay[k] = s.with_given ? 0.0 : s.decay_start * std::exp(-eta * s.increment);
  }
  std::array<MohrCoulombStrength, kReturnBlock> strengths;
  for (std::size_t k = 0; k < count; ++k) {
    const ReturnSearch& s = searches[active[k]];
    strengths[k] = s.with_given ? s.given : strength(s.peaks, decay[k]);
  }
  for (std::size_t k = 0; k < count; ++k) {
    ReturnSearch& s = searches[active[k]];
    s.returned = s.trial;
    s.region = return_to_mohr_coulomb(s.returned, strengths[k], stiffness_);
    Eigen::Vector3d correction = s.trial - s.returned;
    correction.array() -= correction.mean();
    const double g = deviatoric_compliance_ * correction.norm();
    s.value = s.with_given ? g : g - s.increment;
  }
}

bool StrainSofteningMohrCoulomb::advance(ReturnSearch& search) const {
  using Phase = ReturnSearch::Phase;
  ReturnSearch& s = search;
  IllinoisBracket& b = s.bracket;
  auto ask_at = [&](double increment, Phase phase) {
    s.with_given = false;
    s.increment = increment;
    s.phase = phase;
    return true;
  };
  auto accept = [&](double increment) {
    s.state->plastic_deviatoric_strain += increment;
    return false;  // `returned` and `region` are those of the last evaluation, at this Δκ
  };
  // illinois_root's steps (bracketed_root.hpp), one evaluation at a time, up to 200.
  auto start_illinois = [&] {
    s.steps = 0;
    return std::abs(b.f_newest) <= s.tolerance ? accept(b.newest) : ask_at(b.secant(), Phase::illinois);
  };

  switch (s.phase) {
    case Phase::start: {
      const double residual_start = s.value;  // r(0) = g(0)
      if (!(residual_start > 0.0)) return accept(0.0);
      // Δκ to 1e-12 of the explicit estimate g(0), but never finer than the rounding of g itself.
      const double rounding =
          8.0 * std::numeric_limits<double>::epsilon() * deviatoric_compliance_ * s.trial.cwiseAbs().maxCoeff();
      s.tolerance = 1e-12 * residual_start + rounding;
      // r = g − Δκ falls from r(0) > 0 and is concave where g saturates with softening.
      // From the explicit estimate Δκ = g(0) secants extrapolate from below the root:
      // close to it in one or two steps (the step changes the strength by η Δκ ≪ 1),
      // and past it on a concave r, which brackets the root. Whatever is not bracketed
      // after a few steps takes the residual strength's bound below.
      b.other = 0.0;  // the largest Δκ with r > 0
      b.f_other = residual_start;
      b.newest = residual_start;
      s.steps = 0;
      return ask_at(b.newest, Phase::extrapolate);
    }
    case Phase::extrapolate: {
      b.f_newest = s.value;
      if (b.f_newest > s.tolerance && s.steps < 4) {
        const double next = b.secant();
        if (next > b.newest) {  // else r is not falling: no extrapolation
          b.other = b.newest;
          b.f_other = b.f_newest;
          b.newest = next;
          ++s.steps;
          return ask_at(b.newest, Phase::extrapolate);
        }
      }
      if (std::abs(b.f_newest) <= s.tolerance) return accept(b.newest);
      if (b.f_newest < 0.0) return start_illinois();
      // Upper end: the return with the residual strength. Softening makes g grow
      // with Δκ, so g(∞) usually bounds the root; widen if dilatancy decay says otherwise.
      if (b.f_newest > 0.0) {
        b.other = b.newest;
        b.f_other = b.f_newest;
      }
      s.with_given = true;
      s.given = residual_strength(s.peaks);
      s.phase = Phase::residual_bound;
      return true;
    }
    case Phase::residual_bound:
      b.newest = std::max(b.other, s.value);
      s.steps = 0;
      return ask_at(b.newest, Phase::widen);
    case Phase::widen:
      b.f_newest = s.value;
      if (b.f_newest > 0.0 && s.steps < 60) {
        b.newest = std::max(2.0 * b.newest, b.newest + b.f_newest);
        ++s.steps;
        return ask_at(b.newest, Phase::widen);
      }
      return start_illinois();
    case Phase::illinois: {
      b.take(s.increment, s.value);
      ++s.steps;
      const bool converged = std::abs(b.f_newest) <= s.tolerance || std::abs(b.newest - b.other) <= s.tolerance;
      return converged || s.steps >= 200 ? accept(b.newest) : ask_at(b.secant(), Phase::illinois);
    }
  }
  return accept(0.0);  // unreachable: every phase is handled above
}

}  // namespace ffp
