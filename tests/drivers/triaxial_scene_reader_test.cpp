/// The `triaxial` scene reader in-process: a scene becomes the typed test
/// configuration (no program, no output folder), and bad keys are SceneErrors
/// that name them. End-to-end runs are in triaxial_scene_test.cpp.
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "drivers/app/triaxial_scene.hpp"

namespace {

using json = nlohmann::json;
using namespace ffp;

TriaxialScene read(const json& scene, json& echo) {
  SceneReader top(scene, "", echo);
  top.allow("kind", Doc("the scene kind"));
  return read_triaxial_scene(top);
}

TriaxialScene read(const json& scene) {
  json echo;
  return read(scene, echo);
}

json ssmc_scene() {
  return {
      {"kind", "triaxial"},
      {"material",
       {{"model", "ssmc"}, {"E_kPa", 2500}, {"nu", 0.33}, {"phi_peak_deg", 60}, {"phi_residual_deg", 32}, {"eta", 8}}}};
}

std::string refusal(const json& scene) {
  try {
    read(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("triaxial reader: the defaults are the paper's specimen at 1.72 kPa", "[triaxial][scene][reader]") {
  json echo;
  const TriaxialScene s = read(ssmc_scene(), echo);
  CHECK(s.name == "triaxial");
  CHECK(s.material.model == "ssmc");
  const TriaxialTestConfig& c = s.config;
  CHECK(c.law.index() == make_law(s.material.parameters).index());
  CHECK(c.cell_pressure_Pa == Approx(1720.0));
  CHECK(c.axial_strain_max == 0.2);
  CHECK(c.increments == 2000);
  CHECK(c.strain_rate_per_s == 1e-4);
  CHECK(c.specimen.height_m == 0.15);
  CHECK(c.specimen.diameter_m == 0.07);
  CHECK(c.newton.max_iterations == 25);
  CHECK(c.newton.relative_tolerance == 1e-10);
  CHECK(s.output_every == 1);
  CHECK(echo["specimen"]["height_m"].get<double>() == 0.15);  // defaults are echoed
}

TEST_CASE("triaxial reader: given keys in scene units become SI", "[triaxial][scene][reader]") {
  json scene = ssmc_scene();
  scene["name"] = "dense";
  scene["cell_pressure_kPa"] = 50;
  scene["axial_strain_max"] = 0.1;
  scene["increments"] = 100000;
  scene["specimen"] = {{"height_m", 0.1}, {"diameter_m", 0.05}};
  scene["newton"] = {{"max_iterations", 40}};
  const TriaxialScene s = read(scene);
  CHECK(s.name == "dense");
  CHECK(s.config.cell_pressure_Pa == 5e4);
  CHECK(s.config.axial_strain_max == 0.1);
  CHECK(s.config.increments == 100000);
  CHECK(s.config.specimen.height_m == 0.1);
  CHECK(s.config.specimen.diameter_m == 0.05);
  CHECK(s.config.newton.max_iterations == 40);
  CHECK(s.output_every == 5);  // at most ~20,000 history rows
}

TEST_CASE("triaxial reader: bad keys are SceneErrors that name them", "[triaxial][scene][reader]") {
  json zero = ssmc_scene();
  zero["axial_strain_max"] = 0;
  CHECK_THAT(refusal(zero), Catch::StartsWith("axial_strain_max"));

  json negative = ssmc_scene();
  negative["cell_pressure_kPa"] = -1;
  CHECK_THAT(refusal(negative), Catch::StartsWith("cell_pressure_kPa"));

  json typo = ssmc_scene();
  typo["specimen"] = {{"hieght_m", 0.1}};
  CHECK_THAT(refusal(typo), Catch::Contains("specimen.hieght_m") && Catch::Contains("did you mean 'height_m'"));

  json top = ssmc_scene();
  top["confining_kPa"] = 1;
  CHECK_THAT(refusal(top), Catch::StartsWith("confining_kPa"));

  json density = ssmc_scene();
  density["material"]["density_kg_m3"] = 1500;  // weightless: no density
  CHECK_THAT(refusal(density), Catch::Contains("material.density_kg_m3"));

  json missing = ssmc_scene();
  missing.erase("material");
  CHECK_THAT(refusal(missing), Catch::StartsWith("material"));
}
