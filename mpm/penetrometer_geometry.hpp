#pragma once
/// The penetrometer's exact outline in the (r, z) half-plane: a cone tip (or a
/// flat one: apex angle 180°, the punch of the bearing benchmarks), a rounded
/// edge and a cylindrical body with a flat top. The contact stage takes
/// its normals from here rather than from a noisy mass gradient.
#include <cmath>

namespace ffp::mpm {

struct PenetrometerShape {
  double cone_apex_angle_rad = 1.0471975511965976;  ///< full apex angle (60°; π: a flat tip)
  double base_radius_m = 0.04375;
  double edge_radius_m = 0.005;  ///< fillet between cone and body (0: sharp)
  double body_length_m = 0.5;    ///< cylinder above the cone's base

  bool flat_tip() const;         ///< apex angle π: a flat circular base (a punch)
  double cone_height_m() const;  ///< R / tan(apex/2), 7.58 cm for the BlueDrop; 0 for a flat tip
  double total_length_m() const { return cone_height_m() + body_length_m; }
  double volume_m3() const;  ///< of the solid of revolution (fillet included)
};

/// Closest point of the outline to a query point, in local coordinates (tip at
/// the origin, z up along the axis).
struct SurfaceQuery {
  double signed_distance_m;   ///< < 0 inside the penetrometer
  double normal_r, normal_z;  ///< unit outward normal of the surface at the closest point
};

class PenetrometerGeometry {
 public:
  explicit PenetrometerGeometry(const PenetrometerShape& shape);
  const PenetrometerShape& shape() const { return shape_; }

  /// Query with the tip at z = tip_z_m (global coordinates), r ≥ 0.
  SurfaceQuery query(double r_m, double z_m, double tip_z_m) const;
  /// Outer radius of the outline at height h above the tip (0 outside [0, length]).
  double radius_at(double height_above_tip_m) const;
  bool contains(double r_m, double z_m, double tip_z_m) const { return query(r_m, z_m, tip_z_m).signed_distance_m < 0; }
  /// query()'s side test alone: true where its signed distance is ≤ 0 (< 0 but on the
  /// outline itself), so that a search for the points inside can skip the distance of
  /// the others (their signed distance is ≥ 0).
  bool inside(double r_m, double z_m, double tip_z_m) const { return inside_local(std::abs(r_m), z_m - tip_z_m); }

 private:
  /// Tip at the origin, r ≥ 0.
  bool inside_local(double r, double z) const { return z >= 0.0 && z <= top_z_ && r < radius_at(z); }

  PenetrometerShape shape_;
  double sin_half_ = 0, cos_half_ = 0;
  double cone_end_r_ = 0, cone_end_z_ = 0;  // cone–fillet tangent point
  double fillet_center_r_ = 0, fillet_center_z_ = 0;
  double top_z_ = 0;
};

}  // namespace ffp::mpm
