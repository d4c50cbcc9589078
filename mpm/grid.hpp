#pragma once
/// The background grid: a tensor product of radial node coordinates (fixed)
/// and vertical node coordinates (replaceable each step: the moving mesh),
/// with one or more nodal velocity fields. Node (i, j) has index i + nr·j.
#include <cstddef>
#include <vector>

#include "mpm/boundary_conditions.hpp"
#include "mpm/grid_axis.hpp"
#include "mpm/nodal_field.hpp"

namespace ffp::mpm {

struct Grid {
  GridAxis r;
  GridAxis z;
  std::vector<NodalField> fields;           ///< [0] is the system field (the only one without contact)
  std::vector<NodeConstraint> constraints;  ///< from the boundary conditions

  std::size_t nodes() const { return static_cast<std::size_t>(r.nodes()) * static_cast<std::size_t>(z.nodes()); }
  std::size_t cells() const { return static_cast<std::size_t>(r.cells()) * static_cast<std::size_t>(z.cells()); }
  std::size_t node(int i, int j) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(r.nodes()) * static_cast<std::size_t>(j);
  }
  std::size_t cell(int i, int j) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(r.cells()) * static_cast<std::size_t>(j);
  }
  double min_spacing() const { return r.min_spacing() < z.min_spacing() ? r.min_spacing() : z.min_spacing(); }
  /// The grid starts on the symmetry axis.
  bool has_axis() const { return r.front() == 0.0; }
};

}  // namespace ffp::mpm
