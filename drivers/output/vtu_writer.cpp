#include "drivers/output/vtu_writer.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "drivers/output/run_directory.hpp"

namespace ffp {

static_assert(std::endian::native == std::endian::little, "the VTU files declare LittleEndian");

std::string base64(std::span<const unsigned char> bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (std::uint32_t(bytes[i + 1]) << 8) | bytes[i + 2];
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t(bytes[i]) << 16;
    if (rest == 2) v |= std::uint32_t(bytes[i + 1]) << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += rest == 2 ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

/// VTK inline binary: one base64 stream of [UInt64 byte count][raw little-endian data].
template <class T>
std::string encoded(const std::vector<T>& values) {
  std::vector<unsigned char> bytes(sizeof(std::uint64_t) + values.size() * sizeof(T));
  const std::uint64_t count = values.size() * sizeof(T);
  std::memcpy(bytes.data(), &count, sizeof count);
  if (!values.empty()) std::memcpy(bytes.data() + sizeof count, values.data(), count);
  return base64(bytes);
}

std::string escaped(const std::string& name) {
  std::string out;
  for (char c : name) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void check_size(std::span<const double> a, std::size_t n, const std::string& what) {
  if (a.size() != n)
    throw std::invalid_argument("VTU: " + what + " has " + std::to_string(a.size()) + " values for " +
                                std::to_string(n) + " points");
}

std::vector<double> interleave(std::size_t n, std::span<const double> x, std::span<const double> y,
                               std::span<const double> z) {
  std::vector<double> out(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    out[3 * i] = x[i];
    out[3 * i + 1] = y[i];
    out[3 * i + 2] = z.empty() ? 0.0 : z[i];
  }
  return out;
}

}  // namespace

std::string vtu_text(const VtuPointCloud& cloud) {
  const std::size_t n = cloud.x.size();
  check_size(cloud.y, n, "y");
  if (!cloud.z.empty()) check_size(cloud.z, n, "z");
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "<UnstructuredGrid>\n";
  out += "<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(n) + "\">\n";
  out += "<PointData>\n";
  for (const VtuScalarField& f : cloud.scalars) {
    check_size(f.values, n, f.name);
    out += "<DataArray type=\"Float64\" Name=\"" + escaped(f.name) + "\" format=\"binary\">\n";
    out += encoded(std::vector<double>(f.values.begin(), f.values.end())) + "\n</DataArray>\n";
  }
  for (const VtuVectorField& f : cloud.vectors) {
    check_size(f.x, n, f.name + " x");
    check_size(f.y, n, f.name + " y");
    if (!f.z.empty()) check_size(f.z, n, f.name + " z");
    out += "<DataArray type=\"Float64\" Name=\"" + escaped(f.name) + "\" NumberOfComponents=\"3\" format=\"binary\">\n";
    out += encoded(interleave(n, f.x, f.y, f.z)) + "\n</DataArray>\n";
  }
  out += "</PointData>\n<Points>\n";
  out += "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">\n";
  out += encoded(interleave(n, cloud.x, cloud.y, cloud.z)) + "\n</DataArray>\n</Points>\n";
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  out += "<Cells>\n";
  out += "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">\n" + encoded(connectivity) +
         "\n</DataArray>\n";
  out += "<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">\n" + encoded(offsets) + "\n</DataArray>\n";
  out += "<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">\n" + encoded(types) + "\n</DataArray>\n";
  out += "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

void write_vtu(const std::filesystem::path& file, const VtuPointCloud& cloud) {
  write_file_atomically(file, vtu_text(cloud));
}

std::string PvdIndex::text() const {
  std::string out = "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
  char time[32];
  for (const auto& [t, file] : entries_) {
    std::snprintf(time, sizeof time, "%.9g", t);
    out += std::string("<DataSet timestep=\"") + time + "\" group=\"\" part=\"0\" file=\"" + escaped(file) + "\"/>\n";
  }
  out += "</Collection>\n</VTKFile>\n";
  return out;
}

void PvdIndex::write(const std::filesystem::path& file) const { write_file_atomically(file, text()); }

}  // namespace ffp
