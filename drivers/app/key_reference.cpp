#include "drivers/app/key_reference.hpp"

#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include "drivers/app/job.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

// Material variants for kinds whose shipped scenes hold no such material: an ssmc law's
// rate dependence, and its Bolton dilatancy in place of a constant ψ_p.
const std::string kRateDependence = R"(rate_dependence={"alpha_phi": 0.1, "reference_strain_rate_per_s": 0.01})";
// A micropolar material, for the MPM kinds whose shipped scenes hold none.
const std::string kMicropolar = R"(micropolar={"length_m": 0.0003})";

std::vector<std::string> under(const std::string& prefix, const std::vector<std::string>& overrides) {
  std::vector<std::string> out;
  for (const std::string& o : overrides) out.push_back(prefix + o);
  return out;
}

/// An ssmc `material` (at `prefix`) made rate dependent, and one with Bolton's dilatancy.
std::vector<Probe> material_probes(const std::string& scene, const std::string& prefix) {
  return {{scene, under(prefix, {kRateDependence})},
          {scene, under(prefix, {"psi_peak_deg=null", "psi_residual_deg=null", "relative_density=0.5"})}};
}

std::vector<Probe> joined(std::vector<Probe> a, const std::vector<Probe>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// "bodies[0].material" → "bodies[i].material".
std::string generic(const std::string& path) {
  static const std::regex index("\\[[0-9]+\\]");
  return std::regex_replace(path, index, "[i]");
}

std::string parent_of(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

std::string describe(const Probe& probe) {
  std::string out = probe.scene + ".json";
  for (const std::string& o : probe.overrides) out += " --set " + o;
  return out;
}

/// The keys one probe's readers know, at their generic paths, in reading order.
struct ProbeLog {
  std::vector<ReferenceKey> keys;
  std::set<std::string> paths;
};

ProbeLog run_probe(const Probe& probe, const fs::path& scenes_dir) {
  KeyLog log;
  try {
    json scene = load_scene_file((scenes_dir / (probe.scene + ".json")).string());
    for (const std::string& o : probe.overrides) apply_override(scene, o);
    json echo;
    (void)make_job(scene, scenes_dir, echo, &log);
  } catch (const std::exception& e) {
    throw ReferenceError("the probe " + describe(probe) + " is refused: " + e.what());
  }
  for (const std::string& path : log.conflicts)
    throw ReferenceError("the probe " + describe(probe) + " reads " + path + " twice with different Docs");
  ProbeLog out;
  for (const std::string& path : log.order) {
    const std::string key = generic(path);
    if (out.paths.insert(key).second) out.keys.push_back({key, log.entries.at(path)});
  }
  return out;
}

/// The keys of all probes: each listed once, after the key it follows in the probe that first reads it.
class Merge {
 public:
  void add(const ProbeLog& probe, const std::string& name) {
    std::size_t at = 0;  // where the next new key of this probe goes
    for (const ReferenceKey& key : probe.keys) {
      const auto known = std::find_if(keys_.begin(), keys_.end(), [&](const auto& k) { return k.path == key.path; });
      if (known == keys_.end()) {
        keys_.insert(keys_.begin() + static_cast<long>(at), key);
        first_[key.path] = name;
        ++at;
      } else {
        if (!(known->entry == key.entry))
          throw ReferenceError(key.path + ": the probes " + first_[key.path] + " and " + name +
                               " read it with different Docs (say in words what depends on other keys)");
        at = static_cast<std::size_t>(known - keys_.begin()) + 1;
      }
    }
  }
  const std::vector<ReferenceKey>& keys() const { return keys_; }

 private:
  std::vector<ReferenceKey> keys_;
  std::map<std::string, std::string> first_;
};

/// A key read as required and unconditionally must be read wherever its object is: a key read
/// only when present is optional, and its Doc must say what its absence means (or its branch).
void check_required(const std::vector<ReferenceKey>& keys, const std::vector<std::pair<std::string, ProbeLog>>& logs) {
  for (const ReferenceKey& key : keys) {
    if (key.entry.fallback != "required" || !key.entry.condition.empty()) continue;
    const std::string parent = parent_of(key.path);
    for (const auto& [name, log] : logs) {
      if (log.paths.count(key.path)) continue;
      const bool reached = parent.empty() || std::any_of(log.paths.begin(), log.paths.end(), [&](const std::string& p) {
                             return p.rfind(parent + ".", 0) == 0;
                           });
      if (reached)
        throw ReferenceError(key.path + " is listed as required but the probe " + name +
                             " runs without reading it: say what its absence means (Doc::by_default) or when it "
                             "applies (Doc::only_with)");
    }
  }
}

KindReference reference_of(const KindEntry& kind, const fs::path& scenes_dir) {
  Merge merge;
  std::vector<std::pair<std::string, ProbeLog>> logs;
  for (const Probe& probe : probes_of(kind.kind, scenes_dir)) {
    logs.emplace_back(describe(probe), run_probe(probe, scenes_dir));
    merge.add(logs.back().second, logs.back().first);
  }
  check_required(merge.keys(), logs);
  return {std::string(kind.kind), std::string(kind.description), merge.keys()};
}

}  // namespace

std::vector<Probe> branch_probes(std::string_view kind) {
  if (kind == "point") {
    const std::string segments =
        R"(path={"type": "general", "segments": [{"control": ["stress", "strain", "stress", "strain", "strain", )"
        R"("strain"], "target": [1.72, 0.01, 1.72, 0, 0, 0]}]})";
    return {{"point_triaxial_mc", {"initial_pressure_kPa=null", "initial_stress_kPa=[1.72,1.72,1.72,0,0,0]"}},
            {"point_triaxial_ssmc", {R"(initial_state={"plastic_deviatoric_strain": 0.01})"}},
            {"point_triaxial_ssmc_rate", {R"(initial_state={"strain_rate_per_s": 0.001})"}},
            {"point_triaxial_mc", {segments, "initial_pressure_kPa=1.72"}},
            {"point_triaxial_mc",
             {R"(path={"type": "general", "table_csv": "point_path_table.csv", "increments_per_row": 10})",
              "initial_pressure_kPa=1.72"}}};
  }
  if (kind == "triaxial") return material_probes("triaxial_ssmc_paper", "material.");
  if (kind == "calibration") return material_probes("calibration_dr15", "material.");
  if (kind == "integration_error") return {{"integration_error", {"material." + kRateDependence}}};
  if (kind == "mpm") {
    const std::vector<std::string> ssmc = {"bodies.0.material.model=ssmc", "bodies.0.material.phi_residual_deg=32",
                                           "bodies.0.material.eta=8"};
    std::vector<Probe> probes = {
        {"mpm_wave_column",
         {R"(mesh={"r_nodes_m": [0.01, 0.02, 0.03], "z_nodes_m": [0, 0.25, 0.5, 0.75, 1]})", "boundaries.axis=null",
          "boundaries.inner=free", "output.probes=[]", "bodies.0.region.r_min_m=0.01", "bodies.0.region.r_max_m=0.03",
          "solver.dt_s=1e-5", "output.field_interval_s=null", "output.field_times_s=[0.01]",
          R"(surface_pressures=[{"side": "outer", "pressure_kPa": 1, "z_min_m": 0, "z_max_m": 0.5}])"}}};
    // A saturated body off the axis: the inner side's drainage, and Kozeny–Carman.
    probes.push_back(
        {"mpm_terzaghi_column",
         {"mesh.r_min_m=0.05", "mesh.r_max_m=0.15", "bodies.0.region.r_min_m=0.05", "bodies.0.region.r_max_m=0.15",
          "boundaries.axis=null", "boundaries.inner=roller", "boundaries.drainage.inner=drained",
          "bodies.0.permeability_law=kozeny_carman", "output.probes=[]"}});
    for (Probe p : material_probes("mpm_geostatic_column", "bodies.0.material.")) {
      p.overrides.insert(p.overrides.begin(), ssmc.begin(), ssmc.end());
      probes.push_back(p);
    }
    probes.push_back({"mpm_geostatic_column", {"bodies.0.material." + kMicropolar}});
    return probes;
  }
  if (kind == "ffp")
    return joined({{"ffp_reference",
                    {"ffp.tip=flat", "ffp.cone_apex_angle_deg=null", "ffp.external_force_N=10",
                     "soil.particles_per_cell_near=null", "soil.near_spacing_m=0.005", "output.localisation=true"}}},
                  material_probes("ffp_calibrated", "material."));
  if (kind == "cpt")
    return joined(
        {{"cpt_reference",
          {"end_depth_m=null", "end_time_s=1", "soil.particles_per_cell_near=null", "soil.near_spacing_m=0.005",
           "output.localisation=true"}}},
        joined(material_probes("cpt_reference", "material."), {{"cpt_reference", {"material." + kMicropolar}}}));
  if (kind == "record")
    return {{"record_reference",
             {"medium=water", "ffp.volume_m3=0.003", "impact_time_s=null", "sensor_range_g=100", "rate_laws=null"}},
            {"record_reference",
             {"sensor_range_m_s2=1000", "drag_coefficient=0.5", "ffp.tip=flat", "ffp.cone_apex_angle_deg=null"}}};
  if (kind == "inverse") {
    // Its record holds a record scene's keys: the record kind's branches again, under `record`.
    std::vector<Probe> probes = {
        {"inverse_reference",
         {R"(peak_deceleration={"target_g": 19.4})", R"(final_penetration={"target_m": 0.15})",
          "function_tolerance=1e-3", "parameter_tolerance=1e-3"}},
        {"inverse_reference",
         {R"(record.rate_laws={"reference_velocity_m_s": 0.02, "q_sbc_area": "mantle", "log": {"K": 0.1}, )"
          R"("brilli": {"K": 0.31}, "asinh": {"K": 0.1}})"}}};
    probes.push_back({"inverse_reference", under("record.", {"medium=water", "ffp.volume_m3=0.003",
                                                             "impact_time_s=null", "sensor_range_g=100"})});
    probes.push_back({"inverse_reference", under("record.", {"sensor_range_m_s2=1000", "drag_coefficient=0.5",
                                                             "ffp.tip=flat", "ffp.cone_apex_angle_deg=null"})});
    return probes;
  }
  return {};
}

std::vector<Probe> probes_of(std::string_view kind, const fs::path& scenes_dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const fs::directory_entry& f : fs::directory_iterator(scenes_dir, error)) {
    if (f.path().extension() != ".json") continue;
    const json scene = load_scene_file(f.path().string());
    if (scene.value("kind", "") == kind) names.push_back(f.path().stem().string());
  }
  if (error) throw ReferenceError(scenes_dir.string() + ": cannot list the shipped scenes (" + error.message() + ")");
  std::sort(names.begin(), names.end());
  std::vector<Probe> out;
  for (const std::string& n : names) out.push_back({n, {}});
  return joined(out, branch_probes(kind));
}

std::vector<KindReference> scene_reference(const fs::path& scenes_dir, std::string_view kind) {
  std::vector<KindReference> out;
  for (const KindEntry& k : registered_kinds())
    if (kind.empty() || k.kind == kind) out.push_back(reference_of(k, scenes_dir));
  return out;
}

}  // namespace ffp
