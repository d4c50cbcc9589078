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

namespace ffp::mpm {

enum class Fixity : std::uint8_t { free, roller, fixed };
using FixityName = std::pair<Fixity, std::string_view>;
/// The scene's names of Fixity, in the order messages list them.
inline constexpr auto kFixityNames =
    std::to_array<FixityName>({{Fixity::free, "free"}, {Fixity::roller, "roller"}, {Fixity::fixed, "fixed"}});
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
/// the normal component, fixed both. `inner_is_axis` forces v_r = 0 on the inner side.
std::vector<NodeConstraint> constrained_nodes(const BoundaryConditions& bc, int nr, int nz, bool inner_is_axis);

}  // namespace ffp::mpm
