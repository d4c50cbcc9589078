#include "mpm/body_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/math_constants.hpp"
#include "mpm/internal_force.hpp"
#include "mpm/particle_update.hpp"
#include "mpm/stages.hpp"
#include "mpm/velocity_gradient.hpp"

namespace ffp::mpm {

BodySubcycle::BodySubcycle(Simulation& s, std::size_t body) : body_(body) {
  if (body >= s.bodies.size() || body + 1 != s.bodies.size())
    throw std::invalid_argument("a subcycled body must be the simulation's last body");
  const Body& b = s.bodies[body];
  if (b.field == 0) throw std::invalid_argument("a subcycled body needs its own nodal field (contact)");
  if (s.groups[b.group].disconnected_below_kg_m3 > 0.0)
    throw std::invalid_argument("a subcycled body must be a continuum (no disconnection density)");
  s.main_step_end = b.begin;
  constraint_bits_.assign(s.grid.nodes(), 0);
  for (const NodeConstraint& c : s.grid.constraints) constraint_bits_[c.node] |= c.bits;
  node_slot_.assign(s.grid.nodes(), -1);
  cell_slot_.assign(s.grid.cells(), -1);
}

// v*_i = p_i/m_i + Δt f_i^ext/m_i  (integrate_grid without f_i^int; empty or constrained: 0)
void BodySubcycle::predict_contact_velocity(Simulation& s) {
  // N = ⌈Δt_s/Δt_b⌉ equal substeps, Δt_b = C h_min/(c_p + |v|) of the body alone.
  const double body_dt = s.settings.courant * group_time_step_limit(s, s.groups[s.bodies[body_].group]);
  substeps_ = std::max(1, static_cast<int>(std::ceil(s.dt_s / body_dt * (1.0 - 1e-12))));
  contact_mass_factor_ = std::max(1.0, substeps_ * s.settings.courant);
  NodalField& f = s.grid.fields[s.bodies[body_].field];
  const double dt = s.dt_s, floor = s.mass_floor_kg;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const bool filled = f.mass[i] > floor;
    f.velocity_new_r[i] = filled ? f.velocity_r[i] + dt * f.external_force_r[i] / f.mass[i] : 0.0;
    f.velocity_new_z[i] = filled ? f.velocity_z[i] + dt * f.external_force_z[i] / f.mass[i] : 0.0;
  }
  for (const NodeConstraint& c : s.grid.constraints) {
    if (c.bits & constrain_r) f.velocity_new_r[c.node] = 0.0;
    if (c.bits & constrain_z) f.velocity_new_z[c.node] = 0.0;
  }
}

void BodySubcycle::advance(Simulation& s, const std::vector<NodalImpulse>& impulses) {
  if (s.settings.shape_function == ShapeFunction::linear) {
    run<2>(s, impulses);
  } else {
    run<3>(s, impulses);
  }
}

// The step: the body's nodes, N substeps on them, the contact's work, the particles' update.
template <int S>
void BodySubcycle::run(Simulation& s, const std::vector<NodalImpulse>& impulses) {
  collect_support<S>(s);
  load_nodes(s);
  const std::vector<std::int32_t> impulse_slots = add_impulses(s, impulses);
  const int substeps = substeps_;  // from the step's start (predict_contact_velocity)
  const double h = s.dt_s / substeps;
  for (int k = 0; k < substeps; ++k) substep<S>(s, h);
  add_contact_work(s, impulses, impulse_slots, h);
  update_particles<S>(s);
  last_substeps_ = substeps;
  total_substeps_ += substeps;
}

// The body's nodes and cells of this step, in the order its particles reach them.
template <int S>
void BodySubcycle::collect_support(const Simulation& s) {
  constexpr int support = S * S;
  const Body& b = s.bodies[body_];
  for (std::size_t k : nodes_) node_slot_[k] = -1;
  for (std::size_t c : cells_) cell_slot_[c] = -1;
  nodes_.clear();
  cells_.clear();
  particle_nodes_.resize((b.end - b.begin) * support);
  particle_cell_.resize(b.end - b.begin);
  for (std::size_t p = b.begin; p < b.end; ++p) {
    const ShapeWeights& w = s.weights[p];
    std::int32_t* slots = &particle_nodes_[(p - b.begin) * support];
    for (int bz = 0; bz < S; ++bz) {
      for (int a = 0; a < S; ++a) {
        const std::size_t k = s.grid.node(w.node_r + a, w.node_z + bz);
        if (node_slot_[k] < 0) {
          node_slot_[k] = static_cast<std::int32_t>(nodes_.size());
          nodes_.push_back(k);
        }
        slots[bz * S + a] = node_slot_[k];
      }
    }
    if (cell_slot_[s.cell[p]] < 0) {
      cell_slot_[s.cell[p]] = static_cast<std::int32_t>(cells_.size());
      cells_.push_back(s.cell[p]);
    }
    particle_cell_[p - b.begin] = cell_slot_[s.cell[p]];
  }
}

// The step's mapping on the body's nodes: m_i, v_i^0 = p_i/m_i, f_i^ext; displacement 0.
void BodySubcycle::load_nodes(const Simulation& s) {
  const NodalField& f = s.grid.fields[s.bodies[body_].field];
  const std::size_t n = nodes_.size();
  for (auto* a : {&mass_, &vr_, &vz_, &vr0_, &vz0_, &fr_, &fz_, &er_, &ez_, &ur_, &uz_}) a->assign(n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t k = nodes_[c];
    mass_[c] = f.mass[k];
    if (!(mass_[c] > s.mass_floor_kg)) continue;  // empty: stays at rest, as in integrate_grid
    vr_[c] = vr0_[c] = f.velocity_r[k];           // p_i/m_i, constrained components already 0
    vz_[c] = vz0_[c] = f.velocity_z[k];
    er_[c] = f.external_force_r[k];
    ez_[c] = f.external_force_z[k];
  }
}

// The contact impulse as a constant force over the step: Σ_k δt J_i/Δt_s = J_i.
// Returns each impulse's compact node.
std::vector<std::int32_t> BodySubcycle::add_impulses(const Simulation& s, const std::vector<NodalImpulse>& impulses) {
  std::vector<std::int32_t> slots(impulses.size());
  for (std::size_t j = 0; j < impulses.size(); ++j) {
    const std::int32_t c = node_slot_[impulses[j].node];
    if (c < 0 || !(mass_[c] > s.mass_floor_kg))
      throw std::logic_error("a contact impulse on a node the body does not reach");
    slots[j] = c;
    er_[c] += impulses[j].r / s.dt_s;
    ez_[c] += impulses[j].z / s.dt_s;
  }
  return slots;
}

// Where the body's k-th particle's support node (a, b) sits among the step's compact nodes.
template <int S>
auto BodySubcycle::support_of(std::size_t k) const {
  const std::int32_t* slots = &particle_nodes_[k * S * S];
  return [slots](int a, int b) { return static_cast<std::size_t>(slots[b * S + a]); };
}

// One substep of δt = h: the step's stages on the body's nodes and particles alone.
template <int S>
void BodySubcycle::substep(Simulation& s, double h) {
  // The subcycled body smooths the volumetric part under either smoothing mode (its own B-bar).
  const bool smoothed = s.settings.strain_smoothing != StrainSmoothing::off;
  if (smoothed) mean_stress_of_cells(s);
  internal_forces<S>(s, smoothed);
  integrate_nodes(s, h);
  strain_increments<S>(s, h);
  if (smoothed) smooth_volumetric_strain(s);
  update_stresses(s, h);
}

// cell_volume_[c] = Σ_{p∈c} V_p and cell_mean_[c] = Σ_{p∈c} term(p) over the body's particles.
template <class Term>
void BodySubcycle::sum_cells(const Simulation& s, Term&& term) {
  const Body& b = s.bodies[body_];
  cell_volume_.assign(cells_.size(), 0.0);
  cell_mean_.assign(cells_.size(), 0.0);
  for (std::size_t p = b.begin; p < b.end; ++p) {
    const std::int32_t c = particle_cell_[p - b.begin];
    cell_volume_[c] += s.particles.volume[p];
    cell_mean_[c] += term(p);
  }
}

// B-bar mean stress per cell (smooth_mean_stress, this body's particles only):
//   σ̄_m,c = Σ_{p∈c} V_p tr(σ_p)/3 / Σ_{p∈c} V_p
void BodySubcycle::mean_stress_of_cells(const Simulation& s) {
  const Particles& P = s.particles;
  sum_cells(s, [&](std::size_t p) { return P.volume[p] * trace(P.stress[p]) / 3.0; });
  for (std::size_t c = 0; c < cells_.size(); ++c) cell_mean_[c] /= cell_volume_[c];
}

// f_i^int = −Σ_p V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r]  (compute_internal_forces on the body's nodes)
template <int S>
void BodySubcycle::internal_forces(const Simulation& s, bool smoothed) {
  const Body& b = s.bodies[body_];
  const Particles& P = s.particles;
  std::fill(fr_.begin(), fr_.end(), 0.0);
  std::fill(fz_.begin(), fz_.end(), 0.0);
  for (std::size_t p = b.begin; p < b.end; ++p) {
    const ForceStress sig = smoothed ? b_bar_force_stress(P.stress[p], cell_mean_[particle_cell_[p - b.begin]])
                                     : own_force_stress(P.stress[p]);
    add_internal_force<S>(s.weights[p], sig, P.volume[p], support_of<S>(p - b.begin), fr_.data(), fz_.data());
  }
}

// v_i^{k+1} = v_i^k + δt (f^int + f^ext + J/Δt_s)/m_i; constrained components 0; u_i += δt v_i^{k+1}
void BodySubcycle::integrate_nodes(const Simulation& s, double h) {
  for (std::size_t c = 0; c < nodes_.size(); ++c) {
    if (!(mass_[c] > s.mass_floor_kg)) continue;
    const double inverse_m = 1.0 / mass_[c];
    const std::uint8_t bits = constraint_bits_[nodes_[c]];
    vr_[c] = (bits & constrain_r) ? 0.0 : vr_[c] + h * (fr_[c] + er_[c]) * inverse_m;
    vz_[c] = (bits & constrain_z) ? 0.0 : vz_[c] + h * (fz_[c] + ez_[c]) * inverse_m;
    ur_[c] += h * vr_[c];
    uz_[c] += h * vz_[c];
  }
}

// Δε_p = δt sym(L_p), L_p = Σ_i v_i ⊗ G_ip, L_θθ = Σ_i S_ip v_r,i/r_p; V_p ← V_p det(I + δt L)
// (compute_strain_increments on the body's nodes)
template <int S>
void BodySubcycle::strain_increments(Simulation& s, double h) {
  const Body& b = s.bodies[body_];
  for (std::size_t p = b.begin; p < b.end; ++p) {
    const VelocityGradient L = velocity_gradient<S>(s.weights[p], support_of<S>(p - b.begin), vr_.data(), vz_.data());
    apply_velocity_gradient(L, h, s.strain_increment[p], s.spin_dt[p], s.particles.volume[p]);
  }
}

// Strain smoothing (smooth_volumetric_strain, this body's particles only):
//   Δε_p ← Δε_p + (Σ_{p∈c} V_p Δε_v,p / Σ_{p∈c} V_p − Δε_v,p)/3 · I
void BodySubcycle::smooth_volumetric_strain(Simulation& s) {
  const Body& b = s.bodies[body_];
  sum_cells(s, [&](std::size_t p) { return s.particles.volume[p] * trace(s.strain_increment[p]); });
  for (std::size_t p = b.begin; p < b.end; ++p) {
    const std::int32_t c = particle_cell_[p - b.begin];
    Voigt& de = s.strain_increment[p];
    const double shift = (cell_mean_[c] / cell_volume_[c] - trace(de)) / 3.0;
    de[0] += shift;
    de[1] += shift;
    de[2] += shift;
  }
}

// Jaumann rotation, then the law (update_stresses on the body's particles).
void BodySubcycle::update_stresses(Simulation& s, double h) {
  const Body& b = s.bodies[body_];
  Particles& P = s.particles;
  for (std::size_t p = b.begin; p < b.end; ++p) {
    rotate_by_spin(P.stress[p], s.spin_dt[p]);
    P.strain[p] += s.strain_increment[p];
  }
  s.groups[b.group].update(b.begin, b.end, P.stress, s.strain_increment, h);
}

// Work of the contact forces: Σ_k δt F_i·½(v^k + v^{k+1}) = F_i·(u_i − ½δt(v^N − v^0)), full 2π.
void BodySubcycle::add_contact_work(const Simulation& s, const std::vector<NodalImpulse>& impulses,
                                    const std::vector<std::int32_t>& impulse_slots, double h) {
  const double dt = s.dt_s;
  double work = 0.0;
  for (std::size_t j = 0; j < impulses.size(); ++j) {
    const std::int32_t c = impulse_slots[j];
    work += impulses[j].r / dt * (ur_[c] - 0.5 * h * (vr_[c] - vr0_[c])) +
            impulses[j].z / dt * (uz_[c] - 0.5 * h * (vz_[c] - vz0_[c]));
  }
  contact_work_J_ += kTwoPi * work;
}

// v_p ← α (v_p + Σ S (v^N − v^0)) + (1 − α) Σ S v^N;  x_p ← x_p + Σ S u   (kept inside the walls)
// (update_particles on the body's nodes)
template <int S>
void BodySubcycle::update_particles(Simulation& s) {
  const Body& b = s.bodies[body_];
  Particles& P = s.particles;
  for (std::size_t p = b.begin; p < b.end; ++p) {
    double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0, ur = 0.0, uz = 0.0;
    for_support_at<S>(s.weights[p], support_of<S>(p - b.begin), [&](std::size_t c, double N, double, double) {
      vr += N * vr_[c];
      vz += N * vz_[c];
      dvr += N * (vr_[c] - vr0_[c]);
      dvz += N * (vz_[c] - vz0_[c]);
      ur += N * ur_[c];
      uz += N * uz_[c];
    });
    blend_flip_pic(P, p, s.settings.flip_fraction, vr, vz, dvr, dvz);
    move_within_walls(P, p, P.r[p] + ur, P.z[p] + uz, s.walls, s.wall_clamps);
  }
}

}  // namespace ffp::mpm
