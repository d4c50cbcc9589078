#include "mpm/nodal_field.hpp"

#include <algorithm>

namespace ffp::mpm {

void NodalField::resize(std::size_t nodes) {
  for (auto* a : {&mass, &momentum_r, &momentum_z, &internal_force_r, &internal_force_z, &external_force_r,
                  &external_force_z, &velocity_r, &velocity_z, &velocity_new_r, &velocity_new_z})
    a->assign(nodes, 0.0);
}

void NodalField::reset() {
  for (auto* a :
       {&mass, &momentum_r, &momentum_z, &internal_force_r, &internal_force_z, &external_force_r, &external_force_z})
    std::fill(a->begin(), a->end(), 0.0);
}

}  // namespace ffp::mpm
