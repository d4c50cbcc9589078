#include "mpm/body_subcycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/math_constants.hpp"
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

template <int S>
void BodySubcycle::run(Simulation& s, const std::vector<NodalImpulse>& impulses) {
  constexpr int support = S * S;
  const Body& b = s.bodies[body_];
  const NodalField& f = s.grid.fields[b.field];
  MaterialGroup& group = s.groups[b.group];
  Particles& P = s.particles;
  const std::size_t first = b.begin, last = b.end, count = last - first;
  const double dt = s.dt_s, floor = s.mass_floor_kg;
  // The subcycled body smooths the volumetric part under either smoothing mode (its own B-bar).
  const bool smoothed = s.settings.strain_smoothing != StrainSmoothing::off;

  // The body's nodes and cells of this step, in the order its particles reach them.
  for (std::size_t k : nodes_) node_slot_[k] = -1;
  for (std::size_t c : cells_) cell_slot_[c] = -1;
  nodes_.clear();
  cells_.clear();
  particle_nodes_.resize(count * support);
  particle_cell_.resize(count);
  for (std::size_t p = first; p < last; ++p) {
    const ShapeWeights& w = s.weights[p];
    std::int32_t* slots = &particle_nodes_[(p - first) * support];
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
    particle_cell_[p - first] = cell_slot_[s.cell[p]];
  }
  const std::size_t n = nodes_.size();
  for (auto* a : {&mass_, &vr_, &vz_, &vr0_, &vz0_, &fr_, &fz_, &er_, &ez_, &ur_, &uz_}) a->assign(n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t k = nodes_[c];
    mass_[c] = f.mass[k];
    if (!(mass_[c] > floor)) continue;   // empty: stays at rest, as in integrate_grid
    vr_[c] = vr0_[c] = f.velocity_r[k];  // p_i/m_i, constrained components already 0
    vz_[c] = vz0_[c] = f.velocity_z[k];
    er_[c] = f.external_force_r[k];
    ez_[c] = f.external_force_z[k];
  }
  // The contact impulse as a constant force over the step: Σ_k δt J_i/Δt_s = J_i.
  std::vector<std::int32_t> impulse_slots(impulses.size());
  for (std::size_t j = 0; j < impulses.size(); ++j) {
    const std::int32_t c = node_slot_[impulses[j].node];
    if (c < 0 || !(mass_[c] > floor)) throw std::logic_error("a contact impulse on a node the body does not reach");
    impulse_slots[j] = c;
    er_[c] += impulses[j].r / dt;
    ez_[c] += impulses[j].z / dt;
  }

  const int substeps = substeps_;  // from the step's start (predict_contact_velocity)
  const double h = dt / substeps;
  std::vector<double>& cell_volume = cell_volume_;
  std::vector<double>& cell_mean = cell_mean_;
  const std::size_t cells = cells_.size();

  for (int k = 0; k < substeps; ++k) {
    // B-bar mean stress per cell (smooth_mean_stress, this body's particles only).
    if (smoothed) {
      cell_volume.assign(cells, 0.0);
      cell_mean.assign(cells, 0.0);
      for (std::size_t p = first; p < last; ++p) {
        const std::int32_t c = particle_cell_[p - first];
        cell_volume[c] += P.volume[p];
        cell_mean[c] += P.volume[p] * trace(P.stress[p]) / 3.0;
      }
      for (std::size_t c = 0; c < cells; ++c) cell_mean[c] /= cell_volume[c];
    }
    // f_i^int = −Σ_p V_p [σ_p·G_ip + σ_θθ,p S_ip/r_p e_r]
    std::fill(fr_.begin(), fr_.end(), 0.0);
    std::fill(fz_.begin(), fz_.end(), 0.0);
    for (std::size_t p = first; p < last; ++p) {
      const ShapeWeights& w = s.weights[p];
      const std::int32_t* slots = &particle_nodes_[(p - first) * support];
      Voigt sig = P.stress[p];
      if (smoothed) {
        const double shift = cell_mean[particle_cell_[p - first]] - trace(sig) / 3.0;
        sig[0] += shift;
        sig[1] += shift;
        sig[2] += shift;
      }
      const double V = P.volume[p], hoop = sig[2] * w.inverse_r;
      for (int bz = 0; bz < S; ++bz) {
        for (int a = 0; a < S; ++a) {
          const std::int32_t c = slots[bz * S + a];
          const double N = w.wr[a] * w.wz[bz], Gr = w.gr[a] * w.wz[bz], Gz = w.wr[a] * w.gz[bz];
          fr_[c] -= V * (sig[0] * Gr + sig[3] * Gz + hoop * N);
          fz_[c] -= V * (sig[3] * Gr + sig[1] * Gz);
        }
      }
    }
    // v_i^{k+1} = v_i^k + δt (f^int + f^ext + J/Δt_s)/m_i; constrained components 0; u_i += δt v_i^{k+1}
    for (std::size_t c = 0; c < n; ++c) {
      if (!(mass_[c] > floor)) continue;
      const double inverse_m = 1.0 / mass_[c];
      const std::uint8_t bits = constraint_bits_[nodes_[c]];
      vr_[c] = (bits & constrain_r) ? 0.0 : vr_[c] + h * (fr_[c] + er_[c]) * inverse_m;
      vz_[c] = (bits & constrain_z) ? 0.0 : vz_[c] + h * (fz_[c] + ez_[c]) * inverse_m;
      ur_[c] += h * vr_[c];
      uz_[c] += h * vz_[c];
    }
    // Δε_p = δt sym(L_p), L_p = Σ_i v_i ⊗ G_ip, L_θθ = Σ_i S_ip v_r,i/r_p; V_p ← V_p det(I + δt L)
    for (std::size_t p = first; p < last; ++p) {
      const ShapeWeights& w = s.weights[p];
      const std::int32_t* slots = &particle_nodes_[(p - first) * support];
      VelocityGradient L;
      for (int bz = 0; bz < S; ++bz) {
        for (int a = 0; a < S; ++a) {
          const std::int32_t c = slots[bz * S + a];
          const double N = w.wr[a] * w.wz[bz], Gr = w.gr[a] * w.wz[bz], Gz = w.wr[a] * w.gz[bz];
          L.rr += vr_[c] * Gr;
          L.rz += vr_[c] * Gz;
          L.zr += vz_[c] * Gr;
          L.zz += vz_[c] * Gz;
          L.tt += vr_[c] * N;
        }
      }
      L.tt *= w.inverse_r;
      apply_velocity_gradient(L, h, s.strain_increment[p], s.spin_dt[p], P.volume[p]);
    }
    // Strain smoothing (smooth_volumetric_strain, this body's particles only).
    if (smoothed) {
      cell_volume.assign(cells, 0.0);
      cell_mean.assign(cells, 0.0);
      for (std::size_t p = first; p < last; ++p) {
        const std::int32_t c = particle_cell_[p - first];
        cell_volume[c] += P.volume[p];
        cell_mean[c] += P.volume[p] * trace(s.strain_increment[p]);
      }
      for (std::size_t p = first; p < last; ++p) {
        const std::int32_t c = particle_cell_[p - first];
        Voigt& de = s.strain_increment[p];
        const double shift = (cell_mean[c] / cell_volume[c] - trace(de)) / 3.0;
        de[0] += shift;
        de[1] += shift;
        de[2] += shift;
      }
    }
    // Jaumann rotation, then the law (update_stresses).
    for (std::size_t p = first; p < last; ++p) {
      Voigt& sig = P.stress[p];
      const double w = s.spin_dt[p];
      const double rr = sig[0], zz = sig[1], rz = sig[3];
      sig[0] = rr + 2.0 * w * rz;
      sig[1] = zz - 2.0 * w * rz;
      sig[3] = rz + w * (zz - rr);
      P.strain[p] += s.strain_increment[p];
    }
    group.update(first, last, P.stress, s.strain_increment, h);
  }

  // Work of the contact forces: Σ_k δt F_i·½(v^k + v^{k+1}) = F_i·(u_i − ½δt(v^N − v^0)), full 2π.
  double work = 0.0;
  for (std::size_t j = 0; j < impulses.size(); ++j) {
    const std::int32_t c = impulse_slots[j];
    work += impulses[j].r / dt * (ur_[c] - 0.5 * h * (vr_[c] - vr0_[c])) +
            impulses[j].z / dt * (uz_[c] - 0.5 * h * (vz_[c] - vz0_[c]));
  }
  contact_work_J_ += kTwoPi * work;

  // v_p ← α (v_p + Σ S (v^N − v^0)) + (1 − α) Σ S v^N;  x_p ← x_p + Σ S u   (kept inside the walls)
  const double alpha = s.settings.flip_fraction;
  const Walls& walls = s.walls;
  for (std::size_t p = first; p < last; ++p) {
    const ShapeWeights& w = s.weights[p];
    const std::int32_t* slots = &particle_nodes_[(p - first) * support];
    double vr = 0.0, vz = 0.0, dvr = 0.0, dvz = 0.0, ur = 0.0, uz = 0.0;
    for (int bz = 0; bz < S; ++bz) {
      for (int a = 0; a < S; ++a) {
        const std::int32_t c = slots[bz * S + a];
        const double N = w.wr[a] * w.wz[bz];
        vr += N * vr_[c];
        vz += N * vz_[c];
        dvr += N * (vr_[c] - vr0_[c]);
        dvz += N * (vz_[c] - vz0_[c]);
        ur += N * ur_[c];
        uz += N * uz_[c];
      }
    }
    P.vr[p] = alpha * (P.vr[p] + dvr) + (1.0 - alpha) * vr;
    P.vz[p] = alpha * (P.vz[p] + dvz) + (1.0 - alpha) * vz;
    double r = P.r[p] + ur, z = P.z[p] + uz;
    if (r < walls.r_min || r > walls.r_max || z < walls.z_min || z > walls.z_max) {
      r = std::clamp(r, walls.r_min, walls.r_max);
      z = std::clamp(z, walls.z_min, walls.z_max);
      ++s.wall_clamps;
    }
    P.r[p] = r;
    P.z[p] = z;
  }
  last_substeps_ = substeps;
  total_substeps_ += substeps;
}

}  // namespace ffp::mpm
