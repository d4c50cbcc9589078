/// README's key tables against what the readers accept, kind by kind: every key
/// a table lists is one the kind's reader knows, and every key a reader knows
/// is in a table (or inside an object a table lists whole, such as `material`,
/// which has a table of its own).
///
/// README layout read here: "### `kind`: …" (or "### `ffp` and `cpt`: …")
/// opens a kind's section; in it, every table whose first column is `key`
/// lists keys, spelled as JSON paths in backticks in that column (several per
/// cell allowed: "`eta_min`, `eta_max`"; a bare name after a dotted one shares
/// its parent: "`surface_pressures[i].z_min_m`, `z_max_m`"). The point path
/// table (first column `type`) lists `path.type` and, in its last column, the
/// keys of each path under `path.`. Array elements are written `[i]`. The
/// keys common to all kinds are the table under "Keys common to all kinds".
///
/// What a reader knows is collected through a KeyLog while make_job reads the
/// shipped scenes of the kind and a few variants that reach its other branches.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "drivers/app/job.hpp"
#include "tests/app/shipped_scene.hpp"
#include "tests/support/scratch.hpp"

namespace fs = std::filesystem;
using namespace ffp;

namespace {

using KeySet = std::set<std::string>;

std::vector<std::string> backticked(const std::string& text) {
  std::vector<std::string> out;
  static const std::regex tick("`([^`]+)`");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), tick); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1].str());
  return out;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  const auto e = s.find_last_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

/// README's keys by kind ("" holds the keys common to all kinds).
std::map<std::string, KeySet> readme_keys() {
  std::ifstream in(fs::path(FFP_SOURCE_DIR) / "README.md");
  REQUIRE(in);
  std::map<std::string, KeySet> out;
  std::vector<std::string> kinds;  // of the current section
  bool common = false;
  enum class Table { none, keys, path_types, other } table = Table::none;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0 || line.rfind("### ", 0) == 0) {
      kinds.clear();
      common = false;
      if (line.rfind("### `", 0) == 0) {
        const std::string title =
            line.substr(4, line.find(':') == std::string::npos ? std::string::npos : line.find(':') - 4);
        kinds = backticked(title);
      }
      continue;
    }
    if (line.find("**Keys common to all kinds**") != std::string::npos) common = true;
    if (line.rfind("|", 0) != 0) {
      table = Table::none;
      continue;
    }
    const std::vector<std::string> row = cells(line);
    if (table == Table::none) {
      const std::string first = trim(row.front());
      table = first == "key"                                                  ? Table::keys
              : first == "type" && kinds == std::vector<std::string>{"point"} ? Table::path_types
                                                                              : Table::other;
      continue;
    }
    if (line.rfind("|---", 0) == 0 || line.rfind("|:-", 0) == 0 || table == Table::other) continue;
    KeySet keys;
    if (table == Table::keys) {
      std::string parent;
      for (const std::string& key : backticked(row.front())) {
        const bool nested = key.find_first_of(".[") != std::string::npos;
        if (nested) parent = key.substr(0, key.find_last_of('.') + 1);
        keys.insert(nested ? key : parent + key);
      }
    } else {  // the point path types: `path.type`, and each path's keys
      keys.insert("path.type");
      for (const std::string& key : backticked(row.back()))
        if (std::regex_match(key, std::regex("[A-Za-z_0-9]+"))) keys.insert("path." + key);
    }
    // In a table two kinds share, a row whose meaning opens "`cpt` only", "`ffp` rigid only" or
    // "`cpt` with …" belongs to that kind alone.
    std::vector<std::string> owners = common ? std::vector<std::string>{""} : kinds;
    std::smatch only;
    static const std::regex owner("^ *`([a-z_]+)`( rigid)? (only|with)\\b.*");
    if (row.size() > 1 && std::regex_match(row[1], only, owner)) owners = {only[1].str()};
    for (const std::string& kind : owners) out[kind].insert(keys.begin(), keys.end());
  }
  return out;
}

/// "bodies[0].material" → "bodies[i].material".
std::string generic(const std::string& path) { return std::regex_replace(path, std::regex("\\[[0-9]+\\]"), "[i]"); }

/// The keys make_job's readers know over these scenes (name, overrides).
KeySet reader_keys(const std::vector<std::pair<std::string, std::vector<std::string>>>& scenes) {
  KeySet out;
  for (const auto& [name, overrides] : scenes) {
    CAPTURE(name, overrides);
    json scene = load_scene_file((test_support::kSceneDir / (name + ".json")).string());
    for (const std::string& o : overrides) apply_override(scene, o);
    json echo;
    KeyLog log;
    REQUIRE_NOTHROW(make_job(scene, test_support::kSceneDir, echo, &log));
    for (const std::string& p : log.paths) out.insert(generic(p));
  }
  return out;
}

bool below(const std::string& key, const std::string& parent) {
  return key.size() > parent.size() && key.rfind(parent, 0) == 0 &&
         (key[parent.size()] == '.' || key[parent.size()] == '[');
}

/// A reader's key is documented when README lists it, when it is an object whose keys README lists,
/// or when it lies inside an object README lists whole (none of whose keys has a row of its own).
bool documented(const std::string& key, const KeySet& readme) {
  if (readme.count(key)) return true;
  for (const std::string& r : readme)
    if (below(r, key)) return true;
  std::string whole;  // the innermost README key containing `key`
  for (const std::string& r : readme)
    if (below(key, r) && r.size() > whole.size()) whole = r;
  if (whole.empty()) return false;
  for (const std::string& r : readme)
    if (below(r, whole)) return false;
  return true;
}

void check_kind(const std::string& kind, const KeySet& readers, const std::map<std::string, KeySet>& readme) {
  INFO("kind " << kind);
  REQUIRE(readme.count(kind));
  KeySet listed = readme.at(kind);
  listed.insert(readme.at("").begin(), readme.at("").end());
  for (const std::string& key : listed) {
    INFO("README lists " << kind << " key " << key);
    bool known = readers.count(key) > 0;
    for (const std::string& k : readers) known = known || below(k, key);
    CHECK(known);
  }
  for (const std::string& key : readers) {
    INFO("the " << kind << " reader knows " << key);
    CHECK(documented(key, listed));
  }
}

}  // namespace

TEST_CASE("README's key tables list exactly the keys the readers accept", "[app][scene][readme]") {
  const std::map<std::string, KeySet> readme = readme_keys();
  test_support::Scratch dir("ffp-readme-keys");
  const fs::path table = dir.write("path.csv",
                                   "time_s,stress_11_kPa,strain_22,stress_33_kPa,strain_12,strain_23,strain_13\n"
                                   "0,1.72,0,1.72,0,0,0\n1,1.72,0.01,1.72,0,0,0\n");
  const std::string segments =
      R"(path={"type": "general", "segments": [{"control": ["stress", "strain", "stress", "strain", "strain", "strain"], )"
      R"("target": [1.72, 0.01, 1.72, 0, 0, 0]}]})";
  SECTION("point") {
    check_kind(
        "point",
        reader_keys(
            {{"point_isotropic", {}},
             {"point_oedometric", {}},
             {"point_simple_shear", {}},
             {"point_triaxial_mc", {"initial_pressure_kPa=null", "initial_stress_kPa=[1.72,1.72,1.72,0,0,0]"}},
             {"point_triaxial_extension_mc", {}},
             {"point_triaxial_ssmc", {"initial_state={\"plastic_deviatoric_strain\": 0.01}"}},
             {"point_triaxial_ssmc_bolton", {}},
             {"point_triaxial_ssmc_rate", {"initial_state={\"strain_rate_per_s\": 0.001}"}},
             {"point_triaxial_mc", {segments, "initial_pressure_kPa=1.72"}},
             {"point_triaxial_mc",
              {"path={\"type\": \"general\", \"table_csv\": \"" + table.string() + "\", \"increments_per_row\": 10}",
               "initial_pressure_kPa=1.72"}}}),
        readme);
  }
  SECTION("triaxial") {
    check_kind("triaxial", reader_keys({{"triaxial_mc", {}}, {"triaxial_ssmc_paper", {}}}), readme);
  }
  SECTION("calibration") {
    check_kind("calibration",
               reader_keys({{"calibration_dr00", {}},
                            {"calibration_dr15", {}},
                            {"calibration_dr15_mpm_05cm", {}},
                            {"calibration_dr15_mpm_1cm", {}},
                            {"calibration_dr15_mpm_2cm", {}}}),
               readme);
  }
  SECTION("integration_error") { check_kind("integration_error", reader_keys({{"integration_error", {}}}), readme); }
  SECTION("mpm") {
    check_kind(
        "mpm",
        reader_keys(
            {{"mpm_wave_column", {}},
             {"mpm_geostatic_column", {}},
             {"mpm_colliding_spheres", {}},
             {"mpm_wave_column",
              {"mesh={\"r_nodes_m\": [0.01, 0.02, 0.03], \"z_nodes_m\": [0, 0.25, 0.5, 0.75, 1]}",
               "boundaries.axis=null", "boundaries.inner=free", "output.probes=[]", "bodies.0.region.r_min_m=0.01",
               "bodies.0.region.r_max_m=0.03", "solver.dt_s=1e-5", "output.field_interval_s=null",
               "output.field_times_s=[0.01]",
               "surface_pressures=[{\"side\": \"outer\", \"pressure_kPa\": 1, \"z_min_m\": 0, \"z_max_m\": 0.5}]"}}}),
        readme);
  }
  SECTION("ffp") {
    check_kind("ffp",
               reader_keys({{"ffp_reference", {}},
                            {"ffp_rough", {}},
                            {"ffp_elastic", {}},
                            {"ffp_steel", {}},
                            {"ffp_dilatancy", {}},
                            {"ffp_peak_friction", {}},
                            {"ffp_calibrated", {}},
                            {"ffp_reference",
                             {"ffp.tip=flat", "ffp.cone_apex_angle_deg=null", "ffp.external_force_N=10",
                              "soil.particles_per_cell_near=null", "soil.near_spacing_m=0.005"}}}),
               readme);
  }
  SECTION("cpt") {
    check_kind("cpt",
               reader_keys({{"cpt_reference", {}},
                            {"cpt_slow", {}},
                            {"punch_smooth", {}},
                            {"punch_rough", {}},
                            {"cpt_reference",
                             {"end_depth_m=null", "end_time_s=1", "soil.particles_per_cell_near=null",
                              "soil.near_spacing_m=0.005"}}}),
               readme);
  }
  SECTION("record") {
    check_kind("record",
               reader_keys({{"record_reference", {}},
                            {"record_reference",
                             {"medium=water", "ffp.volume_m3=0.003", "impact_time_s=null", "sensor_range_g=100"}},
                            {"record_reference", {"sensor_range_m_s2=1000", "drag_coefficient=0.5"}}}),
               readme);
  }
  SECTION("inverse") {
    check_kind("inverse",
               reader_keys({{"inverse_reference", {}},
                            {"inverse_experiment", {}},
                            {"inverse_reference",
                             {"peak_deceleration={\"target_g\": 19.4}", "final_penetration={\"target_m\": 0.15}",
                              "function_tolerance=1e-3", "parameter_tolerance=1e-3"}}}),
               readme);
  }
}
