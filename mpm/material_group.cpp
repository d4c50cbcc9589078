#include "mpm/material_group.hpp"

namespace ffp::mpm {

MaterialGroup::MaterialGroup(std::string group_name, MaterialLaw material_law, double density)
    : name(std::move(group_name)),
      law(std::move(material_law)),
      density_kg_m3(density),
      states(initial_states(law, 0)) {}

void MaterialGroup::update(std::size_t first, std::size_t last, std::span<Voigt> stress,
                           std::span<const Voigt> strain_increment, double dt_s) {
  const std::size_t n = last - first;
  ffp::update(law, stress.subspan(first, n), strain_increment.subspan(first, n), states, first - begin, dt_s);
}

void MaterialGroup::state_output(StateOutput output, std::span<const Voigt> stress, std::span<double> out) const {
  if (!has_state_output(law, output)) return;
  ffp::state_output(law, states, 0, stress.subspan(begin, size()), output, out.subspan(begin, size()));
}

double MaterialGroup::elastic_energy_density(const Voigt& stress) const {
  const ElasticConstants& e = elastic();
  const Voigt s = deviator(stress);
  const double t = trace(stress);
  return contract(s, s) / (4.0 * e.shear_modulus()) + t * t / (18.0 * e.bulk_modulus());
}

}  // namespace ffp::mpm
