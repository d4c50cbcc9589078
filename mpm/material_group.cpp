#include "mpm/material_group.hpp"

#include <type_traits>

namespace ffp::mpm {

MaterialGroup::MaterialGroup(std::string group_name, MaterialLaw material_law, double density)
    : name(std::move(group_name)), law(std::move(material_law)), density_kg_m3(density) {}

const ElasticConstants& MaterialGroup::elastic() const {
  return std::visit(
      [](const auto& m) -> const ElasticConstants& {
        if constexpr (std::is_same_v<std::decay_t<decltype(m)>, LinearElastic>) {
          return m.elastic();
        } else {
          return m.parameters().elastic;
        }
      },
      law);
}

void MaterialGroup::update(std::size_t first, std::size_t last, std::span<Voigt> stress,
                           std::span<const Voigt> strain_increment, double dt_s) {
  const std::size_t n = last - first;
  auto s = stress.subspan(first, n);
  auto de = strain_increment.subspan(first, n);
  std::visit(
      [&](const auto& m) {
        using Law = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<Law, StrainSofteningMohrCoulomb>) {
          m.update(s, de, std::span(ssmc_state).subspan(first - begin, n), dt_s);
        } else {
          m.update(s, de);
        }
      },
      law);
}

double MaterialGroup::elastic_energy_density(const Voigt& stress) const {
  const ElasticConstants& e = elastic();
  const Voigt s = deviator(stress);
  const double t = trace(stress);
  return contract(s, s) / (4.0 * e.shear_modulus()) + t * t / (18.0 * e.bulk_modulus());
}

}  // namespace ffp::mpm
