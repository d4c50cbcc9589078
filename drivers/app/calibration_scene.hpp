#pragma once
/// Reading a `calibration` scene: the SSMC softening factor η fitted to a lab
/// triaxial curve so that the numerical triaxial dissipates the lab's work
/// (paper section 4.2, Fig. 3; calibration/softening_calibration.hpp).
/// Reading only; calibration_job runs it.
///
/// Its keys, each declared where calibration_scene.cpp reads it: `ffp keys calibration`
/// (docs/reference/scenes.md).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "calibration/lab_curve.hpp"
#include "calibration/mpm_triaxial_specimen.hpp"
#include "calibration/softening_calibration.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "mpm/model_size.hpp"

namespace ffp {

/// Where the fit starts (`fit_start`).
enum class FitStart { material_eta, scan };
using FitStartName = std::pair<FitStart, std::string_view>;
inline constexpr auto kFitStartNames =
    std::to_array<FitStartName>({{FitStart::material_eta, "material_eta"}, {FitStart::scan, "scan"}});
std::string to_string(FitStart start);

/// The numerical triaxial the calibration fits with (`specimen.type`).
enum class SpecimenType { element, mpm };
using SpecimenTypeName = std::pair<SpecimenType, std::string_view>;
inline constexpr auto kSpecimenTypeNames =
    std::to_array<SpecimenTypeName>({{SpecimenType::element, "element"}, {SpecimenType::mpm, "mpm"}});
std::string to_string(SpecimenType type);

struct CalibrationScene {
  std::filesystem::path lab_file;  ///< resolved against the scene's folder
  LabCurve lab;
  StrainSofteningParameters material;  ///< φ'_p replaced by the lab peak's with fit_peak_friction
  bool fitted_peak_friction = false;
  double eta_start = 8.0;  ///< material.eta (where the fit starts with fit_start = material_eta)
  FitStart fit_start = FitStart::material_eta;
  SpecimenType specimen = SpecimenType::element;
  TriaxialTestConfig test;  ///< the element test (σ3 and the specimen's size serve both types)
  MpmTriaxialConfig mpm;    ///< the MPM specimen (type mpm)
  CalibrationSettings settings;
  bool compare_modes = true;
  std::vector<double> compare_eta;
};

/// Reads every key after kind/name and finish()es the scene. SceneError on bad input.
CalibrationScene read_calibration_scene(SceneReader& scene, const std::filesystem::path& scene_dir);

/// The MPM specimen's size before it is built (for the memory check and `ffp check`).
mpm::ModelSize specimen_size(const MpmTriaxialConfig& m);

/// `v` with `digits` significant digits (%g), as messages and figure labels print it.
std::string format_significant(double v, int digits = 4);

}  // namespace ffp
