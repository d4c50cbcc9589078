#include "mpm/particle_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/boundary_conditions.hpp"

namespace ffp::mpm {

void ParticleContact::collect(const Simulation& s, const PenetrometerGeometry& geometry, double tip_z_m,
                              std::uint8_t soil_field, double band_m) {
  candidates_.clear();
  const Particles& P = s.particles;
  const double R = geometry.shape().base_radius_m, top = tip_z_m + geometry.shape().total_length_m();
  for (const Body& body : s.bodies) {
    if (body.field != soil_field) continue;
    for (std::size_t p = body.begin; p < body.end; ++p) {
      const double r = P.r[p], z = P.z[p], lr = P.half_r[p], lz = P.half_z[p];
      // Outside the outline's bounding box grown by the band and the domain: no gap below the band.
      if (r - lr > R + band_m || z + lz < tip_z_m - band_m || z - lz > top + band_m) continue;
      const SurfaceQuery q = geometry.query(r, z, tip_z_m);
      const double gap = q.signed_distance_m - (lr * std::abs(q.normal_r) + lz * std::abs(q.normal_z));
      if (gap < band_m) candidates_.push_back({p, q.normal_r, q.normal_z, gap});
    }
  }
}

namespace {

// Particles with almost the same support and normals θ apart (on the fillet, by the apex) are
// almost parallel constraints, which Gauss–Seidel closes only at cos²θ per sweep. Their split of
// the impulse moves the velocities little: on ffp_reference.json at 0.5 cm (musl, 60 ms) 100 /
// 1,000 / 5,000 sweeps give z 0.191041 / 0.191048 / 0.191052 m and 2 ms peaks 17.329 / 17.333 /
// 17.332 g. So the sweeps stop at 200 and the step's residual is reported.
constexpr int kMaxSweeps = 200;

}  // namespace

ParticleContactOutcome ParticleContact::solve(const Simulation& s, std::uint8_t soil_field, double* vr, double* vz,
                                              double body_velocity, double body_inverse_mass, const ContactLaw& law,
                                              bool warm_start) {
  build_supports(s, s.grid.fields[soil_field]);
  normal_impulse_.assign(candidates_.size(), 0.0);
  tangent_impulse_.assign(candidates_.size(), 0.0);
  Exchange exchange{vr, vz, body_velocity, body_inverse_mass, law, s.dt_s};
  if (warm_start) start_from_last_impulses(exchange, s.particles.size());
  ParticleContactOutcome out;
  sweep(exchange, out, 1e-9 * (1.0 + std::abs(body_velocity)));
  if (warm_start) keep_impulses(s.dt_s);
  tally(out);
  out.body_velocity = exchange.v_body;
  return out;
}

void ParticleContact::build_supports(const Simulation& s, const NodalField& f) {
  const int S = s.settings.shape_function == ShapeFunction::linear ? 2 : 3;
  // The grid's fixities hold through the contact (v_r = 0 on the axis under the apex, the chamber's
  // walls): a constrained component takes no impulse and adds no inverse mass.
  if (fixed_.size() != f.size()) {
    fixed_.assign(f.size(), 0);
    for (const NodeConstraint& c : s.grid.constraints) fixed_[c.node] |= c.bits;
  }
  supports_.assign(candidates_.size(), Support{});
  for (std::size_t c = 0; c < candidates_.size(); ++c) {
    const ShapeWeights& w = s.weights[candidates_[c].particle];
    Support& support = supports_[c];
    for (int b = 0; b < S; ++b)
      for (int a = 0; a < S; ++a) {
        const std::size_t i = s.grid.node(w.node_r + a, w.node_z + b);
        const double N = w.wr[a] * w.wz[b];
        if (!(N > 0.0) || !(f.mass[i] > s.mass_floor_kg)) continue;
        const double free_r = (fixed_[i] & constrain_r) ? 0.0 : 1.0, free_z = (fixed_[i] & constrain_z) ? 0.0 : 1.0;
        support.node[support.count] = i;
        support.weight[support.count] = N;
        support.weight_over_mass_r[support.count] = free_r * N / f.mass[i];
        support.weight_over_mass_z[support.count] = free_z * N / f.mass[i];
        support.inverse_mass_r += free_r * N * N / f.mass[i];
        support.inverse_mass_z += free_z * N * N / f.mass[i];
        ++support.count;
      }
  }
}

// The impulse (jr, jz) of a candidate: to its nodes, and its reaction to the body.
void ParticleContact::apply(Exchange& e, const Support& support, double jr, double jz) {
  for (int k = 0; k < support.count; ++k) {
    e.vr[support.node[k]] += support.weight_over_mass_r[k] * jr;
    e.vz[support.node[k]] += support.weight_over_mass_z[k] * jz;
  }
  e.v_body -= e.body_inverse_mass * jz;
}

void ParticleContact::start_from_last_impulses(Exchange& e, std::size_t particles) {
  if (last_normal_.size() != particles) {
    last_normal_.assign(particles, 0.0);
    last_tangent_.assign(particles, 0.0);
    last_particles_.clear();
  }
  const double scale = last_dt_s_ > 0.0 ? e.dt / last_dt_s_ : 0.0;
  for (std::size_t c = 0; c < candidates_.size(); ++c) {
    const std::size_t p = candidates_[c].particle;
    normal_impulse_[c] = scale * last_normal_[p];
    tangent_impulse_[c] = scale * last_tangent_[p];
    const double jn = normal_impulse_[c], jt = tangent_impulse_[c];
    if (jn != 0.0 || jt != 0.0)
      apply(e, supports_[c], jn * candidates_[c].nr - jt * candidates_[c].nz,
            jn * candidates_[c].nz + jt * candidates_[c].nr);
  }
}

// One Gauss–Seidel update of candidate c; returns the largest velocity change it made.
double ParticleContact::update(Exchange& e, std::size_t c) {
  const Candidate& cand = candidates_[c];
  const Support& support = supports_[c];
  if (support.count == 0) return 0.0;
  double ur = 0.0, uz = -e.v_body;
  for (int k = 0; k < support.count; ++k) {
    ur += support.weight[k] * e.vr[support.node[k]];
    uz += support.weight[k] * e.vz[support.node[k]];
  }
  // Normal: close at most the gap in this step (none deeper once overlapping).
  const double floor_n = cand.gap_m >= 0.0 ? -cand.gap_m / e.dt : 0.0;
  const double w_n =
      support.inverse_mass_r * cand.nr * cand.nr + (support.inverse_mass_z + e.body_inverse_mass) * cand.nz * cand.nz;
  if (!(w_n > 0.0)) return 0.0;  // every node it could push along n is fixed
  const double un = ur * cand.nr + uz * cand.nz;
  const double jn = std::max(0.0, normal_impulse_[c] + (floor_n - un) / w_n);
  const double djn = jn - normal_impulse_[c];
  normal_impulse_[c] = jn;
  if (djn != 0.0) {
    apply(e, support, djn * cand.nr, djn * cand.nz);
    ur += support.inverse_mass_r * djn * cand.nr;
    uz += (support.inverse_mass_z + e.body_inverse_mass) * djn * cand.nz;
  }
  // Tangent t = (−n_z, n_r): Coulomb friction, |J_t| ≤ μ J_n (rough: any, while in contact).
  const double tr = -cand.nz, tz = cand.nr;
  const double w_t = support.inverse_mass_r * tr * tr + (support.inverse_mass_z + e.body_inverse_mass) * tz * tz;
  if (!(w_t > 0.0)) return std::abs(djn) * w_n;
  const double ut = ur * tr + uz * tz;
  const double limit = e.law.rough ? (jn > 0.0 ? std::numeric_limits<double>::infinity() : 0.0) : e.law.friction * jn;
  const double jt = std::clamp(tangent_impulse_[c] - ut / w_t, -limit, limit);
  const double djt = jt - tangent_impulse_[c];
  tangent_impulse_[c] = jt;
  if (djt != 0.0) apply(e, support, djt * tr, djt * tz);
  return std::max(std::abs(djn) * w_n, std::abs(djt) * w_t);
}

// Sweeps over the particles in contact (J_n > 0) until they settle, then a sweep over all
// candidates, which must change nothing (else the contact set is taken again). Most candidates
// never touch: this visits them once or twice per step instead of at every sweep.
void ParticleContact::sweep(Exchange& e, ParticleContactOutcome& out, double tolerance) {
  std::vector<std::size_t> in_contact;
  for (out.sweeps = 0; out.sweeps < kMaxSweeps;) {
    double largest = 0.0;
    for (std::size_t c = 0; c < candidates_.size(); ++c) largest = std::max(largest, update(e, c));
    ++out.sweeps;
    out.residual_m_s = largest;
    if (largest <= tolerance) break;
    in_contact.clear();
    for (std::size_t c = 0; c < candidates_.size(); ++c)
      if (normal_impulse_[c] > 0.0) in_contact.push_back(c);
    while (out.sweeps < kMaxSweeps) {
      double change = 0.0;
      for (const std::size_t c : in_contact) change = std::max(change, update(e, c));
      ++out.sweeps;
      out.residual_m_s = change;
      if (change <= tolerance) break;
    }
  }
  out.sweeps = std::min(out.sweeps, kMaxSweeps);
}

void ParticleContact::keep_impulses(double dt) {
  // Only the last solve's particles hold impulses: clear those, not every particle of the run.
  for (const std::size_t p : last_particles_) last_normal_[p] = last_tangent_[p] = 0.0;
  last_particles_.clear();
  for (std::size_t c = 0; c < candidates_.size(); ++c) {
    last_normal_[candidates_[c].particle] = normal_impulse_[c];
    last_tangent_[candidates_[c].particle] = tangent_impulse_[c];
    last_particles_.push_back(candidates_[c].particle);
  }
  last_dt_s_ = dt;
}

void ParticleContact::tally(ParticleContactOutcome& out) const {
  for (std::size_t c = 0; c < candidates_.size(); ++c) {
    const double jn = normal_impulse_[c], jt = tangent_impulse_[c], nr = candidates_[c].nr, nz = candidates_[c].nz;
    const double jz = jn * nz + jt * nr;
    out.impulse_z += jz;
    if (nz < 0.0) {
      out.cone_z += jz;
      out.cone_normal_z += jn * nz;
    } else if (nz == 0.0) {
      out.shaft_z += jz;
    }
    if (jn > 0.0) ++out.active;
  }
}

}  // namespace ffp::mpm
