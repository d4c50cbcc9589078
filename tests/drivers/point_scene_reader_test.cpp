/// The `point` scene reader in-process: a scene becomes the typed description
/// the job runs (no program, no output folder), and bad keys are SceneErrors
/// that name them. End-to-end runs are in point_scene_test.cpp.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "drivers/app/point_scene.hpp"

namespace {

using json = nlohmann::json;
using namespace ffp;

/// What make_job does before the kind's reader: the top-level reader, kind already read.
PointScene read(const json& scene, json& echo) {
  SceneReader top(scene, "", echo);
  top.allow("kind", Doc("the scene kind"));
  return read_point_scene(top, std::filesystem::path(FFP_SOURCE_DIR) / "data" / "scenes");
}

PointScene read(const json& scene) {
  json echo;
  return read(scene, echo);
}

json mc_triaxial() {
  return {{"kind", "point"},
          {"name", "mc"},
          {"material", {{"model", "mohr_coulomb"}, {"E_kPa", 2500}, {"nu", 0.33}, {"phi_peak_deg", 39}}},
          {"path", {{"type", "triaxial_compression"}, {"cell_pressure_kPa", 5}, {"increments", 400}}}};
}

json ssmc_triaxial() {
  json scene = mc_triaxial();
  scene["material"] = {{"model", "ssmc"},    {"E_kPa", 2500},          {"nu", 0.33},
                       {"phi_peak_deg", 60}, {"phi_residual_deg", 32}, {"eta", 8}};
  return scene;
}

/// The message of the SceneError `scene` raises (empty if none).
std::string refusal(const json& scene) {
  try {
    read(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("point reader: a triaxial compression path starts at the cell pressure with σ_r held and ε_a driven",
          "[point][scene][reader]") {
  json echo;
  const PointScene s = read(mc_triaxial(), echo);
  CHECK(s.name == "mc");
  CHECK(s.material.model == "mohr_coulomb");
  CHECK(s.path_type == "triaxial_compression");
  const PointConfig& c = s.config;
  CHECK(c.law.index() == make_law(s.material.parameters).index());
  CHECK(c.initial_state.index() == c.law.index());                 // the law's virgin state
  for (int i = 0; i < 3; ++i) CHECK(c.initial_stress[i] == -5e3);  // compression positive kPa → tension positive Pa
  for (int i = 3; i < 6; ++i) CHECK(c.initial_stress[i] == 0.0);
  REQUIRE(c.segments.size() == 1);
  const PathSegment& leg = c.segments[0];
  CHECK(leg.control == ControlSet{Control::stress, Control::strain, Control::stress, Control::strain, Control::strain,
                                  Control::strain});
  CHECK(leg.target[0] == -5e3);
  CHECK(leg.target[1] == -0.2);  // the default axial_strain_max, compression
  CHECK(leg.increments == 400);
  CHECK(leg.duration_s == Approx(0.2 / 1e-4));
  CHECK(c.newton.max_iterations == 25);
  CHECK(c.newton.relative_tolerance == 1e-10);
  CHECK(c.record_every == 1);
  CHECK(echo["path"]["strain_rate_per_s"].get<double>() == 1e-4);  // defaults are echoed
}

TEST_CASE("point reader: an initial_state sets the internal variables of a softening law", "[point][scene][reader]") {
  json scene = ssmc_triaxial();
  CHECK(initial_state_json(read(scene).config.initial_state) ==
        json{{"plastic_deviatoric_strain", 0.0}, {"strain_rate_per_s", 0.0}});
  scene["initial_state"] = {{"plastic_deviatoric_strain", 0.05}, {"strain_rate_per_s", 2e-3}};
  CHECK(initial_state_json(read(scene).config.initial_state) ==
        json{{"plastic_deviatoric_strain", 0.05}, {"strain_rate_per_s", 2e-3}});
}

TEST_CASE("point reader: initial_pressure_kPa and a general path of segments", "[point][scene][reader]") {
  json scene = mc_triaxial();
  scene["initial_pressure_kPa"] = 10;
  scene["path"] = {{"type", "general"},
                   {"segments",
                    {{{"control", {"stress", "strain", "stress", "strain", "strain", "strain"}},
                      {"target", {10, 0.01, 10, 0, 0, 0}},
                      {"increments", 50},
                      {"duration_s", 2}},
                     {{"control", {"strain", "strain", "strain", "strain", "strain", "strain"}},
                      {"target", {0, 0.02, 0, 0, 0, 0}},
                      {"increments", 30}}}}};
  const PointScene s = read(scene);
  CHECK(s.path_type == "general");
  CHECK(s.config.initial_stress[0] == -1e4);
  REQUIRE(s.config.segments.size() == 2);
  CHECK(s.config.segments[0].duration_s == 2.0);
  CHECK(s.config.segments[1].duration_s == 1.0);  // the default
  CHECK(s.config.segments[1].increments == 30);
  CHECK(s.config.segments[1].target[1] == -0.02);
}

TEST_CASE("point reader: bad keys are SceneErrors that name them", "[point][scene][reader]") {
  json typo = mc_triaxial();
  typo["path"]["incremnts"] = 10;
  CHECK_THAT(refusal(typo), Catch::Contains("path.incremnts") && Catch::Contains("did you mean 'increments'"));

  json top = mc_triaxial();
  top["output_every"] = 10;
  CHECK_THAT(refusal(top), Catch::Contains("output_every"));

  json both = mc_triaxial();
  both["initial_pressure_kPa"] = 1;
  both["initial_stress_kPa"] = {1, 1, 1, 0, 0, 0};
  CHECK_THAT(refusal(both), Catch::StartsWith("initial_pressure_kPa"));

  json stateless = mc_triaxial();
  stateless["initial_state"] = {{"plastic_deviatoric_strain", 0.1}};
  CHECK_THAT(refusal(stateless), Catch::StartsWith("initial_state") && Catch::Contains("only an ssmc material"));

  json state_typo = ssmc_triaxial();
  state_typo["initial_state"] = {{"plastic_strain", 0.1}};
  CHECK_THAT(refusal(state_typo), Catch::Contains("initial_state.plastic_strain"));

  json path_type = mc_triaxial();
  path_type["path"]["type"] = "triaxial";
  CHECK_THAT(refusal(path_type), Catch::Contains("path.type"));

  json material = mc_triaxial();
  material["material"]["eta"] = 8;  // a softening key on a Mohr-Coulomb material
  CHECK_THAT(refusal(material), Catch::Contains("material.eta"));
}
