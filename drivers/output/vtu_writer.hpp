#pragma once
/// ParaView point clouds: VTK XML UnstructuredGrid files (.vtu, one vertex
/// cell per point, base64 binary Float64) and the .pvd index that lists them
/// with their times. Plain arrays in; nothing here knows about the MPM.
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ffp {

struct VtuScalarField {
  std::string name;
  std::span<const double> values;
};

/// A vector field from its components (z empty: a 2D vector, third component 0).
struct VtuVectorField {
  std::string name;
  std::span<const double> x, y, z;
};

struct VtuPointCloud {
  std::span<const double> x, y, z;  ///< positions (z empty: 0)
  std::vector<VtuScalarField> scalars;
  std::vector<VtuVectorField> vectors;
};

/// The file's full text. Throws std::invalid_argument when arrays disagree in length.
std::string vtu_text(const VtuPointCloud& cloud);
/// Written via a temporary file and renamed.
void write_vtu(const std::filesystem::path& file, const VtuPointCloud& cloud);

/// Base64 (RFC 4648) of raw bytes, as VTK's inline binary data uses it.
std::string base64(std::span<const unsigned char> bytes);

/// The .pvd index of a time series: entries refer to files relative to the .pvd.
class PvdIndex {
 public:
  void add(double time_s, std::string relative_file) { entries_.emplace_back(time_s, std::move(relative_file)); }
  std::size_t size() const { return entries_.size(); }
  std::string text() const;
  /// Written via a temporary file and renamed.
  void write(const std::filesystem::path& file) const;

 private:
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace ffp
