#pragma once
/// Isotropic linear elasticity: the constants every law shares and the
/// linear elastic law itself.
#include <cassert>
#include <cmath>
#include <span>

#include "models/return_region.hpp"
#include "models/state_output.hpp"
#include "models/voigt.hpp"

namespace ffp {

struct ElasticConstants {
  double youngs_modulus_Pa = 0.0;
  double poisson_ratio = 0.0;

  double shear_modulus() const { return youngs_modulus_Pa / (2.0 * (1.0 + poisson_ratio)); }
  double bulk_modulus() const { return youngs_modulus_Pa / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double lame_lambda() const {
    return youngs_modulus_Pa * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  /// Constrained (oedometric, P-wave) modulus M = λ + 2G.
  double constrained_modulus() const { return lame_lambda() + 2.0 * shear_modulus(); }
  /// P-wave speed c_p = √(M/ρ): the speed the explicit CFL step must resolve.
  double p_wave_speed(double density_kg_m3) const { return std::sqrt(constrained_modulus() / density_kg_m3); }

  /// Δσ = λ tr(Δε) I + 2G Δε.
  Voigt stress_increment(const Voigt& strain_increment) const {
    const double lambda_tr = lame_lambda() * trace(strain_increment);
    Voigt ds = 2.0 * shear_modulus() * strain_increment;
    ds[0] += lambda_tr;
    ds[1] += lambda_tr;
    ds[2] += lambda_tr;
    return ds;
  }
};

/// λ and 2G of a set of ElasticConstants, computed once: the elastic trial of a
/// law's update without the divisions of lame_lambda() and shear_modulus() per
/// point. Same operations on the same values, so the same bits as
/// ElasticConstants::stress_increment.
struct ElasticStiffness {
  double lambda = 0.0;     ///< λ = Eν/((1 + ν)(1 − 2ν))
  double two_shear = 0.0;  ///< 2G = 2·E/(2(1 + ν))

  static ElasticStiffness of(const ElasticConstants& e) { return {e.lame_lambda(), 2.0 * e.shear_modulus()}; }

  /// Δσ = λ tr(Δε) I + 2G Δε.
  Voigt stress_increment(const Voigt& strain_increment) const {
    const double lambda_tr = lambda * trace(strain_increment);
    Voigt ds = two_shear * strain_increment;
    ds[0] += lambda_tr;
    ds[1] += lambda_tr;
    ds[2] += lambda_tr;
    return ds;
  }
};

/// Linear elastic law (also the FFP body in the deformable comparison runs).
class LinearElastic {
 public:
  struct State {};  // no internal variables

  explicit LinearElastic(const ElasticConstants& elastic) : elastic_(elastic) {}

  const ElasticConstants& elastic() const { return elastic_; }
  double p_wave_speed(double density_kg_m3) const { return elastic_.p_wave_speed(density_kg_m3); }

  void update(Voigt& stress, const Voigt& strain_increment) const {
    stress += elastic_.stress_increment(strain_increment);
  }

  /// Batch update: stress[i] += D : strain_increment[i].
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment) const {
    for (std::size_t i = 0; i < stress.size(); ++i) update(stress[i], strain_increment[i]);
  }

  // The interface every law has (models/material_law.hpp): no state, no rate, no yield surface.
  ReturnRegion update(Voigt& stress, const Voigt& strain_increment, State&, double) const {
    update(stress, strain_increment);
    return ReturnRegion::elastic;
  }
  void update(std::span<Voigt> stress, std::span<const Voigt> strain_increment, std::span<State>, double) const {
    update(stress, strain_increment);
  }
  static std::span<const StateOutput> outputs() { return {}; }
  double output(const State&, double, StateOutput) const {
    assert(false && "a linear elastic law has no state outputs");
    return 0.0;
  }

 private:
  ElasticConstants elastic_;
};

}  // namespace ffp
