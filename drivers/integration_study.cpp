#include "drivers/integration_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace ffp {

namespace {

using Clock = std::chrono::steady_clock;

struct Curve {
  std::vector<double> axial, q, volumetric;
};

Curve curve_of(const PointHistory& h) {
  Curve c;
  for (const PointRecord& r : h.records) {
    c.axial.push_back(-r.strain[1]);
    c.q.push_back(deviatoric_stress(r.stress));
    c.volumetric.push_back(-trace(r.strain));
  }
  return c;
}

/// Linear interpolation in a curve with increasing abscissae.
double at(const std::vector<double>& x, const std::vector<double>& y, double xi) {
  const auto it = std::lower_bound(x.begin(), x.end(), xi);
  if (it == x.begin()) return y.front();
  if (it == x.end()) return y.back();
  const std::size_t j = static_cast<std::size_t>(it - x.begin());
  const double w = (xi - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + w * (y[j] - y[j - 1]);
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double peak(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

/// One law update from (σ, state) in `substeps` equal parts. dt = 0: the map
/// is about the return, not the rate law (the rate stays as it was).
Voigt integrate(const PointLaw& law, Voigt stress, MaterialState state, const Voigt& increment, int substeps) {
  const Voigt part = increment / substeps;
  for (int k = 0; k < substeps; ++k) update(law, stress, part, state, 0.0);
  return stress;
}

double frobenius(const Voigt& v) { return std::sqrt(contract(v, v)); }

}  // namespace

PointConfig drained_triaxial_config(const PointLaw& law, double cell_pressure_Pa, double axial_strain_max,
                                    double strain_rate_per_s, int increments) {
  PointConfig config;
  config.law = law;
  config.initial_state = initial_state(law);
  config.initial_stress << -cell_pressure_Pa, -cell_pressure_Pa, -cell_pressure_Pa, 0, 0, 0;
  PathSegment segment;
  segment.control = {Control::stress, Control::strain, Control::stress,
                     Control::strain, Control::strain, Control::strain};
  segment.target << -cell_pressure_Pa, -axial_strain_max, -cell_pressure_Pa, 0, 0, 0;
  segment.increments = increments;
  segment.duration_s = axial_strain_max / strain_rate_per_s;
  config.segments = {segment};
  return config;
}

TriaxialErrorResult run_triaxial_error_study(const TriaxialErrorStudy& study,
                                             const std::function<void(const std::string&)>& on_stage) {
  TriaxialErrorResult result;
  auto config_for = [&](int n) {
    return drained_triaxial_config(study.law, study.cell_pressure_Pa, study.axial_strain_max, study.strain_rate_per_s,
                                   n);
  };
  if (on_stage) on_stage("reference, " + std::to_string(study.reference_increments) + " increments");
  const auto reference_start = Clock::now();
  const Curve reference = curve_of(integrate_point(config_for(study.reference_increments)));
  result.reference_wall_time_s = std::chrono::duration<double>(Clock::now() - reference_start).count();
  result.total_increments += study.reference_increments;
  const double reference_peak = peak(reference.q);
  const double volumetric_scale = std::max(max_abs(reference.volumetric), 1e-300);
  result.reference_peak_q_kPa = 1e-3 * reference_peak;
  result.reference_final_volumetric_strain = reference.volumetric.back();

  for (int n : study.increments) {
    if (on_stage) on_stage(std::to_string(n) + " increments");
    const PointConfig config = config_for(n);
    PointHistory history;
    int repeats = 0;
    const auto start = Clock::now();
    double elapsed = 0.0;
    do {
      history = integrate_point(config);
      ++repeats;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < study.min_timing_s);
    result.total_increments += static_cast<long>(repeats) * n;
    const Curve c = curve_of(history);
    TriaxialErrorRow row;
    row.increments = n;
    row.wall_time_s = elapsed / repeats;
    for (std::size_t i = 0; i < reference.axial.size(); ++i) {
      const double x = reference.axial[i];
      row.q_error_path = std::max(row.q_error_path, std::abs(at(c.axial, c.q, x) - reference.q[i]));
      row.volumetric_error_path =
          std::max(row.volumetric_error_path, std::abs(at(c.axial, c.volumetric, x) - reference.volumetric[i]));
    }
    row.q_error = std::abs(c.q.back() - reference.q.back()) / reference_peak;
    row.volumetric_error = std::abs(c.volumetric.back() - reference.volumetric.back()) / volumetric_scale;
    row.q_error_path /= reference_peak;
    row.volumetric_error_path /= volumetric_scale;
    row.peak_q_kPa = 1e-3 * peak(c.q);
    row.peak_q_error = std::abs(peak(c.q) - reference_peak) / reference_peak;
    result.rows.push_back(row);
  }
  return result;
}

IsoErrorMap run_iso_error_map(const IsoErrorMapStudy& study) {
  const ElasticConstants& elastic = elastic_constants(study.law);
  const MaterialState state = initial_state(study.law);
  // The starting stresses need the friction angle the law has at its start.
  const std::optional<MohrCoulombParameters> strength = mohr_coulomb_strength(study.law, state, study.confining_Pa);
  if (!strength) throw std::invalid_argument("iso-error maps need a Mohr-Coulomb type law");
  const double phi = strength->friction_angle_rad, cohesion = strength->cohesion_Pa;
  // On the surface with σ3 = confining (compression): σ1' = σ3' Nφ + 2c √Nφ.
  const double n_phi = (1.0 + std::sin(phi)) / (1.0 - std::sin(phi));
  const double minor = study.confining_Pa;
  const double major = minor * n_phi + 2.0 * cohesion * std::sqrt(n_phi);
  Voigt edge = Voigt::Zero(), plane = Voigt::Zero();
  edge << -minor, -major, -minor, 0, 0, 0;                   // triaxial compression at failure
  plane << -minor, -major, -0.5 * (minor + major), 0, 0, 0;  // σ2 midway: on the face
  Voigt start = Voigt::Zero();
  if (study.start == MapStart::edge) start = edge;
  if (study.start == MapStart::plane) start = plane;
  if (study.start == MapStart::apex) {
    const double apex = std::sin(phi) > 0.0 ? cohesion / std::tan(phi) : 0.0;
    start << apex, apex, apex, 0, 0, 0;
  }

  IsoErrorMap map;
  map.start_stress = start;
  map.yield_strain = (major - minor) / (3.0 * elastic.shear_modulus());
  const double scale = frobenius(plane);
  // Unit deviatoric strain directions (√(2/3 e:e) = 1): axial compression, and Lode.
  Voigt along = Voigt::Zero(), across = Voigt::Zero();
  along << 0.5, -1.0, 0.5, 0, 0, 0;
  across << 1.0, 0.0, -1.0, 0, 0, 0;
  along /= deviatoric_strain(along);
  across /= deviatoric_strain(across);

  for (int i = 0; i < study.points_x; ++i) map.x.push_back(study.max_multiple * i / std::max(study.points_x - 1, 1));
  for (int j = 0; j < study.points_y; ++j)
    map.y.push_back(-study.max_multiple + 2.0 * study.max_multiple * j / std::max(study.points_y - 1, 1));
  for (double y : map.y) {
    for (double x : map.x) {
      const Voigt increment = map.yield_strain * (x * along + y * across);
      const Voigt one_step = integrate(study.law, start, state, increment, 1);
      const Voigt reference = integrate(study.law, start, state, increment, study.reference_substeps);
      map.error.push_back(frobenius(one_step - reference) / scale);
      map.updates += 1 + study.reference_substeps;
    }
  }
  return map;
}

}  // namespace ffp
