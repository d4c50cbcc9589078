#include "models/consolidation_solutions.hpp"

#include <algorithm>
#include <cmath>

#include "models/math_constants.hpp"

namespace ffp {

namespace {

constexpr int kSeriesTerms = 2000;  ///< e^{−M²T} of the last term at T = 1e-5: 1e-43

/// M = π(2m + 1)/2 of Terzaghi's series.
double terzaghi_root(int m) { return kPi * (2 * m + 1) / 2; }

}  // namespace

double Terzaghi::pressure(double depth_m, double t_s) const {
  const double H = height_m, T = consolidation_coefficient_m2_s * t_s / (H * H);
  double sum = 0.0;
  for (int m = 0; m < kSeriesTerms; ++m) {
    const double M = terzaghi_root(m);
    sum += 2.0 / M * std::sin(M * depth_m / H) * std::exp(-M * M * T);
  }
  return initial_pressure_Pa * sum;
}

double Terzaghi::displacement(double depth_m, double t_s) const {
  const double H = height_m, T = consolidation_coefficient_m2_s * t_s / (H * H);
  double sum = 0.0;
  for (int m = 0; m < kSeriesTerms; ++m) {
    const double M = terzaghi_root(m);
    sum += 2.0 * H / (M * M) * std::cos(M * depth_m / H) * std::exp(-M * M * T);
  }
  return initial_pressure_Pa / constrained_modulus_Pa * ((H - depth_m) - sum);
}

double Terzaghi::degree_of_consolidation(double t_s) const {
  const double T = consolidation_coefficient_m2_s * t_s / (height_m * height_m);
  double sum = 0.0;
  for (int m = 0; m < kSeriesTerms; ++m) {
    const double M = terzaghi_root(m);
    sum += 2.0 / (M * M) * std::exp(-M * M * T);
  }
  return 1.0 - sum;
}

double consolidation_coefficient(double permeability_m_s, double fluid_density_kg_m3, double constrained_modulus_Pa,
                                 double porosity, double fluid_bulk_modulus_Pa, double conductivity_gravity_m_s2) {
  return permeability_m_s / (fluid_density_kg_m3 * conductivity_gravity_m_s2 *
                             (1.0 / constrained_modulus_Pa + porosity / fluid_bulk_modulus_Pa));
}

double undrained_share(double constrained_modulus_Pa, double fluid_bulk_modulus_Pa, double porosity) {
  const double fluid = fluid_bulk_modulus_Pa / porosity;
  return fluid / (constrained_modulus_Pa + fluid);
}

std::vector<double> bessel_j0_zeros(int count) {
  std::vector<double> zeros;
  for (int m = 1; m <= count; ++m) {
    double x = (m - 0.25) * kPi;
    for (int k = 0; k < 50; ++k) x += std::cyl_bessel_j(0.0, x) / std::cyl_bessel_j(1.0, x);
    zeros.push_back(x);
  }
  return zeros;
}

double RadialDiffusion::pressure(double r_m, double t_s) const {
  const double R = radius_m;
  double sum = 0.0;
  for (const double a : alpha)
    sum += std::cyl_bessel_j(0.0, a * r_m / R) / (a * std::cyl_bessel_j(1.0, a)) *
           std::exp(-a * a * diffusivity_m2_s * t_s / (R * R));
  return 2.0 * initial_pressure_Pa * sum;
}

double RadialDiffusion::cell_mean(double r0_m, double r1_m, double t_s) const {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  double sum = 0.0, weight = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double r = 0.5 * (r0_m + r1_m) + 0.5 * (r1_m - r0_m) * x[k];
    sum += w[k] * r * pressure(r, t_s);
    weight += w[k] * r;
  }
  return sum / weight;
}

BiotColumn::Wave BiotColumn::wave(int index) const {
  const double n = porosity, K = fluid_bulk_modulus_Pa / n, Ec = constrained_modulus_Pa;
  const double rd = dry_density_kg_m3, rw = fluid_density_kg_m3;
  // M⁻¹K = [[a, b], [c, d]]
  const double a = (Ec + (1 - n) * (1 - n) * K) / rd, b = n * (1 - n) * K / rd;
  const double c = (1 - n) * K / rw, d = n * K / rw;
  const double trace = a + d, determinant = a * d - b * c;
  const double root = std::sqrt(trace * trace - 4 * determinant);
  // The smaller eigenvalue as determinant/larger: no cancellation when the waves' speeds differ widely.
  const double fast = 0.5 * (trace + root), lambda = index == 0 ? fast : determinant / fast;
  const double phi_w = (lambda - a) / b;  // (a − λ) φ_s + b φ_w = 0 with φ_s = 1
  const double beta = n * n * rw * conductivity_gravity_m_s2 / permeability_m_s;
  const double modal_mass = rd + n * rw * phi_w * phi_w;
  return {std::sqrt(lambda), beta * (1 - phi_w) * (1 - phi_w) / (2 * modal_mass), phi_w};
}

double BiotColumn::uncoupling_mismatch() const {
  const double n = porosity, K = fluid_bulk_modulus_Pa / n;
  return (constrained_modulus_Pa + (1 - n) * K) * fluid_density_kg_m3 / (K * dry_density_kg_m3) - 1.0;
}

// The top's strains, σ' = E_c u_s' = −P and p = −K[(1 − n) u_s' + n u_w'] = 0, split onto the modes
// (1, 1) and (1, φ_w): u' = A_1 (1, 1) + A_2 (1, φ_w), A_2 = P/(n E_c (φ_w − 1)), A_1 = −P/E_c − A_2.
// Each mode's pore pressure is −K[(1 − n) + n φ] A and its effective stress E_c A.
double BiotColumn::fast_wave_pressure_share() const {
  const double n = porosity, K = fluid_bulk_modulus_Pa / n, Ec = constrained_modulus_Pa;
  const double A2 = 1.0 / (n * Ec * (wave(1).liquid_motion - 1.0)), A1 = -1.0 / Ec - A2;
  return -K * A1;
}

double BiotColumn::slow_wave_pressure_share() const {
  const double n = porosity, K = fluid_bulk_modulus_Pa / n, Ec = constrained_modulus_Pa;
  const double phi = wave(1).liquid_motion, A2 = 1.0 / (n * Ec * (phi - 1.0));
  return K * ((1 - n) + n * phi) * A2;
}

// F(a, t) = e^{−γa} + γa ∫_0^S e^{−γτ} I_1(γs)/τ ds, τ = √(s² + a²), S = √(t² − a²): the
// substitution s = √(τ² − a²) takes the integrand's square-root corner away (Simpson's rule).
double BiotColumn::slow_step_response(double delay_s, double t_s) const {
  if (t_s < delay_s) return 0.0;
  const double gamma = wave(1).damping_1_s, a = delay_s, S = std::sqrt(t_s * t_s - a * a);
  const auto integrand = [&](double s) {
    const double tau = std::sqrt(s * s + a * a);
    return std::exp(-gamma * tau) * std::cyl_bessel_i(1.0, gamma * s) / tau;
  };
  constexpr int intervals = 100;  // the integrand is smooth: Simpson's error ~(S/100)⁴
  const double h = S / intervals;
  double sum = integrand(0.0) + integrand(S);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
  return std::exp(-gamma * a) + gamma * a * sum * h / 3.0;
}

namespace {

/// P(t)/P of the half-cosine ramp over t_r (t_r = 0: a step).
double ramp_fraction(double ramp_s, double t_s) {
  if (t_s <= 0.0) return 0.0;
  return t_s >= ramp_s ? 1.0 : 0.5 * (1.0 - std::cos(kPi * t_s / ramp_s));
}

}  // namespace

// ∫_0^{min(t_r, t − a)} P'(τ) F(a, t − τ) dτ / P, P'(τ)/P = (π/2t_r) sin(πτ/t_r).
double BiotColumn::ramped_slow_response(double ramp_s, double delay_s, double t_s) const {
  if (ramp_s <= 0.0) return slow_step_response(delay_s, t_s);
  const double end = std::min(ramp_s, t_s - delay_s);
  if (end <= 0.0) return 0.0;
  static const double x[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                              0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
  static const double w[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                              0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
  double sum = 0.0;
  for (int k = 0; k < 16; ++k) {
    const double xi = k < 8 ? -x[k] : x[k - 8], weight = k < 8 ? w[k] : w[k - 8];
    const double tau = 0.5 * end * (1.0 + xi);
    sum += weight * kPi / (2.0 * ramp_s) * std::sin(kPi * tau / ramp_s) * slow_step_response(delay_s, t_s - tau);
  }
  return 0.5 * end * sum;
}

double BiotColumn::pressure(double load_Pa, double ramp_s, double depth_m, double t_s) const {
  const double fast = ramp_fraction(ramp_s, t_s - depth_m / wave(0).speed_m_s);
  const double slow = ramped_slow_response(ramp_s, depth_m / wave(1).speed_m_s, t_s);
  return load_Pa * (fast_wave_pressure_share() * fast - slow_wave_pressure_share() * slow);
}

double BiotColumn::effective_stress(double load_Pa, double ramp_s, double depth_m, double t_s) const {
  const double n = porosity, Ec = constrained_modulus_Pa;
  const double A2 = 1.0 / (n * Ec * (wave(1).liquid_motion - 1.0)), A1 = -1.0 / Ec - A2;
  const double fast = ramp_fraction(ramp_s, t_s - depth_m / wave(0).speed_m_s);
  const double slow = ramped_slow_response(ramp_s, depth_m / wave(1).speed_m_s, t_s);
  return load_Pa * Ec * (A1 * fast + A2 * slow);
}

}  // namespace ffp
