#include "drivers/app/particle_fields.hpp"

#include <cmath>
#include <cstdio>

#include "models/voigt.hpp"

namespace ffp {

ParticleFieldSeries::ParticleFieldSeries(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::filesystem::create_directories(dir_);
}

void ParticleFieldSeries::write(const mpm::Particles& P, double time_s, const ParticleFieldColumns& columns) {
  const std::size_t n = P.size();
  const bool stress = columns.stress_components;
  std::vector<double> body(n), dr(n), dz(n), p(n), q(n), ed(n), density(n);
  std::vector<double> srr(stress ? n : 0), szz(stress ? n : 0), stt(stress ? n : 0), srz(stress ? n : 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Voigt& sig = P.stress[i];
    body[i] = P.body[i];
    dr[i] = P.r[i] - P.r0[i];
    dz[i] = P.z[i] - P.z0[i];
    if (stress) {
      srr[i] = 1e-3 * sig[0];
      szz[i] = 1e-3 * sig[1];
      stt[i] = 1e-3 * sig[2];
      srz[i] = 1e-3 * sig[3];
    }
    p[i] = 1e-3 * mean_pressure(sig);
    q[i] = 1e-3 * deviatoric_stress(sig);
    ed[i] = deviatoric_strain(P.strain[i]);
    density[i] = P.mass[i] / P.volume[i];
  }
  VtuPointCloud cloud;
  cloud.x = P.r;
  cloud.y = P.z;
  cloud.scalars.push_back({"body", body});
  if (stress) {
    cloud.scalars.insert(cloud.scalars.end(),
                         {{"sigma_rr_kPa", srr}, {"sigma_zz_kPa", szz}, {"sigma_tt_kPa", stt}, {"sigma_rz_kPa", srz}});
  }
  cloud.scalars.insert(cloud.scalars.end(), {{"p_kPa", p}, {"q_kPa", q}, {"deviatoric_strain", ed}});
  for (const auto& [name, values] : columns.extra) cloud.scalars.push_back({name, values});
  cloud.scalars.push_back({"density_kg_m3", density});
  cloud.vectors = {{"velocity_m_s", P.vr, P.vz, {}}, {"displacement_m", dr, dz, {}}};
  char file[64];
  std::snprintf(file, sizeof file, "particles_%04d.vtu", static_cast<int>(pvd_.size()));
  write_vtu(dir_ / file, cloud);
  pvd_.add(time_s, file);
}

std::vector<std::pair<std::string, std::vector<double>>> micropolar_columns(const mpm::MicropolarFields& f) {
  if (!f.active()) return {};
  const std::size_t n = f.rotation.size();
  std::vector<double> relative(n), skew(n), couple(n);
  for (std::size_t i = 0; i < n; ++i) {
    relative[i] = f.macro_rotation[i] - f.rotation[i];
    skew[i] = 1e-3 * f.skew_stress[i];
    couple[i] =
        std::sqrt(f.couple_r[i] * f.couple_r[i] + f.couple_z[i] * f.couple_z[i] + f.couple_hoop[i] * f.couple_hoop[i]);
  }
  return {{"micro_rotation_rad", f.rotation},
          {"relative_rotation_rad", relative},
          {"skew_stress_kPa", skew},
          {"couple_stress_N_m", couple}};
}

std::vector<std::pair<std::string, std::vector<double>>> pore_fluid_columns(const mpm::Simulation& s) {
  if (!s.two_phase) return {};
  const mpm::TwoPhase& t = *s.two_phase;
  const std::size_t n = s.particles.size();
  std::vector<double> pressure(n), excess(n);
  for (std::size_t p = 0; p < n; ++p) {
    pressure[p] = 1e-3 * t.pore_pressure[p];
    excess[p] = 1e-3 * t.excess_pressure(s.particles, p);
  }
  return {{"pore_pressure_kPa", pressure}, {"excess_pore_pressure_kPa", excess}, {"porosity", t.porosity}};
}

void ParticleFieldSeries::finish() const {
  if (pvd_.size() > 0) pvd_.write(dir_ / "particles.pvd");
}

}  // namespace ffp
