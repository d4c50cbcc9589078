#pragma once
/// Symmetric second-order tensors in Voigt storage, shared by every law, the
/// point driver and the MPM.
///
/// Order (11, 22, 33, 12, 23, 13) with *tensor* shear components (ε_12, not the
/// engineering γ_12 = 2 ε_12). In axisymmetry 1 = r, 2 = z, 3 = θ and 12 = rz.
/// Continuum sign convention: tension positive. SI units (Pa, dimensionless strain).
#include <Eigen/Core>

namespace ffp {

using Voigt = Eigen::Matrix<double, 6, 1>;

inline double trace(const Voigt& t) { return t[0] + t[1] + t[2]; }

/// t : u with the shear pairs counted twice (they stand for two tensor entries).
inline double contract(const Voigt& t, const Voigt& u) {
  return t[0] * u[0] + t[1] * u[1] + t[2] * u[2] + 2.0 * (t[3] * u[3] + t[4] * u[4] + t[5] * u[5]);
}

inline Voigt deviator(const Voigt& t) {
  Voigt d = t;
  const double m = trace(t) / 3.0;
  d[0] -= m;
  d[1] -= m;
  d[2] -= m;
  return d;
}

/// Geotechnical mean effective stress p' = −tr σ / 3 (compression positive).
inline double mean_pressure(const Voigt& stress) { return -trace(stress) / 3.0; }

/// Geotechnical deviatoric stress q = √(3/2 s:s).
inline double deviatoric_stress(const Voigt& stress) {
  const Voigt s = deviator(stress);
  return std::sqrt(1.5 * contract(s, s));
}

/// Deviatoric strain measure √(2/3 e:e) (equals the axial strain in an
/// isochoric triaxial test).
inline double deviatoric_strain(const Voigt& strain) {
  const Voigt e = deviator(strain);
  return std::sqrt(2.0 / 3.0 * contract(e, e));
}

}  // namespace ffp
