#pragma once
/// Drained triaxial element test on a weightless cylindrical specimen: the
/// numbers behind the `triaxial` scene kind and the "numerical triaxial" the
/// calibration of η runs (paper section 4.2). Pure numerics: no files, no output.
///
/// One material point stands for the whole specimen (homogeneous stress and
/// strain): constant cell pressure σ3 on the two radial components (stress
/// controlled), axial strain ε_a driven to `axial_strain_max` in equal
/// increments (component 22, see drivers/point_integrator.hpp).
///
/// The specimen turns stresses into what a load frame measures:
///   axial (piston) force  F = q·A,  A = π D²/4 (constant: no area correction)
///   axial displacement    δ = ε_a·H
/// and the "dissipated work" of the paper's calibration is the area under that
/// curve, W = ∫ F dδ = V ∫ q dε_a, integrated by the trapezoid rule on every
/// increment (see `area_under`).
///
/// W is the piston's deviatoric work only; it is not what the law dissipates.
/// Per unit volume, σ:dε = q dε_a + σ3 dε_v (compression positive), so
///   W = W_plastic + ΔU_elastic − W_cell,  W_cell = σ3·V·ε_v,
/// the cell doing positive work on a contracting specimen and negative work on a
/// dilating one. The result carries every term; the identity holds to the
/// Newton tolerance on σ3 because the integrator's works use the same
/// mid-increment stress as the trapezoid.
#include <functional>
#include <span>
#include <vector>

#include "drivers/point_integrator.hpp"

namespace ffp {

/// The paper's specimen (section 4.2, after Albatal 2018): 0.15 m high, 0.07 m wide.
struct TriaxialSpecimen {
  double height_m = 0.15;
  double diameter_m = 0.07;

  double area_m2() const;
  double volume_m3() const;
};

struct TriaxialTestConfig {
  PointLaw law = LinearElastic(ElasticConstants{});
  double cell_pressure_Pa = 1.72e3;  ///< σ3 > 0 (compression), the paper's 10.5 cm depth
  double axial_strain_max = 0.2;     ///< compression positive
  int increments = 1000;
  double strain_rate_per_s = 1e-4;  ///< only the rate law sees it (quasi-static default)
  TriaxialSpecimen specimen;
  NewtonSettings newton;
};

/// The test after every increment (index 0: the isotropic start). Geotechnical
/// signs: compression positive for strains and stresses.
struct TriaxialResult {
  PointHistory history;  ///< every increment, as the point integrator recorded it
  std::vector<double> axial_strain;
  std::vector<double> volumetric_strain;
  std::vector<double> deviatoric_stress_Pa;  ///< q
  std::vector<double> mean_stress_Pa;        ///< p'
  std::vector<double> axial_displacement_m;  ///< δ = ε_a H
  std::vector<double> axial_force_N;         ///< F = q A
  std::vector<double> dissipated_work_J;     ///< ∫₀^δ F dδ so far (trapezoid)
  std::vector<double> plastic_work_J;        ///< V Σ σ:Δε^p so far (the law's dissipation)

  double peak_q_Pa = 0.0;
  double axial_strain_at_peak = 0.0;  ///< first strain where q is within 1e-8 of its peak
  double residual_q_Pa = 0.0;         ///< q at the end of the test
  double dissipated_work_J_total = 0.0;
  double plastic_work_J_total = 0.0;
  double elastic_energy_change_J = 0.0;  ///< V [U(σ_end) − U(σ_start)], U = ½ σ:C:σ
  double cell_work_J = 0.0;              ///< σ3 V ε_v,end: work of the cell pressure on the specimen
};

/// Throws PointIntegrationFailure if an increment does not converge and
/// std::invalid_argument for a config that is not a test (non-positive σ3, ...).
TriaxialResult run_triaxial_test(const TriaxialTestConfig& config,
                                 const std::function<void(long done, long total)>& on_step = {});

/// ∫ y dx over [from, to] by the trapezoid rule on the points (x increasing),
/// the end intervals cut by linear interpolation: exactly the area under the
/// polyline through the points. Throws std::invalid_argument if [from, to]
/// is not inside [x.front(), x.back()].
double area_under(std::span<const double> x, std::span<const double> y, double from, double to);

/// y at xi by linear interpolation (x increasing; xi inside [x.front(), x.back()]).
double interpolate_linear(std::span<const double> x, std::span<const double> y, double xi);

}  // namespace ffp
