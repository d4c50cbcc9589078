#pragma once
/// The scene of an inverse fit (`inverse` kind): an `ffp` scene whose chosen
/// parameters are fitted, within bounds, so that its deceleration against
/// depth matches a record, optionally with scalar targets. Reading only;
/// inverse_job runs it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "calibration/bounded_least_squares.hpp"
#include "drivers/app/record_scene.hpp"
#include "drivers/scene/scene_reader.hpp"

namespace ffp {

/// The scene keys an inverse fit may vary: continuous soil and contact parameters.
inline constexpr const char* kInverseKeys[] = {"material.phi_peak_deg", "material.E_kPa", "material.eta",
                                               "contact.delta_deg", "material.rate_dependence.alpha_phi"};

struct ScalarTarget {
  double value = 0.0;
  double weight = 1.0;
  double scale = 1.0;  ///< the residual is weight·(model − value)/scale
};

struct InverseScene {
  std::filesystem::path forward_scene;         ///< an `ffp` scene, resolved against this scene's folder
  std::vector<std::string> forward_overrides;  ///< key=value applied to every model run
  std::vector<FitParameter> parameters;        ///< name = the scene key
  std::optional<RecordScene> record;
  /// The record's deceleration against depth at `profile_points` depths over
  /// its loading branch; residual weight·(d_model − d_record)/scale_g/√points.
  int profile_points = 40;
  double profile_weight = 1.0, profile_scale_g = 1.0;
  bool profile = false;
  std::optional<ScalarTarget> peak_deceleration_g;
  std::optional<ScalarTarget> final_penetration_m;
  BoundedFitSettings fit;
};

/// Reads forward_scene, forward_overrides, parameters [{key, initial, lower,
/// upper, step}], record {…the record kind's keys}, profile {points, weight,
/// scale_g}, peak_deceleration {target_g, weight, scale_g}, final_penetration
/// {target_m, weight, scale_m}, max_iterations, function_tolerance. The forward
/// scene is validated at the initial values and at every bound. Does not finish().
InverseScene read_inverse_scene(SceneReader& scene, const std::filesystem::path& scene_dir);

/// "key=value" with every digit of the value, so that a point is one run's cache key.
std::string assignment(const std::string& key, double value);

/// The overrides of one model run at parameter values `x` (one per parameter, in order; none to
/// check the forward overrides alone): forward_overrides, no particle fields, each parameter.
/// The fit's runs get exactly these, and read_inverse_scene checks the forward scene with them,
/// so that `ffp check` refuses what the runs would.
std::vector<std::string> model_run_overrides(const InverseScene& scene, const std::vector<double>& x);

}  // namespace ffp
