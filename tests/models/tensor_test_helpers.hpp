#pragma once
/// Small tensor utilities shared by the law tests.
#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "models/voigt.hpp"

namespace ffp::test {

inline Eigen::Matrix3d to_matrix(const Voigt& v) {
  Eigen::Matrix3d m;
  m << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  return m;
}

inline Voigt to_voigt(const Eigen::Matrix3d& m) {
  Voigt v;
  v << m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0)), 0.5 * (m(1, 2) + m(2, 1)), 0.5 * (m(0, 2) + m(2, 0));
  return v;
}

inline Voigt rotated(const Voigt& v, const Eigen::Matrix3d& r) { return to_voigt(r * to_matrix(v) * r.transpose()); }

inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// A symmetric tensor with independent normal entries of the given scale.
inline Voigt random_voigt(std::mt19937_64& rng, double scale) {
  std::normal_distribution<double> normal(0.0, scale);
  Voigt v;
  for (int i = 0; i < 6; ++i) v[i] = normal(rng);
  return v;
}

inline Voigt isotropic(double value) {
  Voigt v = Voigt::Zero();
  v[0] = v[1] = v[2] = value;
  return v;
}

inline double max_abs(const Voigt& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace ffp::test
