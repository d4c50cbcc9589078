#pragma once
/// The scalars of a law's state that drivers report beside the stress: history
/// columns of the point and triaxial kinds, particle fields of the MPM. Each
/// law lists the ones it has (`outputs()`) and evaluates them (`output()`);
/// a law without internal variables has none. Values are SI: angles in
/// radians, rates in 1/s (drivers turn them into the units of the scenes).
#include <string_view>

namespace ffp {

enum class StateOutput : unsigned char {
  plastic_deviatoric_strain,  ///< accumulated ε_d^p = Σ √(2/3 Δe^p:Δe^p)
  friction_angle,             ///< the current φ' (rad)
  dilatancy_angle,            ///< the current ψ (rad)
  strain_rate,                ///< the deviatoric strain rate the law sees (1/s)
};

enum class OutputUnit : unsigned char { none, radian, per_second };

/// The output's name without a unit suffix ("friction_angle").
constexpr std::string_view name(StateOutput output) {
  switch (output) {
    case StateOutput::plastic_deviatoric_strain:
      return "plastic_deviatoric_strain";
    case StateOutput::friction_angle:
      return "friction_angle";
    case StateOutput::dilatancy_angle:
      return "dilatancy_angle";
    case StateOutput::strain_rate:
      return "strain_rate";
  }
  return "";
}

constexpr OutputUnit unit(StateOutput output) {
  switch (output) {
    case StateOutput::friction_angle:
    case StateOutput::dilatancy_angle:
      return OutputUnit::radian;
    case StateOutput::strain_rate:
      return OutputUnit::per_second;
    default:
      return OutputUnit::none;
  }
}

}  // namespace ffp
