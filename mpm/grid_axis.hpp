#pragma once
/// Node coordinates along one grid direction (r or z), possibly non-uniform,
/// with an O(1) cell lookup. The vertical axis of the FFP's moving mesh is
/// this same object with its coordinates replaced between steps.
#include <span>
#include <vector>

namespace ffp::mpm {

class GridAxis {
 public:
  GridAxis() = default;
  /// Strictly increasing coordinates, at least 3 nodes (2 cells) so that a
  /// GIMP particle's three-node support always fits. Throws std::invalid_argument.
  explicit GridAxis(std::vector<double> coordinates);

  /// Moving mesh: new coordinates, same count, still strictly increasing.
  void set_coordinates(std::span<const double> coordinates);

  int nodes() const { return static_cast<int>(x_.size()); }
  int cells() const { return nodes() - 1; }
  double coordinate(int node) const { return x_[static_cast<std::size_t>(node)]; }
  double spacing(int cell) const { return coordinate(cell + 1) - coordinate(cell); }
  double inverse_spacing(int cell) const { return inverse_spacing_[static_cast<std::size_t>(cell)]; }
  double min_spacing() const { return min_spacing_; }
  double front() const { return x_.front(); }
  double back() const { return x_.back(); }
  std::span<const double> coordinates() const { return x_; }

  /// The cell holding x (the last cell for x = back()), or −1 outside the axis.
  int cell_of(double x) const {
    if (!(x >= x_.front() && x <= x_.back())) return -1;
    std::size_t bucket = static_cast<std::size_t>((x - x_.front()) * inverse_bucket_);
    if (bucket >= lookup_.size()) bucket = lookup_.size() - 1;
    int c = lookup_[bucket];
    const int last = cells() - 1;
    while (c < last && x >= x_[static_cast<std::size_t>(c) + 1]) ++c;
    return c;
  }

  /// cell_of(x), trying `hint` first: a particle's cell of the previous step,
  /// which holds it again in most steps (a particle moves less than a cell).
  int cell_near(double x, int hint) const {
    if (hint >= 0 && hint < cells() && x >= x_[static_cast<std::size_t>(hint)] &&
        x < x_[static_cast<std::size_t>(hint) + 1])
      return hint;
    return cell_of(x);
  }

  /// ∫_a^b N_node(x) dx of the node's hat function (exact, any spacing).
  double hat_integral(int node, double a, double b) const;
  /// ∫_a^b N_node(x) x dx (exact, any spacing): per radian, the area a node of the radial
  /// axis takes on a face of normal z, whose element is r dθ dr.
  double hat_moment(int node, double a, double b) const;

 private:
  void build_lookup();

  std::vector<double> x_;
  std::vector<double> inverse_spacing_;  ///< 1/h per cell
  std::vector<int> lookup_;              ///< bucket → first candidate cell
  double inverse_bucket_ = 0.0;
  double min_spacing_ = 0.0;
};

}  // namespace ffp::mpm
