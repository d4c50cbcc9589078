#include "calibration/lab_curve.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "drivers/output/csv_writer.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

double LabCurve::peak_q_Pa() const {
  return deviatoric_stress_Pa.empty() ? 0.0
                                      : *std::max_element(deviatoric_stress_Pa.begin(), deviatoric_stress_Pa.end());
}

double LabCurve::axial_strain_at_peak() const {
  if (deviatoric_stress_Pa.empty()) return 0.0;
  const auto it = std::max_element(deviatoric_stress_Pa.begin(), deviatoric_stress_Pa.end());
  return axial_strain[static_cast<std::size_t>(it - deviatoric_stress_Pa.begin())];
}

namespace {

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// `lines`: the file line of each row (CsvData::lines), so that messages point where an editor does.
void check(const LabCurve& curve, const std::vector<std::size_t>& lines) {
  auto where = [&](std::size_t row) {
    return curve.source + ":" + (row < lines.size() ? std::to_string(lines[row]) : "row " + std::to_string(row + 1));
  };
  const std::size_t n = curve.axial_strain.size();
  if (curve.deviatoric_stress_Pa.size() != n ||
      (!curve.volumetric_strain.empty() && curve.volumetric_strain.size() != n))
    throw SceneError(curve.source + ": the columns have different lengths");
  if (n < kMinLabPoints)
    throw SceneError(curve.source + ": has " + std::to_string(n) + " data row(s); a lab curve needs at least " +
                     std::to_string(kMinLabPoints));
  for (std::size_t i = 0; i < n; ++i) {
    const double e = curve.axial_strain[i];
    if (!std::isfinite(e) || !std::isfinite(curve.deviatoric_stress_Pa[i]) ||
        (!curve.volumetric_strain.empty() && !std::isfinite(curve.volumetric_strain[i])))
      throw SceneError(where(i) + ": every value must be a finite number");
    if (e < 0.0)
      throw SceneError(where(i) + ": axial_strain " + number(e) +
                       " is negative; it must be ≥ 0 (compression positive, from the start of shearing)");
    if (e > 1.0)
      throw SceneError(where(i) + ": axial_strain " + number(e) + " is above 1 (a strain, not a percentage)");
    if (i > 0 && !(e > curve.axial_strain[i - 1]))
      throw SceneError(where(i) + ": axial_strain " + number(e) + " does not increase on the row before (" +
                       number(curve.axial_strain[i - 1]) + "); it must increase strictly from row to row");
  }
  if (!(curve.peak_q_Pa() > 0.0))
    throw SceneError(curve.source +
                     ": deviatoric_stress_kPa is never above 0; a triaxial compression curve needs q > 0 "
                     "(compression positive)");
}

}  // namespace

void check_lab_curve(const LabCurve& curve) { check(curve, {}); }

LabCurve read_lab_curve(const std::filesystem::path& file) {
  const CsvData data = read_numeric_csv(file);
  LabCurve curve;
  curve.source = file.string();
  for (const char* required : {"axial_strain", "deviatoric_stress_kPa"}) {
    if (!data.has(required)) {
      std::string header;
      for (const auto& c : data.columns) header += (header.empty() ? "" : ", ") + c;
      throw SceneError(curve.source + ": no column '" + required + "' (the header has: " + header +
                       "); a lab curve needs axial_strain and deviatoric_stress_kPa, optionally volumetric_strain");
    }
  }
  curve.axial_strain = data.column("axial_strain");
  curve.deviatoric_stress_Pa = data.column("deviatoric_stress_kPa");
  for (double& q : curve.deviatoric_stress_Pa) q *= 1e3;
  if (data.has("volumetric_strain")) curve.volumetric_strain = data.column("volumetric_strain");
  check(curve, data.lines);
  return curve;
}

}  // namespace ffp
