#pragma once
/// A saturated elastic soil column in uniaxial strain (rollers on the axis and the outer
/// wall, a fixed impermeable base, a drained free top), the model of the two-phase
/// verification tests, and the figures they read from it.
#include <cmath>
#include <optional>
#include <vector>

#include "models/consolidation_solutions.hpp"
#include "models/math_constants.hpp"
#include "mpm/simulation.hpp"
#include "mpm_test_support.hpp"

namespace ffp::mpm::testing {

struct SaturatedColumn {
  double height_m = 1.0;
  int cells = 20;  ///< along z; square cells, two of them across
  double constrained_modulus_Pa = 10e6;
  double poisson_ratio = 0.25;
  double dry_density_kg_m3 = 1600.0;
  double porosity = 0.4;
  double permeability_m_s = 1e-3;
  double fluid_bulk_modulus_Pa = 2.2e9;
  ShapeFunction shape = ShapeFunction::gimp;
  std::optional<double> gravity_m_s2;  ///< with it, a K0 start at rest with the water table at the top
  double k0 = 1.0 / 3.0;               ///< ν/(1 − ν) of ν = 0.25: the elastic column's own K0
  Drainage bottom = Drainage::impermeable;

  double cell_m() const { return height_m / cells; }
  double youngs_modulus_Pa() const {
    const double nu = poisson_ratio;
    return constrained_modulus_Pa * (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu);
  }
  double fluid_density_kg_m3() const { return 1000.0; }
  double saturated_density_kg_m3() const { return dry_density_kg_m3 + porosity * fluid_density_kg_m3(); }
  /// The undrained share of a 1D load the pore fluid takes: (K_w/n)/(E_c + K_w/n).
  double undrained_share() const {
    return ::ffp::undrained_share(constrained_modulus_Pa, fluid_bulk_modulus_Pa, porosity);
  }
  /// Terzaghi's coefficient of consolidation with a compressible fluid, c_v = k/(γ_w (1/E_c + n/K_w)).
  double consolidation_coefficient_m2_s() const {
    return ::ffp::consolidation_coefficient(permeability_m_s, fluid_density_kg_m3(), constrained_modulus_Pa, porosity,
                                            fluid_bulk_modulus_Pa, kConductivityGravity_m_s2);
  }

  ModelDescription model() const {
    const double h = cell_m();
    ModelDescription m;
    m.r_nodes_m = nodes(0.0, 2 * h, 2);
    m.z_nodes_m = nodes(0.0, height_m, cells);
    std::optional<GeostaticStress> geostatic;
    if (gravity_m_s2) geostatic = GeostaticStress{k0, height_m};
    BodyDescription soil = elastic_body("soil", youngs_modulus_Pa(), poisson_ratio, dry_density_kg_m3,
                                        BoxRegion{0.0, 2 * h, 0.0, height_m}, 0.0, 0.0, 2, geostatic);
    soil.saturated = SaturatedSoil{porosity, permeability_m_s, PermeabilityLaw::constant};
    m.bodies.push_back(soil);
    m.gravity_m_s2 = gravity_m_s2;
    m.boundaries = {Fixity::roller, Fixity::roller, Fixity::fixed, Fixity::free};
    m.drainage.bottom = bottom;
    m.fluid.bulk_modulus_Pa = fluid_bulk_modulus_Pa;
    m.fluid.density_kg_m3 = fluid_density_kg_m3();
    m.solver.shape_function = shape;
    return m;
  }
};

/// A top pressure p(t) on the whole column (the total stress it adds is −p on σ_zz).
inline SurfacePressure top_pressure(double width_m, std::function<double(double)> pressure_Pa) {
  SurfacePressure load;
  load.side = Side::top;
  load.r_min_m = 0.0;
  load.r_max_m = width_m;
  load.pressure_Pa = std::move(pressure_Pa);
  return load;
}

/// Each cell row's mean of a particle figure, by the rows the particles start in: the
/// value of the row's one (smoothed) pore pressure, compared at the row's centre.
template <class Figure>
std::vector<double> row_means(const Simulation& s, Figure&& figure) {
  const int rows = s.grid.z.cells();
  std::vector<double> sum(static_cast<std::size_t>(rows), 0.0), count(static_cast<std::size_t>(rows), 0.0);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    const auto row = static_cast<std::size_t>(s.grid.z.cell_of(s.particles.z0[p]));
    sum[row] += figure(p);
    count[row] += 1.0;
  }
  for (std::size_t r = 0; r < sum.size(); ++r) sum[r] = count[r] > 0 ? sum[r] / count[r] : 0.0;
  return sum;
}

}  // namespace ffp::mpm::testing
