#pragma once
/// A laboratory drained triaxial curve: what the calibration fits the model to.
///
/// File format (data/lab/README.md): CSV with a header row, '#' comment lines,
/// columns `axial_strain` (–, compression positive), `deviatoric_stress_kPa`
/// and optionally `volumetric_strain` (–, compression positive); other
/// columns are ignored. The strain must start at ≥ 0 and increase strictly;
/// at least 5 rows.
#include <filesystem>
#include <string>
#include <vector>

namespace ffp {

struct LabCurve {
  std::string source;                        ///< where it came from (for messages and plots)
  std::vector<double> axial_strain;          ///< ≥ 0, strictly increasing
  std::vector<double> deviatoric_stress_Pa;  ///< q
  std::vector<double> volumetric_strain;     ///< empty when the file has no such column

  double peak_q_Pa() const;
  double axial_strain_at_peak() const;
};

inline constexpr std::size_t kMinLabPoints = 5;

/// Reads and checks a lab curve. Bad files throw SceneError with one line
/// naming the file, the line and what is allowed.
LabCurve read_lab_curve(const std::filesystem::path& file);

/// The same checks on a curve built in memory (`source` names it in messages).
void check_lab_curve(const LabCurve& curve);

}  // namespace ffp
