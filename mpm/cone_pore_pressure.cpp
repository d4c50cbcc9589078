#include "mpm/cone_pore_pressure.hpp"

namespace ffp::mpm {

namespace {

/// Σ V_p p_p and Σ V_p p_e,p over a region's particles.
struct RegionSum {
  double volume = 0.0, pressure = 0.0, excess = 0.0;
  std::size_t particles = 0;

  void add(double V, double p, double p_e) {
    volume += V;
    pressure += V * p;
    excess += V * p_e;
    ++particles;
  }
  /// The mean, or the hydrostatic pressure at `mid_z_m` when no particle is in the region.
  PorePressureReading reading(const TwoPhase& t, double mid_z_m) const {
    if (particles == 0) return {t.hydrostatic_pressure(mid_z_m), 0.0, 0};
    return {pressure / volume, excess / volume, particles};
  }
};

}  // namespace

ConePorePressure cone_pore_pressure(const FfpRun& run) {
  const Simulation& s = run.simulation();
  if (!s.two_phase) return {};
  const TwoPhase& t = *s.two_phase;
  const Particles& P = s.particles;
  const MaterialGroup& soil = s.groups[run.soil_body()];
  const double h = run.description().mesh.min_cell_m, tip = run.tip_z_m();
  const double H = run.description().shape.cone_height_m(), R = run.description().shape.base_radius_m;
  const double u1_top = tip + 0.5 * H, u2_bottom = tip + H, u2_top = tip + H + 2.0 * h;
  RegionSum u1, u2;
  for (std::size_t p = soil.begin; p < soil.end; ++p) {
    const double z = P.z[p];
    // Outside both regions' bounding boxes: no distance needed.
    if (P.r[p] > R + h || z < tip - h || z > u2_top || (z > u1_top && z < u2_bottom)) continue;
    if (run.geometry().query(P.r[p], z, tip).signed_distance_m > h) continue;
    RegionSum& region = z <= u1_top ? u1 : u2;
    region.add(P.volume[p], t.pore_pressure[p], t.excess_pressure(P, p));
  }
  return {u1.reading(t, tip + 0.25 * H), u2.reading(t, tip + H + h)};
}

}  // namespace ffp::mpm
