#include "mpm/contact_law.hpp"

#include <cmath>

namespace ffp::mpm {

Vector2 contact_velocity(Vector2 v, Vector2 surface, Vector2 n, const ContactLaw& law, double dt_over_h) {
  const double dr = v.r - surface.r, dz = v.z - surface.z;
  const double normal = dr * n.r + dz * n.z;
  if (!(normal < 0.0)) return v;  // separating or sliding along: free
  const double tr = dr - normal * n.r, tz = dz - normal * n.z;
  double keep = 0.0;  // fraction of the tangential slip that survives
  if (!law.rough) {
    const double slip = std::hypot(tr, tz);
    const double limit = law.friction * -normal;
    keep = slip > limit ? 1.0 - limit / slip : 0.0;
  }
  const Vector2 corrected{surface.r + keep * tr, surface.z + keep * tz};
  const double cr = corrected.r - v.r, cz = corrected.z - v.z;
  const double strain = std::hypot(cr, cz) * dt_over_h;  // the correction's strain in one step
  const double cap = law.velocity_scaling;
  const double scale = (cap > 0.0 && strain > cap) ? cap / strain : 1.0;
  return {v.r + scale * cr, v.z + scale * cz};
}

}  // namespace ffp::mpm
