#pragma once
/// Material points as a structure of arrays. Axisymmetric: mass and volume are
/// per radian (V_p = r_p·A_p, m_p = ρ·V_p); multiply by 2π for the full body.
/// Particles of one material group are contiguous (MaterialGroup::begin/end)
/// and are never reordered, so indices stay valid for the whole run.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "models/voigt.hpp"

namespace ffp::mpm {

struct Particles {
  std::vector<std::uint8_t> body;      ///< body index (→ nodal field, contact)
  std::vector<double> r, z;            ///< position (m)
  std::vector<double> vr, vz;          ///< velocity (m/s)
  std::vector<double> mass;            ///< per radian (kg/rad)
  std::vector<double> volume;          ///< per radian (m³/rad), V_p = r_p·A_p in the reference state
  std::vector<double> half_r, half_z;  ///< GIMP half-lengths of the particle domain (m), constant (uGIMP)
  std::vector<double> r0, z0;          ///< initial position, for displacements
  std::vector<Voigt> stress;           ///< Cauchy stress (Pa), (rr, zz, θθ, rz, zθ, rθ), tension positive
  std::vector<Voigt> strain;           ///< accumulated strain increments (log strain for coaxial stretch)

  std::size_t size() const { return r.size(); }
  void resize(std::size_t n);
};

}  // namespace ffp::mpm
