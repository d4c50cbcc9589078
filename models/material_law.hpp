#pragma once
/// Any of the project's constitutive laws, its state and the parameter set of
/// each: the one place that lists the laws. The point driver, the triaxial
/// test and the MPM take a MaterialLaw and call the functions below; none of
/// them names a law. A new law is one more entry in `Laws` (and in
/// MaterialParameters and make_law), plus its keys in the scene's material
/// reader (drivers/scene/material_scene.*).
///
/// Every law has the same small interface (checked by `ConstitutiveLaw`):
///   struct State;                                   value type, default = virgin state
///   const ElasticConstants& elastic() const;
///   ReturnRegion update(Voigt& σ, const Voigt& Δε, State&, double dt_s) const;
///   void update(span<Voigt> σ, span<const Voigt> Δε, span<State>, double dt_s) const;
///   static span<const StateOutput> outputs();      what it reports of its state
///   double output(const State&, double p'_Pa, StateOutput) const;
/// dt_s > 0 feeds rate-dependent laws; dt_s ≤ 0 leaves the rate as it was.
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "models/elastic.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/return_region.hpp"
#include "models/state_output.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"
#include "models/voigt.hpp"

namespace ffp {

template <class L>
concept ConstitutiveLaw = requires(const L law, Voigt& stress, const Voigt& increment, typename L::State& state,
                                   std::span<Voigt> stresses, std::span<const Voigt> increments,
                                   std::span<typename L::State> states, StateOutput output) {
  { law.elastic() } -> std::same_as<const ElasticConstants&>;
  { law.update(stress, increment, state, 0.0) } -> std::same_as<ReturnRegion>;
  law.update(stresses, increments, states, 0.0);
  { L::outputs() } -> std::same_as<std::span<const StateOutput>>;
  { law.output(state, 0.0, output) } -> std::same_as<double>;
};

/// The laws, their states (same alternative index) and, for the MPM, one
/// contiguous vector of states per group of points.
template <ConstitutiveLaw... L>
struct LawSet {
  using Law = std::variant<L...>;
  using State = std::variant<typename L::State...>;
  using States = std::variant<std::vector<typename L::State>...>;
};
using Laws = LawSet<LinearElastic, MohrCoulomb, StrainSofteningMohrCoulomb>;

using MaterialLaw = Laws::Law;
using MaterialState = Laws::State;    ///< the state of one point
using MaterialStates = Laws::States;  ///< the states of many points of one law
using MaterialParameters = std::variant<ElasticConstants, MohrCoulombParameters, StrainSofteningParameters>;

/// The law with these parameters (same alternative index).
MaterialLaw make_law(const MaterialParameters& parameters);

/// K0 at rest when none is given: Jaky (1944) 1 − sin φ'_p for the frictional
/// laws (1 − sin 38° = 0.384; the paper's Table 1 rounds to 0.39), ν/(1 − ν) (lateral confinement) for an elastic one.
double at_rest_k0(const MaterialParameters& parameters);
/// c' at the peak (Pa): 0 for an elastic material.
double peak_cohesion_Pa(const MaterialParameters& parameters);

/// The elastic constants of any law or parameter set.
const ElasticConstants& elastic_constants(const MaterialLaw& law);
const ElasticConstants& elastic_constants(const MaterialParameters& parameters);

/// The virgin state of a law; `count` of them, contiguous, for a group of points.
MaterialState initial_state(const MaterialLaw& law);
MaterialStates initial_states(const MaterialLaw& law, std::size_t count);

/// One point: σ ← law(σ, Δε), the state updated. `state` must hold the law's alternative.
ReturnRegion update(const MaterialLaw& law, Voigt& stress, const Voigt& strain_increment, MaterialState& state,
                    double dt_s);

/// A batch: the law is visited once, then each point i of `stress` is updated
/// with states[first + i]. `states` must hold the law's alternative.
void update(const MaterialLaw& law, std::span<Voigt> stress, std::span<const Voigt> strain_increment,
            MaterialStates& states, std::size_t first, double dt_s);

/// The outputs the law reports of its state (none for a law without internal variables).
std::span<const StateOutput> state_outputs(const MaterialLaw& law);
bool has_state_output(const MaterialLaw& law, StateOutput output);
/// One output at a state and mean pressure p' (Pa, compression positive).
double state_output(const MaterialLaw& law, const MaterialState& state, double mean_pressure_Pa, StateOutput output);
/// One output of points [first, first + out.size()) of a group, p' taken from `stress` (one per point).
void state_output(const MaterialLaw& law, const MaterialStates& states, std::size_t first,
                  std::span<const Voigt> stress, StateOutput output, std::span<double> out);

/// The Mohr-Coulomb strength (φ', ψ, c') the law has at a state and p', for
/// the laws that have one (a yield surface of Mohr-Coulomb shape); none otherwise.
std::optional<MohrCoulombParameters> mohr_coulomb_strength(const MaterialLaw& law, const MaterialState& state,
                                                           double mean_pressure_Pa);

}  // namespace ffp
