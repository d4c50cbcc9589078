#include "mpm/diagnostics.hpp"

#include <cmath>

namespace ffp::mpm {

namespace {

Diagnostics measure_range(const Simulation& s, std::size_t begin, std::size_t end) {
  const Particles& P = s.particles;
  Diagnostics d;
  const double g = s.gravity_m_s2.value_or(0.0);
  for (const MaterialGroup& group : s.groups) {
    const std::size_t first = std::max(begin, group.begin), last = std::min(end, group.end);
    for (std::size_t p = first; p < last; ++p) {
      const double m = P.mass[p];
      const double v2 = P.vr[p] * P.vr[p] + P.vz[p] * P.vz[p];
      d.mass_kg += m;
      d.momentum_z_N_s += m * P.vz[p];
      d.kinetic_energy_J += 0.5 * m * v2;
      d.strain_energy_J += P.volume[p] * group.elastic_energy_density(P.stress[p]);
      d.gravity_energy_J += m * g * P.z[p];
      d.mass_z_kg_m += m * P.z[p];
      d.max_speed_m_s = std::max(d.max_speed_m_s, std::sqrt(v2));
    }
  }
  d.mass_kg *= kTwoPi;
  d.momentum_z_N_s *= kTwoPi;
  d.kinetic_energy_J *= kTwoPi;
  d.strain_energy_J *= kTwoPi;
  d.gravity_energy_J *= kTwoPi;
  d.mass_z_kg_m *= kTwoPi;
  return d;
}

}  // namespace

Diagnostics measure(const Simulation& s) { return measure_range(s, 0, s.particles.size()); }

Diagnostics measure_body(const Simulation& s, std::size_t body) {
  return measure_range(s, s.bodies.at(body).begin, s.bodies.at(body).end);
}

double kinetic_energy_body(const Simulation& s, std::size_t body) {
  const Particles& P = s.particles;
  const std::size_t begin = s.bodies.at(body).begin, end = s.bodies.at(body).end;
  double kinetic = 0.0;
  for (const MaterialGroup& group : s.groups) {  // measure_range's order
    const std::size_t first = std::max(begin, group.begin), last = std::min(end, group.end);
    for (std::size_t p = first; p < last; ++p) {
      const double m = P.mass[p];
      const double v2 = P.vr[p] * P.vr[p] + P.vz[p] * P.vz[p];
      kinetic += 0.5 * m * v2;
    }
  }
  return kinetic * kTwoPi;
}

double vertical_internal_force_N(const NodalField& field, const std::vector<std::size_t>& nodes) {
  double sum = 0.0;
  for (std::size_t i : nodes) sum += field.internal_force_z[i];
  return kTwoPi * sum;
}

}  // namespace ffp::mpm
