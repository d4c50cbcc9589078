#pragma once
/// A saturated `mpm` run as the saturated-sand verification reads it: the column's
/// parameters from the scene the run echoed back (never retyped), and its probes'
/// histories (one particle each, SI units, pore pressure and stress in Pa).
#include <optional>
#include <string>
#include <vector>

#include "models/consolidation_solutions.hpp"
#include "reports/study.hpp"

namespace ffp {

struct SaturatedParameters {
  double constrained_modulus_Pa = 0.0, poisson_ratio = 0.0, dry_density_kg_m3 = 0.0;
  double porosity = 0.0, permeability_m_s = 0.0, initial_excess_pressure_Pa = 0.0;
  double fluid_bulk_modulus_Pa = 0.0, fluid_density_kg_m3 = 0.0;
  double gravity_m_s2 = 0.0;  ///< 0 without gravity
  double top_m = 0.0;         ///< the body's top, z_max of its region
  double radius_m = 0.0;      ///< the body's outer radius
  double cell_r_m = 0.0, cell_z_m = 0.0;
  double load_Pa = 0.0, ramp_s = 0.0;  ///< the first top pressure, if any
  std::optional<double> k0;            ///< the K0 of initial_stress, if any

  double undrained_share() const;
  double consolidation_coefficient_m2_s() const;
  BiotColumn biot() const;
};

struct ProbeHistory {
  std::string name;
  double r0_m = 0.0, z0_m = 0.0;  ///< where its particle starts (the first row)
  std::vector<double> r_m, z_m, pore_pressure_Pa, excess_pressure_Pa, stress_rr_Pa, stress_zz_Pa;
};

struct SaturatedRun {
  SaturatedParameters parameters;
  std::vector<double> time_s;
  std::vector<ProbeHistory> probes;
  double wall_time_s = 0.0;
  long steps = 0;
};

/// The run's figures, or none when it failed or its outputs lack what is read here.
std::optional<SaturatedRun> read_saturated_run(const StudyResults& results, std::size_t run);

/// The index of the row whose time is nearest t.
std::size_t nearest_row(const std::vector<double>& time_s, double t_s);

}  // namespace ffp
