#pragma once
/// The numerical triaxial of the paper's calibration (section 4.2) as a meshed
/// MPM specimen: "discretized using elements of the same size as those
/// considered in the FFP model (1 cm)". Softening localises in bands whose
/// width follows the cells, so W = ∫F dδ of a softening specimen depends on
/// the cell size; calibrating η on the FFP's cell size is what matches the
/// dissipated work where it matters.
///
/// The specimen (axisymmetric, weightless, dry/drained):
/// - a cylinder of radius D/2 and height H filled with particles (2×2 per
///   cell by default); the grid fits the specimen: n_r = round(R/h) cells
///   across the radius and n_z = round(H/h) over the height, so the cells are
///   h only where h divides R and H (0.5 cm: 0.5 × 0.5 cm; 1 cm: 0.875 × 1 cm;
///   2 cm: 1.75 × 1.875 cm). Empty cells of the same width continue the grid
///   past the radius so the specimen can bulge.
/// - initial stress σ = −σ3·I in every particle.
/// - cell pressure σ3 on the lateral face as a traction on the outermost
///   particles' current faces (radius r_p + λ_r·l_r, height 2λ_z·l_z with
///   λ = exp(ε) of the particle's accumulated strain), distributed with the
///   linear hats at the face point in r and the particle's own weights in z:
///   at the start this is exactly the consistent load of the face on its grid
///   line, so the isotropic state is in equilibrium to rounding. The face's
///   tilt is neglected (it stays radial). Not a SurfacePressure on the outer
///   grid line: that load stays on a fixed line while the face moves off it —
///   little before localisation (≤ 0.16 % of R at the peak, measured at 2, 1
///   and 0.5 cm) but up to 25–28 % of R by ε_a = 20 %, where the band pushes the
///   upper part outwards — and particles must not leave the grid.
/// - platens rough by default: the lab's porous stones. The end restraint is
///   what makes a perfect specimen localise as a real one does; with smooth
///   platens only the axis and the discretisation break the homogeneous state
///   (the Mohr-Coulomb peak check uses them for that homogeneity).
/// - bottom platen: the grid's bottom line, v_z = 0 (rough: v_r = 0 as well).
/// - top platen: the grid's top line, v_z = −v(t) (rough: v_r = 0), with v
///   ramped from 0 to v_platen by a half cosine over two axial periods 4H/c_p
///   of the specimen so the ramp excites no wave worth the name. The vertical
///   grid compresses with the platen, z_j(t) = z_j(0)·(H − δ)/H (a moving mesh:
///   mpm/grid_axis.hpp), so the platen stays a grid line and a particle keeps
///   its place in its cell in homogeneous compression.
///
/// What a load frame measures, and q as a lab reduces it (compression positive):
///   F_soil = 2π Σ_{top nodes} f^int_z      the soil's push on the top platen
///   A_top  = π R²  (rough: the soil is stuck to the platen)
///          = π r_top² (smooth: r_top = the top outer particle's face radius)
///   F      = F_soil − σ3·A_top             the piston force: the cell pressure carries
///                                          σ3 on the cap, the piston the rest
///   ε_a    = δ/H,  δ = platen displacement
///   ε_v    = 1 − V/V_0, V = 2π Σ V_p (particle volumes per radian)
///   A_c    = A (1 − ε_v)/(1 − ε_a)         the lab's right-cylinder area correction, A = π D²/4
///   q      = F/A_c                         the deviator stress a lab reports; for a
///                                          homogeneous specimen exactly the element test's σ1 − σ3
/// The calibration turns every curve (lab, element test, this) into work the same
/// way, W = A·H ∫ q dε_a, so q must mean the same on all three: a stress. The
/// piston's own work ∫F dδ is larger by the area correction (≈ +10 % over
/// 0–20 % strain with the bulge) and is reported beside it (`work_piston_J`).
/// Each output point (every `output_strain_step` of ε_a) is the δ-weighted mean
/// of q and ε_v over ±half a step around it (the first point is the initial
/// state): it filters what is left of the specimen's axial ringing and keeps
/// the area (see `MpmTriaxialResult::work_steps_J`).
#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "calibration/numerical_triaxial.hpp"
#include "drivers/triaxial_test.hpp"
#include "mpm/material_group.hpp"
#include "mpm/shape_functions.hpp"

namespace ffp {

enum class PlatenFriction { rough, smooth };
using PlatenFrictionName = std::pair<PlatenFriction, std::string_view>;
/// The scene's names of PlatenFriction, in the order messages list them.
inline constexpr auto kPlatenFrictionNames =
    std::to_array<PlatenFrictionName>({{PlatenFriction::rough, "rough"}, {PlatenFriction::smooth, "smooth"}});
inline std::string to_string(PlatenFriction friction) {
  return std::string(std::ranges::find(kPlatenFrictionNames, friction, &PlatenFrictionName::first)->second);
}

struct MpmTriaxialConfig {
  TriaxialSpecimen specimen;          ///< 0.15 m × 0.07 m (the paper's)
  double cell_m = 0.01;               ///< nominal cell size h (the FFP's 1 cm)
  double cell_pressure_Pa = 1.72e3;   ///< σ3
  double axial_strain_max = 0.2;      ///< the test stops at ε_a = this (the lab's last strain)
  double platen_velocity_m_s = 0.01;  ///< after the ramp
  PlatenFriction platens = PlatenFriction::rough;
  mpm::ShapeFunction shape_function = mpm::ShapeFunction::gimp;
  double courant = 0.9;
  /// α of the FLIP/PIC blend (mpm/model.hpp). The 10 % PIC share dissipates the
  /// velocity noise each softening burst leaves behind. Measured at 1 cm, η = 8,
  /// Courant 0.8: with 1 % PIC (α = 0.99) W wandered between 0.50 and 0.57 J over
  /// platen speeds 0.01, 0.005, 0.0025 and 0.00125 m/s (the band picks a different
  /// pattern each time); with 10 % it converges, 0.652, 0.647, 0.644 J at 0.01,
  /// 0.005, 0.0025 m/s, and at the slowest speed it agrees within 0.4 % with
  /// Cundall damping 0.2 (0.643 J) and pure PIC (0.646 J).
  double flip_fraction = 0.9;
  double local_damping = 0.0;  ///< Cundall's local damping coefficient (0: none)
  int particles_per_cell = 2;  ///< per direction
  /// Sets the time scale only (weightless, quasi-static): the sand's γ_d = 14.6 kN/m³.
  double density_kg_m3 = 14.6e3 / 9.81;
  double output_strain_step = 1e-3;  ///< spacing of the curve's points in ε_a
  double radial_margin = 0.5;        ///< empty grid beyond R, as a fraction of R
};

struct MpmTriaxialResult {
  SpecimenCurve curve;                 ///< q, ε_a, ε_v at the output points
  std::vector<double> axial_force_N;   ///< q·A at the output points (the calibration's force)
  std::vector<double> piston_force_N;  ///< F = F_soil − σ3·A_top (same windows)
  std::vector<double> bottom_q_Pa;     ///< q from the bottom platen's force (same windows)
  /// A·H ∫ q dε_a over every step (trapezoid per step): what the curve's trapezoid approximates.
  double work_steps_J = 0.0;
  double work_curve_J = 0.0;   ///< A·H ∫ q dε_a of the output curve (trapezoid on its points)
  double work_piston_J = 0.0;  ///< ∫F dδ of the piston force over every step
  double peak_q_Pa = 0.0;      ///< of the output curve
  double axial_strain_at_peak = 0.0;
  /// max over the output points of |q_top − q_bottom| / peak q: inertia left in the test.
  double platen_force_imbalance = 0.0;
  /// Lateral face at the peak: outer particles' face radii relative to R, minus 1.
  double bulge_at_peak_min = 0.0, bulge_at_peak_max = 0.0;
  double bulge_at_end_min = 0.0, bulge_at_end_max = 0.0;
  long steps = 0;
  std::size_t particles = 0;
  int cells_r = 0, cells_z = 0;  ///< across the specimen (the grid has more radially)
  double cell_r_m = 0.0, cell_z_m = 0.0;
  double ramp_time_s = 0.0;
  double wall_time_s = 0.0;
  long wall_clamps = 0;  ///< particle moves stopped at a wall (should stay 0)
};

/// Runs one test. Throws std::invalid_argument for a config that is not a
/// test, mpm::StepFailure if the step fails (a particle leaves the grid, NaN).
MpmTriaxialResult run_mpm_triaxial(const mpm::MaterialLaw& law, const MpmTriaxialConfig& config);

/// Sees every run of a numerical triaxial (its η and the whole result): timings, diagnostics.
using MpmTriaxialObserver = std::function<void(double eta, const MpmTriaxialResult& result)>;

/// η ↦ the MPM specimen's response with `material`'s softening factor replaced by η.
NumericalTriaxial mpm_triaxial_specimen(const StrainSofteningParameters& material, const MpmTriaxialConfig& config,
                                        MpmTriaxialObserver observer = {});

}  // namespace ffp
