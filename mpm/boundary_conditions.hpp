#pragma once
/// Fixities on the four sides of the grid. The inner side is the axis when the
/// grid starts at r = 0: v_r = 0 there always (roller at least).
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/grid_axis.hpp"

namespace ffp::mpm {

/// `absorbing`: no fixity but viscous dashpots (Lysmer & Kuhlemeyer 1969) that let
/// waves leave the grid as into more of the same material, while holding the
/// static reaction the side carried at the start (a soil that goes on beyond it).
enum class Fixity : std::uint8_t { free, roller, fixed, absorbing };
using FixityName = std::pair<Fixity, std::string_view>;
/// The scene's names of Fixity, in the order messages list them.
inline constexpr auto kFixityNames = std::to_array<FixityName>(
    {{Fixity::free, "free"}, {Fixity::roller, "roller"}, {Fixity::fixed, "fixed"}, {Fixity::absorbing, "absorbing"}});
inline std::string to_string(Fixity f) {
  return std::string(std::ranges::find(kFixityNames, f, &FixityName::first)->second);
}

struct BoundaryConditions {
  Fixity inner = Fixity::roller;  ///< r = r_0 (the axis if r_0 = 0)
  Fixity outer = Fixity::roller;  ///< r = r_max
  Fixity bottom = Fixity::fixed;  ///< z = z_0
  Fixity top = Fixity::free;      ///< z = z_max
};

/// Which velocity components a node has fixed to zero.
enum ConstraintBits : std::uint8_t { constrain_r = 1, constrain_z = 2 };

struct NodeConstraint {
  std::uint32_t node;
  std::uint8_t bits;
};

/// The constrained nodes of an nr × nz grid (node = i + nr·j); a roller fixes
/// the normal component, fixed both, absorbing none. `inner_is_axis` forces v_r = 0 on the inner side.
std::vector<NodeConstraint> constrained_nodes(const BoundaryConditions& bc, int nr, int nz, bool inner_is_axis);

/// The sand (or other material) beyond the absorbing sides: density and wave speeds, and
/// optionally where the waves come from (r, z of the source; the FFP's impact point), which adds
/// the far field's static stiffness as springs (the viscous-spring boundary of Liu et al. 2006):
/// without it a dashpot-only side lets a load held for longer than a wave's transit drift away.
struct Impedance {
  double density_kg_m3, p_wave_m_s, s_wave_m_s;
  bool has_source = false;
  double source_r_m = 0.0, source_z_m = 0.0;
};
/// Liu et al. (2006): spring stiffness per unit area α G/R at a distance R from the source,
/// α_N = 1.33 normal to the side and α_T = 0.67 along it (their recommended values).
inline constexpr double kSpringNormal = 1.33, kSpringTangential = 0.67;

/// A node on an absorbing side: its grid position and which sides it lies on.
struct AbsorbingNode {
  std::uint32_t node;
  int i, j;           ///< node = i + nr·j
  bool bottom, top;   ///< on an absorbing side of normal z
  bool inner, outer;  ///< on an absorbing side of normal r
};

/// The nodes of the absorbing sides; an absorbing bottom's on row `bottom_row`.
std::vector<AbsorbingNode> absorbing_nodes(const BoundaryConditions& bc, int nr, int nz, int bottom_row = 0);

/// Dashpot coefficients per radian (kg/s) of a node on absorbing sides, the material's
/// impedance times the node's share A_i of the side: ρ c_p A_i normal to the side, ρ c_s A_i
/// along it (summed where two sides meet); with a source, springs α G A_i/R as well. A_i per radian with linear hats: ∫
/// N_i(r) r dr on a side of normal z, r_side ∫ N_j(z) dz on one of normal r, on the grid's present coordinates (a
/// moving mesh changes the sides' node spacings). `r` and `z` are the node coordinates.
struct Dashpot {
  double damping_r, damping_z;      ///< kg/s per radian
  double stiffness_r, stiffness_z;  ///< N/m per radian (0 without a source)
};
Dashpot dashpot(const AbsorbingNode& a, const GridAxis& r, const GridAxis& z, const Impedance& beyond);

}  // namespace ffp::mpm
