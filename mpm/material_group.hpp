#pragma once
/// A material group: one constitutive law, its parameters and its per-particle
/// states (one contiguous vector, of the law's State type), for a contiguous
/// range of particles. A group updates all its particles in one batch call: the
/// variant is visited once per batch, never per particle. Which law it is, is
/// models/material_law.hpp's business: nothing here names one.
#include <cstddef>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "models/elastic.hpp"
#include "models/material_law.hpp"
#include "models/state_output.hpp"
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
  std::size_t begin = 0;  ///< first particle
  std::size_t end = 0;    ///< one past the last particle
  MaterialStates states;  ///< one per particle, [0, size()) for particles [begin, end)

  MaterialGroup(std::string name, MaterialLaw law, double density_kg_m3);

  std::size_t size() const { return end - begin; }
  const ElasticConstants& elastic() const { return elastic_constants(law); }
  /// Constrained modulus M = λ + 2G (c_p = √(M/ρ) at the current density).
  double constrained_modulus() const { return elastic().constrained_modulus(); }

  /// Particles [first, last) (absolute indices inside [begin, end)):
  /// σ ← law(σ, Δε). `dt_s` feeds rate-dependent laws.
  void update(std::size_t first, std::size_t last, std::span<Voigt> stress, std::span<const Voigt> strain_increment,
              double dt_s);

  /// out[p] for p in [begin, end): the law's `output` of particle p's state at σ = stress[p]
  /// (absolute indices). Leaves `out` as it is when the law has no such output.
  void state_output(StateOutput output, std::span<const Voigt> stress, std::span<double> out) const;

  /// Recoverable elastic energy density w = s:s/(4G) + (tr σ)²/(18K) (J/m³).
  double elastic_energy_density(const Voigt& stress) const;
};

}  // namespace ffp::mpm
