#include "drivers/app/inverse_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "drivers/app/job.hpp"

namespace ffp {

namespace fs = std::filesystem;

std::string assignment(const std::string& key, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return key + "=" + buffer;
}

std::vector<std::string> model_run_overrides(const InverseScene& scene, const std::vector<double>& x) {
  std::vector<std::string> overrides = scene.forward_overrides;
  overrides.push_back("output.field_times_s=[]");  // no particle fields: only the deceleration is compared
  for (std::size_t j = 0; j < x.size(); ++j) overrides.push_back(assignment(scene.parameters[j].name, x[j]));
  return overrides;
}

namespace {

/// The forward scene must be an ffp scene that takes `overrides`; its own error otherwise.
void check_forward(const json& forward, const fs::path& forward_dir, const std::vector<std::string>& overrides,
                   const std::string& what) {
  json scene = forward;
  json echo;
  try {
    for (const std::string& a : overrides) apply_override(scene, a);
    (void)make_job(scene, forward_dir, echo);
  } catch (const SceneError& e) {
    throw SceneError(what + ": the forward scene refuses it: " + e.what());
  }
}

/// A scalar target for the run's `figure` (a summary.json key).
std::optional<ScalarTarget> read_target(SceneReader& scene, const char* key, const std::string& figure,
                                        const char* value_key, const Range& range, const char* scale_key,
                                        double default_scale) {
  if (!scene.has(key)) return std::nullopt;
  SceneReader t = scene.object(
      key, Doc("a target for the run's " + figure + ": the residual weight·(" + figure + " − target)/scale")
               .by_default("none")
               .within("object"));
  ScalarTarget target;
  target.value = t.number(value_key, range, Doc("the target " + figure));
  target.weight = t.number("weight", Range::non_negative(1e6), 1.0, Doc("the residual's weight"));
  target.scale = t.number(scale_key, Range::positive(1e6), default_scale, Doc("the residual's scale"));
  t.finish(std::string(key) + " (" + value_key + ", weight, " + scale_key + ")");
  return target;
}

}  // namespace

InverseScene read_inverse_scene(SceneReader& scene, const fs::path& scene_dir) {
  InverseScene out;
  out.forward_scene = scene.existing_file("forward_scene", scene_dir, kSceneFileLimit,
                                          Doc("the ffp scene whose parameters are fitted"));
  json forward_json;
  try {
    forward_json = load_scene_file(out.forward_scene.string());
  } catch (const SceneError& e) {
    scene.fail("forward_scene", e.what());
  }
  if (forward_json.value("kind", "") != "ffp") scene.fail("forward_scene", "must be a scene of kind ffp");
  if (const std::optional<json> list =
          scene.raw("forward_overrides", Doc("overrides applied to every model run, as --set takes them (e.g. "
                                             "mesh.min_cell_m=0.02)")
                                             .by_default("[]")
                                             .within("a list of \"key=value\" strings"))) {
    if (!list->is_array()) scene.fail("forward_overrides", "must be a list of \"key=value\" strings");
    for (const json& item : *list) {
      if (!item.is_string() || item.get<std::string>().find('=') == std::string::npos)
        scene.fail("forward_overrides", "must be a list of \"key=value\" strings");
      out.forward_overrides.push_back(item.get<std::string>());
    }
  }
  const fs::path forward_dir = out.forward_scene.parent_path();
  check_forward(forward_json, forward_dir, model_run_overrides(out, {}), "forward_overrides");

  std::string fittable;
  for (const char* key : kInverseKeys) fittable += (fittable.empty() ? "`" : ", `") + std::string(key) + "`";
  std::vector<SceneReader> parameters = scene.objects(
      "parameters", 1, 6,
      Doc("the fitted parameters; the forward scene is checked at their initial values and at their bounds "
          "([theory](../theory.md#inverse))"));
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    SceneReader& p = parameters[k];
    FitParameter q;
    q.name = p.text("key", Doc("the forward scene's key").within(fittable));
    const auto known = std::find(std::begin(kInverseKeys), std::end(kInverseKeys), q.name);
    if (known == std::end(kInverseKeys)) {
      std::string allowed;
      for (const char* key : kInverseKeys) allowed += (allowed.empty() ? "" : ", ") + std::string(key);
      p.fail("key", "'" + q.name + "' cannot be fitted: must be one of " + allowed);
    }
    for (std::size_t j = 0; j < k; ++j)
      if (out.parameters[j].name == q.name) p.fail("key", "'" + q.name + "' is fitted twice");
    q.lower = p.number("lower", Range{}, Doc("its lower bound"));
    q.upper = p.number("upper", Range::open(q.lower, std::numeric_limits<double>::max(), "", "> lower"),
                       Doc("its upper bound").within("> lower"));
    q.initial = p.number("initial", Range::closed(q.lower, q.upper, "", "within [lower, upper]"),
                         Doc("where the fit starts").within("[lower, upper]"));
    // 2 % of the range: beyond the cell-crossing ripple of the MPM answer, small against the bounds.
    q.step =
        p.number("step", Range::open(0.0, q.upper - q.lower, "", "> 0 and < upper − lower"), 0.02 * (q.upper - q.lower),
                 Doc("the finite-difference step (2 % of the range: beyond the cell-crossing ripple of the MPM "
                     "answer)")
                     .by_default("0.02 × (upper − lower)")
                     .within("(0, upper − lower)"));
    p.finish("parameters[] (key, initial, lower, upper, step)");
    out.parameters.push_back(q);
  }
  // The forward scene at every parameter's initial value, then at every lower and every upper
  // bound at once: three model builds whatever the number of parameters. A refusal names the key,
  // and so the parameter whose value it was.
  const std::string refuses = ": the forward scene refuses it: ";
  for (const char* what : {"initial", "lower", "upper"}) {
    auto value_of = [&](const FitParameter& q) {
      return what[0] == 'i' ? q.initial : what[0] == 'l' ? q.lower : q.upper;
    };
    std::vector<double> values;
    for (const FitParameter& q : out.parameters) values.push_back(value_of(q));
    try {
      check_forward(forward_json, forward_dir, model_run_overrides(out, values), what);
    } catch (const SceneError& e) {
      const std::string message = e.what();
      const std::string cause = message.substr(message.find(refuses) + refuses.size());
      for (std::size_t k = 0; k < out.parameters.size(); ++k)
        if (cause.find(out.parameters[k].name) != std::string::npos) {
          char value[32];
          std::snprintf(value, sizeof value, "%g", value_of(out.parameters[k]));
          throw SceneError(parameters[k].path() + "." + what + " = " + value + refuses + cause);
        }
      throw SceneError(std::string("parameters (their ") + what + " values together)" + refuses + cause);
    }
  }

  if (scene.has("record")) {
    SceneReader r =
        scene.object("record", Doc("the record to match: the record kind's keys").by_default("none").within("object"));
    out.record = read_record_scene(r, scene_dir);
    r.finish("record (the keys of a record scene)");
  }
  if (scene.has("profile") && !out.record) scene.fail("profile", "matches a record: give record {record_csv, …}");
  if (out.record) {
    out.profile = true;
    SceneReader pr = scene.object(
        "profile", Doc("the deceleration–depth residuals weight·(d_model − d_record)/scale_g/√points over the "
                       "record's loading branch (a weight of 0: none)")
                       .only_with("record"));
    out.profile_points =
        pr.integer("points", 3, 10000, 40, Doc("depths of the residuals, spread over the loading branch"));
    out.profile_weight = pr.number("weight", Range::non_negative(1e6), 1.0, Doc("the residuals' weight"));
    out.profile_scale_g = pr.number("scale_g", Range::positive(1e6, "g"), 1.0, Doc("the residuals' scale"));
    pr.finish("profile (points, weight, scale_g)");
    if (out.profile_weight == 0.0) out.profile = false;
  }
  out.peak_deceleration_g = read_target(scene, "peak_deceleration", "peak_deceleration_g", "target_g",
                                        Range::open(-1.0, 1e5, "g"), "scale_g", 1.0);
  out.final_penetration_m = read_target(scene, "final_penetration", "final_penetration_m", "target_m",
                                        Range::positive(100.0, "m"), "scale_m", 0.01);
  if (!out.profile && !out.peak_deceleration_g && !out.final_penetration_m)
    scene.fail(
        "record",
        "nothing to fit: give a record (its profile), peak_deceleration {target_g} or final_penetration {target_m}");

  out.fit.max_iterations = scene.integer("max_iterations", 1, 200, 15, Doc("Ceres iterations, at most"));
  out.fit.function_tolerance = scene.number("function_tolerance", Range::open(0.0, 1.0), 1e-3,
                                            Doc("Ceres stops when the cost changes by less (relative)"));
  out.fit.parameter_tolerance = scene.number("parameter_tolerance", Range::open(0.0, 1.0), 1e-3,
                                             Doc("Ceres stops when the parameters change by less (relative)"));
  return out;
}

}  // namespace ffp
