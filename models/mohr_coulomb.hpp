#pragma once
/// Non-associated Mohr-Coulomb, elastic–perfectly plastic, with an exact
/// return mapping in principal stresses (plane, triaxial-compression edge,
/// triaxial-extension edge, apex): see models/mohr_coulomb_return.hpp.
#include <cassert>
#include <span>

#include "models/elastic.hpp"
#include "models/mohr_coulomb_return.hpp"
#include "models/voigt.hpp"

namespace ffp {

struct MohrCoulombParameters {
  ElasticConstants elastic;
  double friction_angle_rad = 0.0;   ///< φ' (0 ≤ φ < 90°; 0 is Tresca)
  double dilatancy_angle_rad = 0.0;  ///< ψ (0 ≤ ψ ≤ φ)
  double cohesion_Pa = 0.0;          ///< c' (0 for sand)
};

/// How fast a softening law's strength falls with its plastic deviatoric strain κ = ε_d^p at a
/// state: dφ'/dκ and dc'/dκ (≤ 0 while softening; 0 for a perfectly plastic law). ψ's fall moves
/// the flow direction, not the surface, so only these enter the hardening modulus.
struct StrengthSlopes {
  double friction_rad = 0.0;  ///< dφ'/dκ
  double cohesion_Pa = 0.0;   ///< dc'/dκ
};

class MohrCoulomb {
 public:
  struct State {};  // perfectly plastic: no internal variables

  explicit MohrCoulomb(const MohrCoulombParameters& parameters);

  const MohrCoulombParameters& parameters() const { return parameters_; }
  const ElasticConstants& elastic() const { return parameters_.elastic; }
  double p_wave_speed(double density_kg_m3) const { return parameters_.elastic.p_wave_speed(density_kg_m3); }

  /// f = (σ1 − σ3) + (σ1 + σ3) sin φ − 2 c cos φ with σ1 ≥ σ2 ≥ σ3 (tension positive).
  double yield_function(const Voigt& stress) const;

  /// One point: elastic predictor, then the return onto the surface.
  ReturnRegion update(Voigt& stress, const Voigt& strain_increment) const;

  /// A batch of points with the same parameters.
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment) const;

  // The interface every law has (models/material_law.hpp): no state, no rate.
  ReturnRegion update(Voigt& stress, const Voigt& strain_increment, State&, double) const {
    return update(stress, strain_increment);
  }
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment, std::span<State>, double) const {
    update(stress, strain_increment);
  }
  /// Perfectly plastic: the strength is the parameters' at every state.
  MohrCoulombParameters current_strength(const State&, double) const { return parameters_; }
  StrengthSlopes strength_slopes(const State&, double) const { return {}; }
  /// Nothing to report beside the stress (the strength never changes).
  static std::span<const StateOutput> outputs() { return {}; }
  double output(const State&, double, StateOutput) const {
    assert(false && "a Mohr-Coulomb law has no state outputs");
    return 0.0;
  }

 private:
  /// A point whose elastic trial (in `stress`) yields: the return onto the surface.
  void return_from_trial(Voigt& stress) const;

  MohrCoulombParameters parameters_;
  MohrCoulombStrength strength_;
  PrincipalStiffness stiffness_;
  ReturnDirections directions_;         ///< of strength_ and stiffness_, formed once
  ElasticStiffness elastic_stiffness_;  ///< λ, 2G for the trial stress
};

}  // namespace ffp
