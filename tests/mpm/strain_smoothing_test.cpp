/// strain_smoothing full: every particle of a cell takes the cell's volume-weighted
/// mean strain increment, and the internal force takes the cell's mean stress, its
/// transpose (so the internal work matches the strain work term by term).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "mpm/simulation.hpp"
#include "mpm/stages.hpp"
#include "mpm_test_support.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {

/// A 0.1 m elastic block on the axis, 5 × 5 cells of 3 × 3 particles, full smoothing.
Simulation smoothed_block() {
  ModelDescription m;
  m.r_nodes_m = testing::nodes(0.0, 0.1, 5);
  m.z_nodes_m = testing::nodes(0.0, 0.1, 5);
  m.bodies.push_back(testing::elastic_body("b", 1e6, 0.3, 1000.0, BoxRegion{0.0, 0.1, 0.0, 0.1}, 0.0, 0.0, 3));
  m.solver.transfer = Transfer::usl;
  m.solver.strain_smoothing = StrainSmoothing::full;
  Simulation s(m);
  compute_shape_functions(s);  // the particles' cells
  return s;
}

/// σ:ε with Voigt's tensor shear (ε_rz stored, counted twice).
double work_density(const Voigt& sigma, const Voigt& epsilon) {
  return sigma[0] * epsilon[0] + sigma[1] * epsilon[1] + sigma[2] * epsilon[2] + 2.0 * sigma[3] * epsilon[3];
}

/// A different, smooth-free value per particle (no two alike).
Voigt varied(std::size_t p, double scale) {
  const double x = static_cast<double>(p);
  return (Voigt() << std::sin(x), std::cos(1.3 * x), std::sin(0.7 * x + 1.0), std::cos(2.1 * x), 0.0, 0.0).finished() *
         scale;
}

}  // namespace

TEST_CASE("full strain smoothing: every particle of a cell gets the cell's volume-weighted mean strain increment",
          "[mpm][smoothing]") {
  Simulation s = smoothed_block();
  REQUIRE(s.stages.contains("smooth_strain_increment"));
  REQUIRE_FALSE(s.stages.contains("smooth_volumetric_strain"));
  const std::size_t n = s.particles.size();
  std::map<std::size_t, Voigt> weighted;
  std::map<std::size_t, double> volume;
  for (std::size_t p = 0; p < n; ++p) {
    s.strain_increment[p] = varied(p, 1e-4);
    s.particles.volume[p] *= 1.0 + 0.1 * std::sin(3.0 * static_cast<double>(p));  // unequal weights
    weighted.try_emplace(s.cell[p], Voigt::Zero()).first->second += s.particles.volume[p] * s.strain_increment[p];
    volume[s.cell[p]] += s.particles.volume[p];
  }
  REQUIRE(volume.size() == 25);
  smooth_strain_increment(s);
  for (std::size_t p = 0; p < n; ++p) {
    const Voigt mean = weighted.at(s.cell[p]) / volume.at(s.cell[p]);
    INFO("particle " << p);
    CHECK((s.strain_increment[p] - mean).norm() <= 1e-14 * 1e-4);
  }

  // A uniform field is its own mean: unchanged.
  const Voigt uniform = (Voigt() << 2e-4, -1e-4, 3e-5, 5e-5, 0.0, 0.0).finished();
  for (std::size_t p = 0; p < n; ++p) s.strain_increment[p] = uniform;
  smooth_strain_increment(s);
  for (std::size_t p = 0; p < n; ++p) CHECK((s.strain_increment[p] - uniform).norm() <= 1e-15 * uniform.norm());
}

TEST_CASE("full strain smoothing: the internal force is the transpose of the smoothed strain (work balance)",
          "[mpm][smoothing]") {
  // For any nodal velocity v: Σ_i f_i·v_i Δt = −Σ_p V_p σ_p : Δε_p with Δε_p the
  // cell-mean increment, when f takes each particle's cell-mean stress. With the
  // cell-mean strain but the particle's own stress in f the two differ.
  Simulation s = smoothed_block();
  const std::size_t n = s.particles.size();
  for (std::size_t p = 0; p < n; ++p) s.particles.stress[p] = varied(p + 7, 1e3);
  std::vector<double> volume = s.particles.volume;  // the strain update changes V_p
  reset_grid(s);
  map_particles_to_grid(s);
  smooth_mean_stress(s);
  compute_internal_forces(s);
  NodalField& f = s.grid.fields[0];
  double internal_work = 0.0;
  for (std::size_t i = 0; i < f.mass.size(); ++i) {
    const double x = static_cast<double>(i);
    f.velocity_new_r[i] = 1e-3 * std::cos(0.9 * x);
    f.velocity_new_z[i] = 1e-3 * std::sin(1.7 * x + 0.3);
    internal_work +=
        s.dt_s * (f.internal_force_r[i] * f.velocity_new_r[i] + f.internal_force_z[i] * f.velocity_new_z[i]);
  }
  compute_strain_increments(s, StrainVelocity::updated_grid);
  s.particles.volume = volume;  // the same weights on both sides: the identity is then exact
  smooth_strain_increment(s);
  double strain_work = 0.0, scale = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    strain_work += volume[p] * work_density(s.particles.stress[p], s.strain_increment[p]);
    scale += volume[p] * s.particles.stress[p].norm() * s.strain_increment[p].norm();
  }
  INFO("internal work " << internal_work << ", strain work " << strain_work);
  CHECK(std::abs(internal_work + strain_work) <= 1e-12 * scale);
}
