/// Bad keys of a saturated sand under the penetrometer (data/scenes/ffp_saturated.json broken one
/// key at a time): one line naming the key and what is allowed, exit code 2, nothing written.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <functional>

#include "cli_harness.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;

namespace {

json saturated_scene() {
  std::ifstream in(std::string(FFP_SOURCE_DIR) + "/data/scenes/ffp_saturated.json");
  return json::parse(in);
}

json dry_scene() {
  std::ifstream in(std::string(FFP_SOURCE_DIR) + "/data/scenes/ffp_reference.json");
  return json::parse(in);
}

struct BadKey {
  std::string what;
  std::function<json()> scene;
  std::string key;      // the JSON path the message must name
  std::string allowed;  // and what it says is allowed
};

std::vector<BadKey> bad_keys() {
  const auto edited = [](std::function<void(json&)> edit, std::function<json()> base = saturated_scene) {
    return [edit, base] {
      json j = base();
      edit(j);
      return j;
    };
  };
  return {
      {"a porosity of 1", edited([](json& j) { j["soil"]["porosity"] = 1.0; }), "soil.porosity", "> 0 and < 1"},
      {"a negative porosity", edited([](json& j) { j["soil"]["porosity"] = -0.1; }), "soil.porosity", "> 0 and < 1"},
      {"a zero permeability", edited([](json& j) { j["soil"]["permeability_m_s"] = 0.0; }), "soil.permeability_m_s",
       "> 0"},
      {"a permeability above clean gravel's", edited([](json& j) { j["soil"]["permeability_m_s"] = 5.0; }),
       "soil.permeability_m_s", "≤ 1"},
      {"an unknown permeability law", edited([](json& j) { j["soil"]["permeability_law"] = "darcy"; }),
       "soil.permeability_law", "kozeny_carman"},
      {"saturated as a word", edited([](json& j) { j["soil"]["saturated"] = "yes"; }), "soil.saturated", "true"},
      {"a negative fluid bulk modulus", edited([](json& j) { j["fluid"]["bulk_modulus_kPa"] = -1.0; }),
       "fluid.bulk_modulus_kPa", "> 0"},
      {"a zero fluid density", edited([](json& j) { j["fluid"]["density_kg_m3"] = 0.0; }), "fluid.density_kg_m3",
       "> 0"},
      {"a negative water depth", edited([](json& j) { j["fluid"]["water_depth_m"] = -1.0; }), "fluid.water_depth_m",
       "≥ 0"},
      {"an unknown fluid key", edited([](json& j) { j["fluid"]["viscosity_Pa_s"] = 1e-3; }), "fluid.viscosity_Pa_s",
       "water_depth_m"},
      {"an unknown drainage", edited([](json& j) { j["soil"]["drainage"]["base"] = "open"; }), "soil.drainage.base",
       "drained"},
      {"a porosity on a dry sand", edited([](json& j) { j["soil"]["porosity"] = 0.44; }, dry_scene), "soil.porosity",
       "saturated: true"},
      {"a fluid on a dry sand",
       edited(
           [](json& j) {
             j["fluid"] = {{"water_depth_m", 1.0}};
           },
           dry_scene),
       "fluid", "soil.saturated: true"},
      {"a drainage on a dry sand",
       edited(
           [](json& j) {
             j["soil"]["drainage"] = {{"base", "drained"}};
           },
           dry_scene),
       "soil.drainage", "soil.saturated: true"},
      {"absorbing walls", edited([](json& j) { j["soil"]["walls"] = "absorbing"; }), "soil.walls", "rigid"},
      {"a deformable penetrometer", edited([](json& j) {
         j["ffp"]["deformable"] = {{"E_kPa", 2e4}, {"nu", 0.0}};
       }),
       "ffp.deformable", "rigid"},
      {"the particles' contact surface", edited([](json& j) { j["contact"]["surface"] = "particles"; }),
       "contact.surface", "nodes"},
  };
}

}  // namespace

TEST_CASE("saturated ffp: a bad fluid or saturated key is one line naming it and its range, exit code 2",
          "[cli][saturated]") {
  for (const BadKey& bad : bad_keys()) {
    DYNAMIC_SECTION(bad.what) {
      Scratch scratch;
      const std::string scene = scratch.write_json("scene.json", bad.scene()).string();
      const auto before = scratch.entries();
      const auto r = run_ffp({"run", scene, "--out", (scratch.path() / "result").string()}, scratch.path());
      INFO("stderr: " << r.err);
      CHECK(r.exit_code == 2);
      CHECK(r.err.find(bad.key) != std::string::npos);
      CHECK(r.err.find(bad.allowed) != std::string::npos);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK(scratch.entries() == before);
      CHECK(run_ffp({"check", scene}, scratch.path()).exit_code == 2);
    }
  }
}
