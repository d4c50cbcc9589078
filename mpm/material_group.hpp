#pragma once
/// A material group: one constitutive law, its parameters and (where the law
/// has any) per-particle state, for a contiguous range of particles. A group
/// updates all its particles in one batch call: the variant is visited once
/// per batch, never per particle.
#include <cstddef>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "models/elastic.hpp"
#include "models/material_law.hpp"
#include "models/mohr_coulomb.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"
#include "models/voigt.hpp"

namespace ffp::mpm {

using MaterialLaw = ffp::MaterialLaw;

struct MaterialGroup {
  std::string name;
  MaterialLaw law;
  double density_kg_m3 = 0.0;  ///< reference (initial) density
  /// A granular material whose particle density falls below this value has lost
  /// grain contact: its stress is zero (a disconnected, stress-free state, as in
  /// Dunatunga & Kamrin 2015, J. Fluid Mech. 779), and the CFL step takes its wave
  /// speed at this density. Without it, soil thrown up or stretched around the
  /// axis (measured in the FFP run: particles at 1/50 of their initial density)
  /// makes √(M/ρ) seven times the sand's and the step seven times shorter.
  /// 0: never (continua that may not lose contact).
  double disconnected_below_kg_m3 = 0.0;
  std::size_t begin = 0;       ///< first particle
  std::size_t end = 0;         ///< one past the last particle
  std::vector<StrainSofteningMohrCoulomb::State> ssmc_state;  ///< one per particle for SSMC, else empty

  MaterialGroup(std::string name, MaterialLaw law, double density_kg_m3);

  std::size_t size() const { return end - begin; }
  const ElasticConstants& elastic() const;
  /// Constrained modulus M = λ + 2G (c_p = √(M/ρ) at the current density).
  double constrained_modulus() const { return elastic().constrained_modulus(); }

  /// Particles [first, last) (absolute indices inside [begin, end)):
  /// σ ← law(σ, Δε). `dt_s` feeds rate-dependent laws.
  void update(std::size_t first, std::size_t last, std::span<Voigt> stress, std::span<const Voigt> strain_increment,
              double dt_s);

  /// Recoverable elastic energy density w = s:s/(4G) + (tr σ)²/(18K) (J/m³).
  double elastic_energy_density(const Voigt& stress) const;
};

}  // namespace ffp::mpm
