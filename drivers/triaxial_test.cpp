#include "drivers/triaxial_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "drivers/integration_study.hpp"
#include "models/math_constants.hpp"

namespace ffp {

double TriaxialSpecimen::area_m2() const { return 0.25 * kPi * diameter_m * diameter_m; }
double TriaxialSpecimen::volume_m3() const { return area_m2() * height_m; }

namespace {

/// Complementary elastic energy density U = ½ σ:C:σ = p²/2K + q²/6G (J/m³).
double elastic_energy_density(const ElasticConstants& e, const Voigt& stress) {
  const double p = mean_pressure(stress);
  const double q = deviatoric_stress(stress);
  return 0.5 * p * p / e.bulk_modulus() + q * q / (6.0 * e.shear_modulus());
}

}  // namespace

double interpolate_linear(std::span<const double> x, std::span<const double> y, double xi) {
  if (x.size() != y.size() || x.empty()) throw std::invalid_argument("interpolate_linear: x and y differ in size");
  if (!(xi >= x.front() && xi <= x.back()))
    throw std::invalid_argument("interpolate_linear: " + std::to_string(xi) + " is outside [" +
                                std::to_string(x.front()) + ", " + std::to_string(x.back()) + "]");
  const auto it = std::lower_bound(x.begin(), x.end(), xi);
  const std::size_t j = static_cast<std::size_t>(it - x.begin());
  if (j == 0) return y.front();
  const double w = (xi - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + w * (y[j] - y[j - 1]);
}

double area_under(std::span<const double> x, std::span<const double> y, double from, double to) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("area_under: needs two or more points");
  // Rounding of a recomputed end strain must not reject a range that ends on the last point.
  const double slack = 1e-12 * std::max(std::abs(x.front()), std::abs(x.back()));
  if (!(from >= x.front() - slack && to <= x.back() + slack && from <= to))
    throw std::invalid_argument("area_under: [" + std::to_string(from) + ", " + std::to_string(to) +
                                "] is not inside the curve's [" + std::to_string(x.front()) + ", " +
                                std::to_string(x.back()) + "]");
  from = std::clamp(from, x.front(), x.back());
  to = std::clamp(to, x.front(), x.back());
  double area = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double a = std::max(x[i - 1], from);
    const double b = std::min(x[i], to);
    if (!(b > a)) continue;
    // Trapezoid on the piece [a, b] of the segment: exact for the polyline.
    const double slope = (y[i] - y[i - 1]) / (x[i] - x[i - 1]);
    const double ya = y[i - 1] + slope * (a - x[i - 1]);
    const double yb = y[i - 1] + slope * (b - x[i - 1]);
    area += 0.5 * (ya + yb) * (b - a);
  }
  return area;
}

TriaxialResult run_triaxial_test(const TriaxialTestConfig& config,
                                 const std::function<void(long done, long total)>& on_step) {
  if (!(config.cell_pressure_Pa > 0.0)) throw std::invalid_argument("triaxial test: cell pressure must be > 0");
  if (!(config.axial_strain_max > 0.0)) throw std::invalid_argument("triaxial test: axial_strain_max must be > 0");
  if (config.increments < 1) throw std::invalid_argument("triaxial test: needs at least one increment");
  if (!(config.specimen.height_m > 0.0 && config.specimen.diameter_m > 0.0))
    throw std::invalid_argument("triaxial test: specimen height and diameter must be > 0");

  PointConfig point = drained_triaxial_config(config.law, config.cell_pressure_Pa, config.axial_strain_max,
                                              config.strain_rate_per_s, config.increments);
  point.newton = config.newton;
  point.record_every = 1;  // the work integral needs every increment, not a thinned output

  TriaxialResult r;
  r.history = integrate_point(point, on_step);
  const double area = config.specimen.area_m2();
  const double height = config.specimen.height_m;
  const double volume = config.specimen.volume_m3();

  const std::size_t n = r.history.records.size();
  for (auto* v : {&r.axial_strain, &r.volumetric_strain, &r.deviatoric_stress_Pa, &r.mean_stress_Pa,
                  &r.axial_displacement_m, &r.axial_force_N, &r.dissipated_work_J, &r.plastic_work_J})
    v->reserve(n);
  double work = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const PointRecord& record = r.history.records[i];
    const double axial = -record.strain[1];
    const double q = deviatoric_stress(record.stress);
    const double force = q * area;
    const double displacement = axial * height;
    if (i > 0) work += 0.5 * (force + r.axial_force_N.back()) * (displacement - r.axial_displacement_m.back());
    r.axial_strain.push_back(axial);
    r.volumetric_strain.push_back(-trace(record.strain));
    r.deviatoric_stress_Pa.push_back(q);
    r.mean_stress_Pa.push_back(mean_pressure(record.stress));
    r.axial_displacement_m.push_back(displacement);
    r.axial_force_N.push_back(force);
    r.dissipated_work_J.push_back(work);
    r.plastic_work_J.push_back(volume * record.plastic_work_J_m3);
  }

  r.peak_q_Pa = *std::max_element(r.deviatoric_stress_Pa.begin(), r.deviatoric_stress_Pa.end());
  // On a perfectly plastic plateau q wanders by rounding: the peak is where q
  // first comes within 1e-8 of its maximum (Newton stops at 1e-10).
  for (std::size_t i = 0; i < n; ++i) {
    if (r.deviatoric_stress_Pa[i] >= r.peak_q_Pa * (1.0 - 1e-8)) {
      r.axial_strain_at_peak = r.axial_strain[i];
      break;
    }
  }
  r.residual_q_Pa = r.deviatoric_stress_Pa.back();
  r.dissipated_work_J_total = work;
  r.plastic_work_J_total = r.plastic_work_J.back();
  const ElasticConstants& elastic = elastic_constants(config.law);
  r.elastic_energy_change_J = volume * (elastic_energy_density(elastic, r.history.records.back().stress) -
                                        elastic_energy_density(elastic, r.history.records.front().stress));
  r.cell_work_J = config.cell_pressure_Pa * volume * r.volumetric_strain.back();
  return r;
}

}  // namespace ffp
