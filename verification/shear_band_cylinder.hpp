#pragma once
/// A shear band in the MPM: the axial shear of a long thick hollow cylinder of sand
/// (docs/verification.md#localisation-with-a-fixed-width).
///
/// The annulus r_i ≤ r ≤ r_o, confined by an isotropic stress p0, has its inner wall dragged
/// axially (rough: the soil moves with it, and turns no grain: ω = 0) while the outer wall is
/// fixed (u = 0, ω = 0). The cylinder is long: nothing depends on z. The grid holds one cell
/// row of soil, and every node column moves axially as one (its nodes take the column's
/// mass-weighted mean velocity, and its rotational-mass-weighted mean micro-spin): the long
/// cylinder's kinematics. The row's free z-faces then carry nothing of their own, since the
/// nodal forces of σ_zz over a column sum to zero (a column's shape functions sum to one in z).
/// Every node is held radially (u_r = 0, as in the long cylinder). Statics: r T(r) = const,
/// T the axial traction on a face of normal e_r, so the shear peaks at the inner wall
/// (τ ∝ 1/r) and softening starts there.
///
/// The wall's speed rises as a half cosine over `ramp_s`, then stays at `wall_speed_m_s`;
/// quasi-static by a slow drag and Cundall's local damping on the free nodes (the wall's
/// force and the outer wall's agree to the damping's and the inertia's share).
#include <optional>
#include <vector>

#include "models/micropolar.hpp"
#include "mpm/model.hpp"

namespace ffp::verification {

struct ShearBandCase {
  MaterialLaw law;
  double density_kg_m3 = 1490.0;
  std::optional<MicropolarParameters> micropolar = std::nullopt;
  double inner_m = 0.5, outer_m = 0.55;  ///< r_i, r_o
  double confinement_Pa = 50e3;          ///< p0, the isotropic initial stress (compression)
  double wall_speed_m_s = 0.05;
  double ramp_s = 0.02;
  double end_displacement_m = 0.01;  ///< the inner wall's axial travel at the end
  /// When set, the run ends sooner: this far past the travel of the wall's largest force
  /// (a band compared at the same slip past the peak).
  std::optional<double> end_past_peak_m = std::nullopt;
  double local_damping = 0.3;
  mpm::Transfer transfer = mpm::Transfer::musl;
  int particles_per_cell = 2;  ///< across r (one particle per cell along z)
};

/// The walls' axial forces per radian and per metre of height (N/m): r T on each wall, which
/// statics makes equal.
struct ShearBandRecord {
  double displacement_m;  ///< the inner wall's travel
  double inner_force, outer_force;
};

struct ShearBandRun {
  std::vector<ShearBandRecord> history;  ///< one record per step
  std::vector<double> radius_m;          ///< the cells' centres, ascending
  std::vector<double> plastic_shear;     ///< |γ^p|, γ^p = 2 ε_rz − σ_rz/G, of each cell at the end
  std::vector<double> softening;         ///< the law's κ of each cell (0 for a law without it)
  long steps = 0;
};

/// The cylinder of `c` on cells of `cell_m` (square), from rest to the end displacement.
ShearBandRun run_shear_band(const ShearBandCase& c, double cell_m);

/// The largest inner-wall force of a run and the wall's travel there.
ShearBandRecord peak_of(const ShearBandRun& run);

/// The inner-wall force at travel `displacement_m` (linear between steps).
double inner_force_at(const ShearBandRun& run, double displacement_m);

/// The width of the band a profile x(r) (ascending radii, the wall at r_wall) shows.
struct BandWidth {
  double half_maximum_m;  ///< the measure of {r : x(r) ≥ max x / 2}, x linear between samples
                          ///< and x(r_wall) = x of the first sample
  double moment_m;        ///< 2 ∫ (r − r_wall) x⁺ dr / ∫ x⁺ dr: a uniform band's width
};

BandWidth band_width(const std::vector<double>& r, const std::vector<double>& x, double r_wall);

// The cylinder of the verification (docs/verification.md#localisation-with-a-fixed-width), one
// definition for its tests and the report.

/// The paper's sand (E' 2500 kPa, ν' 0.33, γ_d 14.6 kN/m³, φ'_p 39°, φ'_c 32°) softening at
/// the paper's η = 8, with ψ = 0: held radially (u_r = 0) the soil cannot dilate, and a
/// dilatancy would raise p' and the strength with it, against the softening studied here.
StrainSofteningMohrCoulomb paper_softening_sand();

/// The annulus 0.5–0.55 m: a wall of 50 ℓ (ℓ = 1 mm) across which τ ∝ 1/r falls by 10 %, a
/// gradient mild enough that ℓ, not the gradient, sets the band (at r_i = 1 m, half the
/// gradient, the band is 6 % wider). p0 = 50 kPa: the vertical stress 3.4 m down in this sand.
/// The wall travels 5 mm at 0.05 m/s: quasi-static (the two walls' forces agree to 0.2 %; at
/// 0.025 m/s the band moves by 0.4 % and the post-peak force by less than 0.02 kPa).
ShearBandCase paper_sand_cylinder(MaterialLaw law, std::optional<MicropolarParameters> micropolar);

/// ℓ, G_c = G/2, j = ℓ² (the static answer does not depend on j: at j = ℓ²/10 and 4ℓ² the band
/// and the forces move by less than 0.1 %).
MicropolarParameters cylinder_micropolar(double length_m);

}  // namespace ffp::verification
