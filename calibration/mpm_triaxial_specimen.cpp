#include "calibration/mpm_triaxial_specimen.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/math_constants.hpp"
#include "mpm/diagnostics.hpp"
#include "mpm/simulation.hpp"
#include "mpm/stages.hpp"

namespace ffp {

namespace {

using Clock = std::chrono::steady_clock;
using mpm::Simulation;

/// Everything the specimen's own stages share: the platen's motion, the node
/// sets it measures, and one sample per step.
struct Platens {
  double radius_m = 0.0, height_m = 0.0, cell_pressure_Pa = 0.0;
  bool rough = true;
  double speed_m_s = 0.0;  ///< after the ramp
  double ramp_s = 0.0;
  double step_speed_m_s = 0.0;  ///< of the current step (mid-step value of the ramp)
  double displacement_m = 0.0;  ///< δ at the start of the current step
  std::vector<double> z0;       ///< the grid's initial vertical coordinates
  std::vector<double> z;        ///< scratch for the compressed coordinates
  std::vector<std::size_t> top_nodes, bottom_nodes;
  std::vector<std::size_t> face;  ///< particles on the lateral face
  std::size_t top_corner = 0;     ///< the face particle next to the top platen
  double initial_volume_m3 = 0.0;

  // One sample per step, at the step's start configuration.
  std::vector<double> axial_strain, piston_force, q_top, q_bottom, volumetric_strain, bulge_min, bulge_max;

  double speed_at(double t) const {
    if (t >= ramp_s) return speed_m_s;
    return speed_m_s * 0.5 * (1.0 - std::cos(kPi * t / ramp_s));
  }

  /// The face radius of particle p: its centre plus its (stretched) half-width.
  static double face_radius(const mpm::Particles& P, std::size_t p) {
    return P.r[p] + P.half_r[p] * std::exp(P.strain[p][0]);
  }
};

// The ramp's speed at mid-step: δ then advances by the midpoint rule.
void set_platen_speed(Simulation& s, Platens& platens) {
  platens.step_speed_m_s = platens.speed_at(s.time_s + 0.5 * s.dt_s);
}

// F_soil = 2π Σ_top f^int_z (the soil pushes the top nodes up: f^int_z > 0 in
// compression), the bottom's with the opposite sign; F = F_soil − σ3·A_top;
// ε_v = 1 − V/V_0 from the particles' current volumes; q = F/A_c with the lab's
// area correction A_c = A_0 (1 − ε_v)/(1 − ε_a).
void measure_platens(Simulation& s, Platens& platens) {
  const mpm::NodalField& f = s.grid.fields[0];
  const double top_force = mpm::vertical_internal_force_N(f, platens.top_nodes);
  const double bottom_force = -mpm::vertical_internal_force_N(f, platens.bottom_nodes);
  const mpm::Particles& P = s.particles;
  double r_top = platens.radius_m;
  if (!platens.rough) r_top = Platens::face_radius(P, platens.top_corner);
  const double top_area = kPi * r_top * r_top;
  // The bottom platen is rough or smooth like the top; the bottom face's radius
  // under a smooth platen is not tracked, and the top's stands in for it (the
  // bottom q is a check of quasi-statics, not a result).
  double volume = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) volume += P.volume[p];
  volume *= kTwoPi;
  const double axial_strain = platens.displacement_m / platens.height_m;
  const double volumetric_strain = 1.0 - volume / platens.initial_volume_m3;
  const double corrected_area =
      kPi * platens.radius_m * platens.radius_m * (1.0 - volumetric_strain) / (1.0 - axial_strain);
  const double piston = top_force - platens.cell_pressure_Pa * top_area;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t p : platens.face) {
    const double r = Platens::face_radius(P, p) / platens.radius_m - 1.0;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  platens.axial_strain.push_back(axial_strain);
  platens.piston_force.push_back(piston);
  platens.q_top.push_back(piston / corrected_area);
  platens.q_bottom.push_back((bottom_force - platens.cell_pressure_Pa * top_area) / corrected_area);
  platens.volumetric_strain.push_back(volumetric_strain);
  platens.bulge_min.push_back(lo);
  platens.bulge_max.push_back(hi);
}

// The cell pressure on the lateral face, per radian: each face particle's face
// (radius r_f, height l_f) carries σ3·r_f·l_f inward, spread with the linear
// hats at r_f and the particle's own z weights:
//   f_i,r −= σ3 r_f l_f N_I(r_f) s_z,j(z_p)
// (exact for the initial face on its grid line: Σ_p l_f s_z,j = ∫ N_j dz).
void apply_cell_pressure(Simulation& s, const Platens& platens) {
  const mpm::Particles& P = s.particles;
  mpm::NodalField& f = s.grid.fields[0];
  const int support = s.settings.shape_function == mpm::ShapeFunction::gimp ? 3 : 2;
  for (std::size_t p : platens.face) {
    const double rf = Platens::face_radius(P, p);
    const int c = s.grid.r.cell_of(rf);
    if (c < 0)
      throw mpm::StepFailure("the specimen's face left the grid at r = " + std::to_string(rf) +
                             " m (t = " + std::to_string(s.time_s) + " s): widen the radial margin");
    const double lf = 2.0 * P.half_z[p] * std::exp(P.strain[p][1]);
    const double x0 = s.grid.r.coordinate(c), x1 = s.grid.r.coordinate(c + 1);
    const double n0 = (x1 - rf) * s.grid.r.inverse_spacing(c), n1 = (rf - x0) * s.grid.r.inverse_spacing(c);
    const double load = platens.cell_pressure_Pa * rf * lf;
    const mpm::ShapeWeights& w = s.weights[p];
    for (int b = 0; b < support; ++b) {
      const double fz = load * w.wz[b];
      f.external_force_r[s.grid.node(c, w.node_z + b)] -= fz * n0;
      f.external_force_r[s.grid.node(c + 1, w.node_z + b)] -= fz * n1;
    }
  }
}

// Top platen nodes: v^{n+1}_z = −v (rough: v_r = 0). After the grid update
// only v^{n+1} is set, so the FLIP increment v^{n+1} − p/m carries the
// platen's impulse to the particles; after the MUSL remap the velocity the
// strain rate uses is the platen's too.
void drive_top_platen(Simulation& s, const Platens& platens, bool remapped) {
  mpm::NodalField& f = s.grid.fields[0];
  const double v = -platens.step_speed_m_s;
  for (std::size_t i : platens.top_nodes) {
    f.velocity_new_z[i] = v;
    if (remapped) f.velocity_z[i] = v;
    if (platens.rough) {
      f.velocity_new_r[i] = 0.0;
      f.velocity_r[i] = 0.0;
    }
  }
}

// δ ← δ + v Δt;  z_j ← z_j(0)·(H − δ)/H  (the grid compresses with the platen).
void move_top_platen(Simulation& s, Platens& platens) {
  platens.displacement_m += platens.step_speed_m_s * s.dt_s;
  const double scale = (platens.height_m - platens.displacement_m) / platens.height_m;
  if (!(scale > 0.0)) throw mpm::StepFailure("the platen has crushed the specimen");
  for (std::size_t j = 0; j < platens.z0.size(); ++j) platens.z[j] = platens.z0[j] * scale;
  s.grid.z.set_coordinates(platens.z);
}

/// The core's stage list with the specimen's stages woven in.
mpm::StageList specimen_stages(const mpm::StageList& core, Platens& platens) {
  mpm::StageList list;
  int boundary_passes = 0;
  bool moved = false;
  for (const mpm::Stage& stage : core.items()) {
    if (stage.name == "reset_grid")
      list.append({"set_platen_speed", [&platens](Simulation& s) { set_platen_speed(s, platens); }});
    if (stage.name == "update_time_step") {
      list.append({"move_top_platen", [&platens](Simulation& s) { move_top_platen(s, platens); }});
      moved = true;
    }
    list.append(stage);
    if (stage.name == "compute_internal_forces") {
      list.append({"measure_platens", [&platens](Simulation& s) { measure_platens(s, platens); }});
      list.append({"apply_cell_pressure", [&platens](Simulation& s) { apply_cell_pressure(s, platens); }});
    }
    if (stage.name == "apply_boundary_conditions") {
      const bool remapped = boundary_passes++ > 0;
      list.append({remapped ? "drive_top_platen_remapped" : "drive_top_platen",
                   [&platens, remapped](Simulation& s) { drive_top_platen(s, platens, remapped); }});
    }
  }
  if (!moved || boundary_passes != 2 || !list.contains("measure_platens") || !list.contains("set_platen_speed"))
    throw std::logic_error("mpm triaxial: the core's stage list is not the MUSL step this specimen expects: " +
                           core.describe());
  return list;
}

std::vector<double> even_nodes(double from, double to, int cells) {
  std::vector<double> x;
  for (int i = 0; i <= cells; ++i) x.push_back(from + (to - from) * i / cells);
  x.back() = to;
  return x;
}

void check(const MpmTriaxialConfig& c) {
  auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("mpm triaxial: ") + what + " must be > 0");
  };
  positive(c.specimen.height_m, "the specimen height");
  positive(c.specimen.diameter_m, "the specimen diameter");
  positive(c.cell_m, "the cell size");
  positive(c.cell_pressure_Pa, "the cell pressure");
  positive(c.axial_strain_max, "the last axial strain");
  positive(c.platen_velocity_m_s, "the platen velocity");
  positive(c.courant, "the Courant number");
  positive(c.density_kg_m3, "the density");
  positive(c.output_strain_step, "the output strain step");
  positive(c.radial_margin, "the radial margin");
  if (c.courant > 1.0) throw std::invalid_argument("mpm triaxial: the Courant number must be ≤ 1");
  if (c.axial_strain_max >= 0.9) throw std::invalid_argument("mpm triaxial: the last axial strain must be < 0.9");
  if (c.particles_per_cell < 1 || c.particles_per_cell > 8)
    throw std::invalid_argument("mpm triaxial: particles per cell must be in [1, 8]");
  if (c.cell_m > 0.5 * c.specimen.height_m)
    throw std::invalid_argument("mpm triaxial: the cell must fit twice into the specimen's height");
}

/// δ-weighted mean of y over [a, b] (the polyline through the samples).
double window_mean(const std::vector<double>& x, const std::vector<double>& y, double a, double b) {
  return area_under(x, y, a, b) / (b - a);
}

}  // namespace

MpmTriaxialResult run_mpm_triaxial(const mpm::MaterialLaw& law, const MpmTriaxialConfig& config) {
  check(config);
  const auto start = Clock::now();
  const double radius = 0.5 * config.specimen.diameter_m, height = config.specimen.height_m;
  MpmTriaxialResult result;
  result.cells_r = std::max(1, static_cast<int>(std::lround(radius / config.cell_m)));
  result.cells_z = std::max(2, static_cast<int>(std::lround(height / config.cell_m)));
  result.cell_r_m = radius / result.cells_r;
  result.cell_z_m = height / result.cells_z;

  mpm::ModelDescription model;
  // Empty cells beyond R for the bulge, at least two (a GIMP support is three nodes).
  const int margin_cells = std::max(2, static_cast<int>(std::ceil(config.radial_margin * radius / result.cell_r_m)));
  model.r_nodes_m = even_nodes(0.0, radius, result.cells_r);
  for (int i = 1; i <= margin_cells; ++i) model.r_nodes_m.push_back(radius + i * result.cell_r_m);
  model.z_nodes_m = even_nodes(0.0, height, result.cells_z);
  model.bodies.push_back({"specimen", law, config.density_kg_m3, mpm::BoxRegion{0.0, radius, 0.0, height},
                          config.particles_per_cell, config.particles_per_cell, 0.0, 0.0, std::nullopt});
  const bool rough = config.platens == PlatenFriction::rough;
  // The top is driven by the specimen's own stages; the outer side is the cell (free).
  model.boundaries = {mpm::Fixity::roller, mpm::Fixity::free, rough ? mpm::Fixity::fixed : mpm::Fixity::roller,
                      mpm::Fixity::free};
  model.solver.shape_function = config.shape_function;
  model.solver.transfer = mpm::Transfer::musl;
  model.solver.courant = config.courant;
  model.solver.flip_fraction = config.flip_fraction;
  model.solver.local_damping = config.local_damping;

  Simulation s(model);
  Platens platens;
  platens.radius_m = radius;
  platens.height_m = height;
  platens.cell_pressure_Pa = config.cell_pressure_Pa;
  platens.rough = rough;
  platens.speed_m_s = config.platen_velocity_m_s;
  const mpm::MaterialGroup& group = s.groups.front();
  const double wave_speed = std::sqrt(group.constrained_modulus() / config.density_kg_m3);
  // Two periods of the specimen's first axial mode (fixed–driven rod: 4H/c_p).
  platens.ramp_s = 2.0 * 4.0 * height / wave_speed;
  result.ramp_time_s = platens.ramp_s;
  const std::vector<double> z0(s.grid.z.coordinates().begin(), s.grid.z.coordinates().end());
  platens.z0 = z0;
  platens.z = z0;
  const int nr = s.grid.r.nodes(), top = s.grid.z.nodes() - 1;
  for (int i = 0; i < nr; ++i) {
    platens.top_nodes.push_back(s.grid.node(i, top));
    platens.bottom_nodes.push_back(s.grid.node(i, 0));
  }
  mpm::Particles& P = s.particles;
  double top_z = -1.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    P.stress[p] = Voigt::Zero();
    P.stress[p][0] = P.stress[p][1] = P.stress[p][2] = -config.cell_pressure_Pa;
    platens.initial_volume_m3 += P.volume[p];
    if (std::abs(P.r0[p] + P.half_r[p] - radius) < 1e-9 * radius) {
      platens.face.push_back(p);
      if (P.z0[p] > top_z) {
        top_z = P.z0[p];
        platens.top_corner = p;
      }
    }
  }
  platens.initial_volume_m3 *= kTwoPi;
  if (platens.face.empty()) throw std::logic_error("mpm triaxial: no particle on the lateral face");
  // The constructor's step saw zero stress; the initial σ3 barely changes it, but use it.
  s.dt_limit_s = mpm::cfl_time_step_limit(s);
  s.dt_s = s.dt_next_s = config.courant * s.dt_limit_s;
  s.stages = specimen_stages(s.stages, platens);
  result.particles = P.size();

  const double strain_max = config.axial_strain_max;
  while (platens.axial_strain.empty() || platens.axial_strain.back() < strain_max) s.advance();
  result.steps = s.step;
  result.wall_clamps = s.wall_clamps;

  // The curve: the initial state, then window means every output step up to ε_max.
  const std::vector<double>& e = platens.axial_strain;
  const double step = config.output_strain_step;
  const double area = config.specimen.area_m2();
  SpecimenCurve& curve = result.curve;
  curve.axial_strain.push_back(0.0);
  curve.deviatoric_stress_Pa.push_back(platens.q_top.front());
  curve.volumetric_strain.push_back(platens.volumetric_strain.front());
  result.bottom_q_Pa.push_back(platens.q_bottom.front());
  result.piston_force_N.push_back(platens.piston_force.front());
  const long points = static_cast<long>(std::ceil(strain_max / step - 1e-9));
  for (long k = 1; k <= points; ++k) {
    const double x = k == points ? strain_max : static_cast<double>(k) * step;
    const double a = std::max(0.0, x - 0.5 * step), b = std::min(strain_max, x + 0.5 * step);
    curve.axial_strain.push_back(x);
    curve.deviatoric_stress_Pa.push_back(window_mean(e, platens.q_top, a, b));
    curve.volumetric_strain.push_back(window_mean(e, platens.volumetric_strain, a, b));
    result.bottom_q_Pa.push_back(window_mean(e, platens.q_bottom, a, b));
    result.piston_force_N.push_back(window_mean(e, platens.piston_force, a, b));
  }
  for (double q : curve.deviatoric_stress_Pa) result.axial_force_N.push_back(q * area);
  const double volume = area * height;  // W = ∫ q A d(ε_a H)
  result.work_steps_J = volume * area_under(e, platens.q_top, 0.0, strain_max);
  result.work_curve_J = volume * area_under(curve.axial_strain, curve.deviatoric_stress_Pa, 0.0, strain_max);
  result.work_piston_J = height * area_under(e, platens.piston_force, 0.0, strain_max);

  const auto peak = std::max_element(curve.deviatoric_stress_Pa.begin(), curve.deviatoric_stress_Pa.end());
  const auto k_peak = static_cast<std::size_t>(peak - curve.deviatoric_stress_Pa.begin());
  result.peak_q_Pa = *peak;
  result.axial_strain_at_peak = curve.axial_strain[k_peak];
  for (std::size_t k = 1; k < curve.axial_strain.size(); ++k)
    result.platen_force_imbalance =
        std::max(result.platen_force_imbalance,
                 std::abs(curve.deviatoric_stress_Pa[k] - result.bottom_q_Pa[k]) / result.peak_q_Pa);
  // The bulge at the sample nearest the peak's strain, and at the end.
  const std::size_t i_peak =
      static_cast<std::size_t>(std::lower_bound(e.begin(), e.end(), result.axial_strain_at_peak) - e.begin());
  const std::size_t i = std::min(i_peak, e.size() - 1);
  result.bulge_at_peak_min = platens.bulge_min[i];
  result.bulge_at_peak_max = platens.bulge_max[i];
  result.bulge_at_end_min = platens.bulge_min.back();
  result.bulge_at_end_max = platens.bulge_max.back();
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

NumericalTriaxial mpm_triaxial_specimen(const StrainSofteningParameters& material, const MpmTriaxialConfig& config,
                                        MpmTriaxialObserver observer) {
  check(config);
  return [material, config, observer](double eta) {
    StrainSofteningParameters p = material;
    p.softening_factor = eta;
    MpmTriaxialResult result = run_mpm_triaxial(StrainSofteningMohrCoulomb(p), config);
    if (observer) observer(eta, result);
    return std::move(result.curve);
  };
}

}  // namespace ffp
