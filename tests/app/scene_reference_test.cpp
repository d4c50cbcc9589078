/// The scene reference (`ffp keys`) built in-process: every key the readers accept is listed
/// with a meaning, and the probe scenes reach every key the readers' sources name.
/// (docs/reference/scenes.md against the program's output: tests/cli/keys_test.cpp.)
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "drivers/app/job.hpp"
#include "drivers/app/key_reference.hpp"
#include "tests/app/shipped_scene.hpp"

namespace fs = std::filesystem;
using namespace ffp;

namespace {

const std::vector<KindReference>& reference() {
  static const std::vector<KindReference> all = scene_reference(test_support::kSceneDir);
  return all;
}

/// The key literals the readers' sources read: `reader.number("E_kPa", …)`, `.object("soil", …)`, ….
std::set<std::string> keys_named_in_readers() {
  const fs::path root(FFP_SOURCE_DIR);
  std::vector<fs::path> sources = {root / "drivers/scene/material_scene.cpp", root / "drivers/app/kinds.cpp"};
  for (const fs::directory_entry& f : fs::directory_iterator(root / "drivers/app"))
    if (f.path().filename().string().ends_with("_scene.cpp")) sources.push_back(f.path());
  static const std::regex read(
      "\\.(number|optional_number|integer|boolean|text|choice|numbers|optional_numbers|object|required_object|"
      "objects|raw|allow|file|existing_file)\\(\\s*\"([A-Za-z_0-9]+)\"\\s*[,)]");
  std::set<std::string> out;
  for (const fs::path& source : sources) {
    std::ifstream in(source);
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    const std::string code = text.str();
    for (auto it = std::sregex_iterator(code.begin(), code.end(), read); it != std::sregex_iterator(); ++it)
      out.insert((*it)[2].str());
  }
  return out;
}

std::string last_component(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

}  // namespace

TEST_CASE("every key a scene reader accepts is listed with its meaning and what it allows", "[app][scene][keys]") {
  REQUIRE(reference().size() == registered_kinds().size());
  for (const KindReference& kind : reference()) {
    INFO("kind " << kind.kind);
    CHECK(kind.keys.size() >= 4);  // kind, name, description and at least one of its own
    for (const ReferenceKey& key : kind.keys) {
      INFO("key " << key.path);
      CHECK_FALSE(key.entry.meaning.empty());
      CHECK_FALSE(key.entry.allowed.empty());
      CHECK_FALSE(key.entry.fallback.empty());
    }
  }
}

TEST_CASE("the probe scenes reach every key the readers' sources name", "[app][scene][keys]") {
  std::set<std::string> listed;
  for (const KindReference& kind : reference())
    for (const ReferenceKey& key : kind.keys) listed.insert(last_component(key.path));
  const std::set<std::string> named = keys_named_in_readers();
  CHECK(named.size() > 100);  // the scan found the readers' calls
  for (const std::string& key : named) {
    INFO("a reader reads '" << key
                            << "', which no kind's reference lists: add a probe that reaches it "
                               "(drivers/app/key_reference.cpp, branch_probes)");
    CHECK(listed.count(key) == 1);
  }
}

TEST_CASE("the keys of a branch appear in their kind's reference only", "[app][scene][keys]") {
  auto keys_of = [](std::string_view kind) {
    std::set<std::string> out;
    for (const KindReference& k : reference())
      if (k.kind == kind)
        for (const ReferenceKey& key : k.keys) out.insert(key.path);
    return out;
  };
  const std::set<std::string> ffp = keys_of("ffp"), cpt = keys_of("cpt"), integration = keys_of("integration_error");
  // A falling penetrometer has a mass and may be deformable; a pushed one has a push speed and a punch window.
  for (const char* key : {"ffp.mass_kg", "ffp.impact_velocity_m_s", "ffp.deformable.E_kPa", "solver.subcycle"}) {
    CHECK(ffp.count(key) == 1);
    CHECK(cpt.count(key) == 0);
  }
  for (const char* key : {"ffp.push_velocity_m_s", "end_depth_m", "plateau_settlement_ratio", "solver.local_damping"}) {
    CHECK(cpt.count(key) == 1);
    CHECK(ffp.count(key) == 0);
  }
  // The read_material branch the integration_error kind refuses (a constant dilatancy only).
  CHECK(integration.count("material.relative_density") == 0);
  CHECK(integration.count("material.psi_peak_deg") == 1);
}

TEST_CASE("defaults and bounds that depend on other keys are given in words", "[app][scene][keys]") {
  auto entry = [](std::string_view kind, const std::string& path) {
    for (const KindReference& k : reference())
      if (k.kind == kind)
        for (const ReferenceKey& key : k.keys)
          if (key.path == path) return key.entry;
    FAIL("no key " << path << " in kind " << kind);
    return KeyEntry{};
  };
  CHECK(entry("ffp", "mesh.fine_radius_m").fallback == "max(0.15, ffp.base_radius_m + 2 × min_cell_m)");
  CHECK(entry("ffp", "mesh.max_cell_m").allowed == "[min_cell_m, 10]");
  CHECK(entry("ffp", "mesh.max_cell_m").unit == "m");
  CHECK(entry("mpm", "bodies[i].material.psi_peak_deg").allowed == "[0, phi_peak_deg]");
  CHECK(entry("point", "material.phi_residual_deg").condition == "model = ssmc");
  // A value the read knows itself: the Range's interval, the fallback, the enum's names.
  CHECK(entry("ffp", "material.E_kPa").allowed == "(0, 1e9]");
  CHECK(entry("ffp", "gravity_m_s2").fallback == "9.81");
  CHECK(entry("ffp", "solver.transfer").fallback == "`usl`");
  CHECK(entry("mpm", "solver.transfer").fallback == "`musl`");
}

TEST_CASE("the reference's links to the manual land on anchors that exist", "[app][scene][keys]") {
  static const std::regex link("\\]\\(\\.\\./([a-z_]+\\.md)#([A-Za-z0-9_-]+)\\)");
  std::set<std::pair<std::string, std::string>> targets;
  for (const KindReference& kind : reference())
    for (const ReferenceKey& key : kind.keys)
      for (auto it = std::sregex_iterator(key.entry.meaning.begin(), key.entry.meaning.end(), link);
           it != std::sregex_iterator(); ++it)
        targets.insert({(*it)[1].str(), (*it)[2].str()});
  CHECK(targets.size() >= 10);
  for (const auto& [file, id] : targets) {
    INFO("docs/" << file << "#" << id);
    std::ifstream in(fs::path(FFP_SOURCE_DIR) / "docs" / file);
    REQUIRE(in);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str().find("<a id=\"" + id + "\">") != std::string::npos);
  }
}

TEST_CASE("a read logs its key with the Doc's words and its own facts, and a second read must agree",
          "[app][scene][keys]") {
  const json scene = {{"depth_m", 0.3}};
  json echo;
  KeyLog log;
  SceneReader reader(scene, "soil", echo, &log);
  const Doc depth = Doc("depth of the sand");
  CHECK(reader.number("depth_m", Range::positive(100.0, "m"), 0.4, depth) == 0.3);
  CHECK(reader.number("near_depth_m", Range::closed(0.0, 0.3, "m", "≤ depth_m"), 0.3,
                      Doc("depth of the near zone").by_default("depth_m").within("[0, depth_m]")) == 0.3);
  const KeyEntry& entry = log.entries.at("soil.depth_m");
  CHECK(entry.meaning == "depth of the sand");
  CHECK(entry.unit == "m");
  CHECK(entry.fallback == "0.4");
  CHECK(entry.allowed == "(0, 100]");
  CHECK(log.entries.at("soil.near_depth_m").fallback == "depth_m");
  CHECK(log.entries.at("soil.near_depth_m").allowed == "[0, depth_m]");
  CHECK(log.order == std::vector<std::string>{"soil.depth_m", "soil.near_depth_m"});
  // The same read again agrees; another meaning for the same key is a conflict.
  reader.number("depth_m", Range::positive(100.0, "m"), 0.4, depth);
  CHECK(log.conflicts.empty());
  reader.number("depth_m", Range::positive(100.0, "m"), 0.4, Doc("the chamber's depth"));
  CHECK(log.conflicts == std::vector<std::string>{"soil.depth_m"});
  // The echo is the scene as read, whatever the log says.
  CHECK(echo == json{{"depth_m", 0.3}, {"near_depth_m", 0.3}});
}

TEST_CASE("a number in the reference reads as a person writes it", "[app][scene][keys]") {
  CHECK(compact_number(1e9) == "1e9");
  CHECK(compact_number(30000) == "3e4");
  CHECK(compact_number(-1e7) == "-1e7");
  CHECK(compact_number(1000) == "1000");
  CHECK(compact_number(14.6e3 / 9.81) == "1488.28");
  CHECK(compact_number(0.04375) == "0.04375");
  CHECK(compact_number(1e-10) == "1e-10");
  CHECK(compact_number(2e-4) == "0.0002");
}
