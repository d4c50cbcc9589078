#include "mpm/generate_particles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/initial_stress.hpp"

namespace ffp::mpm {

namespace {

bool inside(const BoxRegion& box, double r, double z) {
  return r >= box.r_min_m && r <= box.r_max_m && z >= box.z_min_m && z <= box.z_max_m;
}

bool inside(const Region& region, double r, double z) {
  if (const auto* box = std::get_if<BoxRegion>(&region)) return inside(*box, r, z);
  if (const auto* shape = std::get_if<ShapeRegion>(&region)) return shape->contains(r, z);
  const auto& sphere = std::get<SphereRegion>(region);
  const double dz = z - sphere.center_z_m;
  return r * r + dz * dz <= sphere.radius_m * sphere.radius_m;
}

void check_body(const BodyDescription& body, std::uint8_t body_index, std::span<const SeedingZone> zones) {
  if (body.particles_per_cell_r < 1 || body.particles_per_cell_z < 1)
    throw std::invalid_argument("body " + body.name + ": particles per cell must be ≥ 1");
  if (!(body.density_kg_m3 > 0.0)) throw std::invalid_argument("body " + body.name + ": density must be > 0");
  for (const SeedingZone& zone : zones)
    if (zone.body == body_index && !(zone.spacing_r_m > 0.0 && zone.spacing_z_m > 0.0))
      throw std::invalid_argument("body " + body.name + ": a seeding zone's particle spacing must be > 0");
}

/// Calls seed(r, z, h_r, h_z) at every particle position of the body, cell by
/// cell along the longer grid direction first; stops early when seed returns false.
template <class Seed>
void for_each_seed(const GridAxis& R, const GridAxis& Z, const BodyDescription& body, std::uint8_t body_index,
                   std::span<const SeedingZone> zones, Seed&& seed) {
  const int cells_r = R.cells(), cells_z = Z.cells();
  const bool r_outer = cells_r >= cells_z;  // same rule as ParticleBins::configure
  const int outer_count = r_outer ? cells_r : cells_z, inner_count = r_outer ? cells_z : cells_r;
  for (int outer = 0; outer < outer_count; ++outer) {
    for (int inner = 0; inner < inner_count; ++inner) {
      const int i = r_outer ? outer : inner, j = r_outer ? inner : outer;
      int nr = body.particles_per_cell_r, nz = body.particles_per_cell_z;
      const double centre_r = R.coordinate(i) + 0.5 * R.spacing(i);
      const double centre_z = Z.coordinate(j) + 0.5 * Z.spacing(j);
      for (const SeedingZone& zone : zones) {
        if (zone.body != body_index || !inside(zone.region, centre_r, centre_z)) continue;
        nr = std::max(1, static_cast<int>(std::lround(R.spacing(i) / zone.spacing_r_m)));
        nz = std::max(1, static_cast<int>(std::lround(Z.spacing(j) / zone.spacing_z_m)));
        break;
      }
      const double hr = R.spacing(i) / nr, hz = Z.spacing(j) / nz;
      for (int a = 0; a < nr; ++a) {
        for (int b = 0; b < nz; ++b) {
          const double r = R.coordinate(i) + (a + 0.5) * hr;
          const double z = Z.coordinate(j) + (b + 0.5) * hz;
          if (inside(body.region, r, z) && !seed(r, z, hr, hz)) return;
        }
      }
    }
  }
}

}  // namespace

void append_body_particles(const Grid& grid, const BodyDescription& body, std::uint8_t body_index,
                           double geostatic_unit_weight_N_m3, Particles& particles,
                           std::span<const SeedingZone> zones) {
  check_body(body, body_index, zones);
  const double unit_weight = geostatic_unit_weight_N_m3;
  for_each_seed(grid.r, grid.z, body, body_index, zones, [&](double r, double z, double hr, double hz) {
    const std::size_t p = particles.size();
    particles.resize(p + 1);
    particles.body[p] = body_index;
    particles.r[p] = particles.r0[p] = r;
    particles.z[p] = particles.z0[p] = z;
    particles.vr[p] = body.initial_velocity_r_m_s;
    particles.vz[p] = body.initial_velocity_z_m_s;
    particles.volume[p] = r * hr * hz;
    particles.mass[p] = body.density_kg_m3 * particles.volume[p];
    particles.half_r[p] = 0.5 * hr;
    particles.half_z[p] = 0.5 * hz;
    if (body.initial_stress) particles.stress[p] = geostatic_stress(*body.initial_stress, unit_weight, z);
    return true;
  });
}

std::size_t count_body_particles(const GridAxis& r_axis, const GridAxis& z_axis, const BodyDescription& body,
                                 std::uint8_t body_index, std::span<const SeedingZone> zones, std::size_t limit) {
  check_body(body, body_index, zones);
  std::size_t count = 0;
  for_each_seed(r_axis, z_axis, body, body_index, zones,
                [&](double, double, double, double) { return ++count < limit; });
  return count;
}

}  // namespace ffp::mpm
