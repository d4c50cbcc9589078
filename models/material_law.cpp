#include "models/material_law.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace ffp {

namespace {

template <class Law>
using StateOf = typename std::decay_t<Law>::State;

}  // namespace

MaterialLaw make_law(const MaterialParameters& parameters) {
  return std::visit(
      [](const auto& p) -> MaterialLaw {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, ElasticConstants>) {
          return LinearElastic(p);
        } else if constexpr (std::is_same_v<P, MohrCoulombParameters>) {
          return MohrCoulomb(p);
        } else {
          return StrainSofteningMohrCoulomb(p);
        }
      },
      parameters);
}

double at_rest_k0(const MaterialParameters& parameters) {
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&parameters)) return 1.0 - std::sin(mc->friction_angle_rad);
  if (const auto* ss = std::get_if<StrainSofteningParameters>(&parameters))
    return 1.0 - std::sin(ss->friction_peak_rad);
  const double nu = std::get<ElasticConstants>(parameters).poisson_ratio;
  return nu / (1.0 - nu);
}

double peak_cohesion_Pa(const MaterialParameters& parameters) {
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&parameters)) return mc->cohesion_Pa;
  if (const auto* ss = std::get_if<StrainSofteningParameters>(&parameters)) return ss->cohesion_peak_Pa;
  return 0.0;
}

const ElasticConstants& elastic_constants(const MaterialLaw& law) {
  return std::visit([](const auto& l) -> const ElasticConstants& { return l.elastic(); }, law);
}

const ElasticConstants& elastic_constants(const MaterialParameters& parameters) {
  return std::visit(
      [](const auto& p) -> const ElasticConstants& {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, ElasticConstants>) {
          return p;
        } else {
          return p.elastic;
        }
      },
      parameters);
}

MaterialState initial_state(const MaterialLaw& law) {
  return std::visit([](const auto& l) -> MaterialState { return StateOf<decltype(l)>{}; }, law);
}

MaterialStates initial_states(const MaterialLaw& law, std::size_t count) {
  return std::visit([count](const auto& l) -> MaterialStates { return std::vector<StateOf<decltype(l)>>(count); }, law);
}

ReturnRegion update(const MaterialLaw& law, Voigt& stress, const Voigt& strain_increment, MaterialState& state,
                    double dt_s) {
  return std::visit(
      [&](const auto& l) { return l.update(stress, strain_increment, std::get<StateOf<decltype(l)>>(state), dt_s); },
      law);
}

void update(const MaterialLaw& law, std::span<Voigt> stress, std::span<const Voigt> strain_increment,
            MaterialStates& states, std::size_t first, double dt_s) {
  std::visit(
      [&](const auto& l) {
        auto& s = std::get<std::vector<StateOf<decltype(l)>>>(states);
        l.update(stress, strain_increment, std::span(s).subspan(first, stress.size()), dt_s);
      },
      law);
}

std::span<const StateOutput> state_outputs(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return l.outputs(); }, law);
}

bool has_state_output(const MaterialLaw& law, StateOutput output) {
  const std::span<const StateOutput> outputs = state_outputs(law);
  return std::find(outputs.begin(), outputs.end(), output) != outputs.end();
}

double state_output(const MaterialLaw& law, const MaterialState& state, double mean_pressure_Pa, StateOutput output) {
  return std::visit(
      [&](const auto& l) { return l.output(std::get<StateOf<decltype(l)>>(state), mean_pressure_Pa, output); }, law);
}

void state_output(const MaterialLaw& law, const MaterialStates& states, std::size_t first,
                  std::span<const Voigt> stress, StateOutput output, std::span<double> out) {
  std::visit(
      [&](const auto& l) {
        const auto& s = std::get<std::vector<StateOf<decltype(l)>>>(states);
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = l.output(s[first + i], mean_pressure(stress[i]), output);
      },
      law);
}

std::optional<MohrCoulombParameters> mohr_coulomb_strength(const MaterialLaw& law, const MaterialState& state,
                                                           double mean_pressure_Pa) {
  return std::visit(
      [&](const auto& l) -> std::optional<MohrCoulombParameters> {
        const auto& s = std::get<StateOf<decltype(l)>>(state);
        if constexpr (requires {
                        { l.current_strength(s, mean_pressure_Pa) } -> std::same_as<MohrCoulombParameters>;
                      }) {
          return l.current_strength(s, mean_pressure_Pa);
        } else {
          return std::nullopt;
        }
      },
      law);
}

}  // namespace ffp
