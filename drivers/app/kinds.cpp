#include <algorithm>
#include <cctype>

#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"

namespace ffp {

const std::vector<KindEntry>& registered_kinds() {
  static const std::vector<KindEntry> kinds = {
      {"point", "single material point along a stress/strain path", &make_point_job},
      {"mpm", "axisymmetric MPM verification run (bodies, boundaries, gravity)", &make_mpm_job},
      {"integration_error", "error against run time of the constitutive integration", &make_integration_error_job},
      {"triaxial", "drained triaxial element test: q, ε_v and force–displacement (dissipated work)",
       &make_triaxial_job},
      {"calibration", "fit of the SSMC softening factor η to a lab triaxial curve (dissipated work)",
       &make_calibration_job},
      {"ffp", "free-fall penetrometer impact on sand: axisymmetric MPM, rigid or elastic body, contact", &make_ffp_job},
      {"cpt", "the FFP pushed at a constant velocity: quasi-static reaction profile F_0(z)", &make_cpt_job},
      {"record", "a measured FFP drop interpreted: penetration, velocity, q_dyn and q_sbc against depth",
       &make_record_job},
      {"inverse", "soil parameters of an ffp scene fitted to a record by Ceres over MPM runs", &make_inverse_job},
  };
  return kinds;
}

std::string kind_list(std::string_view open, std::string_view close) {
  std::string out;
  for (const auto& k : registered_kinds())
    out += (out.empty() ? "" : ", ") + std::string(open) + std::string(k.kind) + std::string(close);
  return out;
}

std::string read_scene_name(SceneReader& scene, std::string_view kind) {
  const std::string name =
      scene.text("name", kind,
                 Doc("names the output folder `results/<name>/`: 1–100 letters, digits, `_`, `-`, `.`, the first a "
                     "letter or digit"));
  const auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  };
  if (name.empty() || name.size() > 100 || !std::isalnum(static_cast<unsigned char>(name[0])) ||
      !std::all_of(name.begin(), name.end(), allowed))
    scene.fail("name", "'" + name + "' must be 1–100 letters, digits, '_', '-' or '.' (it names the output folder)");
  return name;
}

std::unique_ptr<Job> make_job(const json& scene, const std::filesystem::path& scene_dir, json& echo, KeyLog* log) {
  echo = json::object();
  SceneReader top(scene, "", echo, log);
  std::vector<std::string> names;
  for (const auto& k : registered_kinds()) names.emplace_back(k.kind);
  const json* kind_value = scene.contains("kind") ? &scene.at("kind") : nullptr;
  if (kind_value == nullptr) top.fail("kind", "is required (one of: " + kind_list("", "") + ")");
  const std::string kind = kind_value->is_string() ? kind_value->get<std::string>() : "";
  const auto entry = std::find_if(registered_kinds().begin(), registered_kinds().end(),
                                  [&](const KindEntry& k) { return k.kind == kind; });
  if (entry == registered_kinds().end()) {
    const std::string allowed = kind_list("", "");
    const std::string guess = kind.empty() ? "" : nearest(kind, names);
    top.fail("kind", (kind_value->is_string() ? "'" + kind + "' is not a kind this build runs"
                                              : std::string("must be a string")) +
                         ": must be one of: " + allowed + (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  top.allow("kind", Doc("what the scene runs: it decides which other keys the scene may hold")
                        .by_default("required")
                        .within(kind_list("`", "`")));
  echo["kind"] = kind;
  read_scene_name(top, kind);  // refused here, not only by `ffp run`: check and an inverse fit's check agree
  top.allow("description", Doc("free text, copied to summary.json unchanged").within("text"));
  if (scene.contains("description")) echo["description"] = scene.at("description");
  return entry->make(top, scene_dir);
}

}  // namespace ffp
