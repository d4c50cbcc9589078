#include "mpm/particles.hpp"

namespace ffp::mpm {

void Particles::resize(std::size_t n) {
  body.resize(n, 0);
  for (auto* a : {&r, &z, &vr, &vz, &mass, &volume, &half_r, &half_z, &r0, &z0}) a->resize(n, 0.0);
  stress.resize(n, Voigt::Zero());
  strain.resize(n, Voigt::Zero());
}

}  // namespace ffp::mpm
