#pragma once
/// Strain-softening Mohr-Coulomb (SSMC, Yerro et al. 2016): φ', c' and ψ decay
/// exponentially with the accumulated plastic deviatoric strain; optional
/// transient Bolton dilatancy and a rate-dependent peak friction angle.
///
/// Integration: backward Euler. The hardening variable is implicit: the
/// increment Δκ of plastic deviatoric strain solves Δκ = g(Δκ), where g is the
/// plastic deviatoric strain of the exact (closed-form) Mohr-Coulomb return
/// with the strength at κ_n + Δκ. The trial's principal frame is computed once;
/// each evaluation of g is a return in principal space. The scalar equation is
/// started at the explicit estimate Δκ = g(0) and solved by secants from there,
/// which bracket the root in one or two steps when η Δκ ≪ 1; then (or, failing
/// that, inside [0, Δκ_hi] with the residual strength's bound) by the Illinois
/// variant of regula falsi, so it converges for any η and increment size. The
/// elastic test first tries a bound without trigonometry (surely_elastic).
/// The strain rate and the mean pressure for Bolton's ψ_p are taken explicitly:
/// the rate of the current increment (after smoothing) and p' at the start of
/// the increment.
///
/// The root search is a machine that asks for one evaluation of g at a time
/// (ReturnSearch, strain_softening_return.cpp). Each evaluation is a chain of
/// dependent latencies (exp, sin, the return's divisions, a square root), so
/// the batch update runs the returns of a block of points side by side, one
/// evaluation of each per round: the processor overlaps their chains. Each
/// point's arithmetic is the same as alone, so the results are the same bits.
#include <array>
#include <optional>
#include <span>

#include "models/bolton_dilatancy.hpp"
#include "models/bracketed_root.hpp"
#include "models/elastic.hpp"
#include "models/friction_rate_law.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/state_output.hpp"
#include "models/voigt.hpp"

namespace ffp {

struct StrainSofteningParameters {
  ElasticConstants elastic;
  double friction_peak_rad = 0.0;      ///< φ'_p (the rate law's reference value)
  double friction_residual_rad = 0.0;  ///< φ'_r (critical state)
  double cohesion_peak_Pa = 0.0;
  double cohesion_residual_Pa = 0.0;
  double dilatancy_peak_rad = 0.0;      ///< ψ_p, used when relative_density is empty
  double dilatancy_residual_rad = 0.0;  ///< ψ_r (0 by default)
  double softening_factor = 1.0;        ///< η
  /// Transient dilatancy from Bolton (paper eqs. 4–5): when set, ψ_p follows p'.
  std::optional<double> relative_density;
  FrictionRateLaw rate;
};

class StrainSofteningMohrCoulomb {
 public:
  struct State {
    double plastic_deviatoric_strain = 0.0;  ///< κ = ε_d^p = Σ √(2/3 Δe^p:Δe^p), monotone
    double strain_rate_per_s = 0.0;          ///< smoothed deviatoric strain-rate norm √(2/3 ė:ė)
  };

  explicit StrainSofteningMohrCoulomb(const StrainSofteningParameters& parameters);

  const StrainSofteningParameters& parameters() const { return parameters_; }
  const ElasticConstants& elastic() const { return parameters_.elastic; }
  double p_wave_speed(double density_kg_m3) const { return parameters_.elastic.p_wave_speed(density_kg_m3); }

  /// The strength (φ', c', ψ) a state currently has at mean pressure p'.
  MohrCoulombParameters current_strength(const State& state, double mean_pressure_Pa) const;
  /// dφ'/dκ and dc'/dκ at that state: the decay law differentiated at the current peaks
  /// (the rate law's φ'_p held at the state's rate, Bolton's ψ_p at p').
  StrengthSlopes strength_slopes(const State& state, double mean_pressure_Pa) const;

  /// dt_s > 0 feeds the rate law; dt_s ≤ 0 leaves the smoothed rate as it was.
  ReturnRegion update(Voigt& stress, const Voigt& strain_increment, State& state, double dt_s) const;
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment, std::span<State> state,
              double dt_s) const;

  /// What drivers report of the state: κ, the current φ' and ψ (at p'), and the smoothed rate.
  static std::span<const StateOutput> outputs() { return kOutputs; }
  double output(const State& state, double mean_pressure_Pa, StateOutput output) const;

 private:
  struct Peaks {
    double friction_rad;
    double dilatancy_rad;
  };
  static constexpr std::array<StateOutput, 4> kOutputs = {StateOutput::plastic_deviatoric_strain,
                                                          StateOutput::friction_angle, StateOutput::dilatancy_angle,
                                                          StateOutput::strain_rate};

  double peak_friction_rad(const State& state) const;
  double peak_dilatancy_rad(double mean_pressure_Pa) const;
  Peaks peaks(const State& state, double mean_pressure_Pa) const;
  MohrCoulombStrength strength(const Peaks& peaks, double decay) const;
  /// strength(peaks, 0): the residual strength, without trigonometry unless
  /// Bolton's ψ_p lies below ψ_r.
  MohrCoulombStrength residual_strength(const Peaks& peaks) const;
  /// True only where the trial is certainly inside the surface at the current
  /// strength: the yield test with a lower bound on sin φ' that needs no trigonometry.
  bool surely_elastic(double major, double minor, double peak_friction_rad, double plastic_deviatoric_strain) const;
  /// The return of a trial (principal values, descending) that the screen did not pass: the
  /// implicit Δκ, added to the state; `returned` holds the returned principal values unless
  /// the result is elastic.
  ReturnRegion plastic_return(const Eigen::Vector3d& trial_values, double peak_friction_rad, double mean_pressure_Pa,
                              State& state, Eigen::Vector3d& returned) const;

  /// One plastic return in progress: the search for Δκ (strain_softening_return.cpp).
  struct ReturnSearch {
    enum class Phase : unsigned char { start, extrapolate, residual_bound, widen, illinois };
    // The point.
    Eigen::Vector3d trial;  ///< principal values, descending
    Peaks peaks;
    double decay_start;  ///< exp(−η κ_n)
    State* state;
    // The evaluation asked for: g with `given` if `with_given`, else r(Δκ) = g(Δκ) − Δκ at `increment`.
    bool with_given;
    MohrCoulombStrength given;
    double increment;
    // Its answer.
    Eigen::Vector3d returned;
    ReturnRegion region;
    double value;
    // The search: newest = the last Δκ evaluated, other = the end kept below it
    // (r > 0 while extrapolating and widening, then across the root).
    Phase phase;
    int steps;  ///< extrapolations, widenings or Illinois steps so far
    double tolerance;
    IllinoisBracket bracket;
  };
  /// Sets the search's point up.
  void prepare_return(ReturnSearch& search, const Eigen::Vector3d& trial_values, double peak_friction_rad,
                      double mean_pressure_Pa, State& state) const;
  /// Starts searches[active[k]], k < count: the strength at κ_n, and the first evaluation
  /// asked for; the searches whose trial is inside the surface there (elastic) are left
  /// out of `active`. Returns how many stay.
  std::size_t start_returns(ReturnSearch* searches, unsigned char* active, std::size_t count) const;
  /// Answers the evaluations that searches[active[k]], k < count, ask for (count ≤ kReturnBlock).
  void evaluate(ReturnSearch* searches, const unsigned char* active, std::size_t count) const;
  static constexpr std::size_t kReturnBlock = 64;  ///< points whose returns run side by side
  /// Takes the answer; true if the search asks for another evaluation, false when Δκ is
  /// found (added to the state; `returned` and `region` then belong to it).
  bool advance(ReturnSearch& search) const;
  /// Up to Capacity points: the update of each, as update() does, with the returns of
  /// the yielding ones side by side; each point's region into regions[i] unless null.
  /// Capacity sizes the block's work arrays: 1 for update(), kReturnBlock for the batch.
  template <std::size_t Capacity>
  void update_block(std::span<Voigt> stress, std::span<const Voigt> strain_increment, std::span<State> state,
                    double dt_s, ReturnRegion* regions) const;
  /// The update after the rate, for a trial that is not planar (the general principal frame).
  ReturnRegion update_general(Voigt& stress, const Voigt& strain_increment, State& state,
                              double peak_friction_rad) const;

  StrainSofteningParameters parameters_;
  PrincipalStiffness stiffness_;
  ElasticStiffness elastic_stiffness_;  ///< λ, 2G for the trial stress
  double deviatoric_compliance_;        ///< √(2/3)/2G: plastic deviatoric strain per unit |dev Δσ|
  MohrCoulombStrength residual_;        ///< strength at ε_d^p → ∞ where ψ_p ≥ ψ_r
  // The elastic screen (surely_elastic): valid where these bounds hold.
  bool screen_ = false;
  double screen_peak_max_rad_ = 0.0;  ///< the largest φ'_p the rate law can give
  double sin_residual_ = 0.0;         ///< sin φ'_r
  double sin_chord_slope_ = 0.0;      ///< (sin φ'_max − sin φ'_r)/(φ'_max − φ'_r)
};

}  // namespace ffp
