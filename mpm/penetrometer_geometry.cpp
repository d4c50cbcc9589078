#include "mpm/penetrometer_geometry.hpp"
#include "models/math_constants.hpp"

#include <algorithm>
#include <cmath>

namespace ffp::mpm {

bool PenetrometerShape::flat_tip() const { return cone_apex_angle_rad >= kPi; }

double PenetrometerShape::cone_height_m() const {
  return flat_tip() ? 0.0 : base_radius_m / std::tan(0.5 * cone_apex_angle_rad);
}

double PenetrometerShape::volume_m3() const {
  // Integrate π r(h)² dh numerically over the outline (the fillet has no
  // short closed form); 20 000 midpoints are exact to ~1e-9 relative.
  const PenetrometerGeometry g(*this);
  const int n = 20000;
  const double length = total_length_m();
  double v = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = g.radius_at((i + 0.5) * length / n);
    v += kPi * r * r;
  }
  return v * length / n;
}

PenetrometerGeometry::PenetrometerGeometry(const PenetrometerShape& shape) : shape_(shape) {
  const double half = 0.5 * shape.cone_apex_angle_rad;
  // A flat tip exactly (cos(π/2) is 6e-17 in floating point, not 0).
  sin_half_ = shape.flat_tip() ? 1.0 : std::sin(half);
  cos_half_ = shape.flat_tip() ? 0.0 : std::cos(half);
  const double radius = shape.base_radius_m;
  const double fillet = std::clamp(shape.edge_radius_m, 0.0, 0.99 * radius);
  // Fillet centre: a distance `fillet` inside both the cylinder r = R and the
  // cone line r cos(half) − z sin(half) = 0.
  fillet_center_r_ = radius - fillet;
  fillet_center_z_ = (fillet_center_r_ * cos_half_ + fillet) / sin_half_;
  cone_end_r_ = fillet_center_r_ + fillet * cos_half_;
  cone_end_z_ = fillet_center_z_ - fillet * sin_half_;
  top_z_ = shape.total_length_m();
}

double PenetrometerGeometry::radius_at(double h) const {
  if (h < 0.0 || h > top_z_) return 0.0;
  if (h <= cone_end_z_) return cos_half_ > 0.0 ? h * sin_half_ / cos_half_ : cone_end_r_;
  if (h < fillet_center_z_) {
    const double fillet = shape_.base_radius_m - fillet_center_r_;
    const double dz = h - fillet_center_z_;
    return fillet_center_r_ + std::sqrt(std::max(0.0, fillet * fillet - dz * dz));
  }
  return shape_.base_radius_m;
}

namespace {
struct Candidate {
  double distance = 1e300, normal_r = 0, normal_z = -1;
};

/// Distance to segment a–b with outward normal (nr, nz).
void consider_segment(Candidate& best, double r, double z, double ar, double az, double br, double bz, double nr,
                      double nz) {
  const double er = br - ar, ez = bz - az;
  const double length2 = er * er + ez * ez;
  const double t = length2 > 0 ? std::clamp(((r - ar) * er + (z - az) * ez) / length2, 0.0, 1.0) : 0.0;
  const double pr = ar + t * er, pz = az + t * ez;
  const double d = std::hypot(r - pr, z - pz);
  if (d < best.distance) {
    best.distance = d;
    // Past an end point the direction to the point is the honest normal (corners).
    if ((t <= 0.0 || t >= 1.0) && d > 1e-12) {
      const double sign = (r - pr) * nr + (z - pz) * nz >= 0 ? 1.0 : -1.0;
      best.normal_r = sign * (r - pr) / d;
      best.normal_z = sign * (z - pz) / d;
    } else {
      best.normal_r = nr;
      best.normal_z = nz;
    }
  }
}
}  // namespace

SurfaceQuery PenetrometerGeometry::query(double r, double z_global, double tip_z) const {
  const double z = z_global - tip_z;
  r = std::abs(r);
  const double radius = shape_.base_radius_m;
  const double fillet = radius - fillet_center_r_;
  Candidate best;
  // Cone flank, outward normal (cos, −sin) of the half angle.
  consider_segment(best, r, z, 0.0, 0.0, cone_end_r_, cone_end_z_, cos_half_, -sin_half_);
  // Rounded edge.
  if (fillet > 0.0) {
    const double dr = r - fillet_center_r_, dz = z - fillet_center_z_;
    const double rho = std::hypot(dr, dz);
    // The outline's arc runs from the cone tangent (angle −half) to the cylinder tangent (angle 0).
    const double angle = std::atan2(dz, dr);
    const bool on_arc = rho > 1e-15 && angle >= -0.5 * shape_.cone_apex_angle_rad && angle <= 0.0;
    if (on_arc) {
      const double d = std::abs(rho - fillet);
      if (d < best.distance) best = {d, dr / rho, dz / rho};
    }
  }
  // Cylinder and flat top.
  consider_segment(best, r, z, radius, fillet_center_z_, radius, top_z_, 1.0, 0.0);
  consider_segment(best, r, z, radius, top_z_, 0.0, top_z_, 0.0, 1.0);
  return {inside_local(r, z) ? -best.distance : best.distance, best.normal_r, best.normal_z};
}

}  // namespace ffp::mpm
