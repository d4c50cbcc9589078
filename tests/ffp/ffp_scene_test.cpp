/// Validation of the `ffp` and `cpt` scenes: every shipped scene is valid, and
/// inputs that mean nothing (or two things) are refused with exit code 2 and a
/// message naming the JSON path.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "ffp_test_support.hpp"

using namespace ffp;
using namespace ffp::test;
using nlohmann::json;

namespace {

json reference() { return read_json(scene_path("ffp_reference.json")); }
json cpt() { return read_json(scene_path("cpt_reference.json")); }

/// `ffp check` on the scene: exit code and stderr.
ProgramResult check(const json& scene) {
  ScratchDir scratch;
  const auto file = scratch.path() / "scene.json";
  std::ofstream(file) << scene.dump(2);
  return run_program({"check", file.string()}, scratch.path());
}

void refused(const json& scene, const std::string& path, const std::string& words) {
  const ProgramResult r = check(scene);
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find(path) != std::string::npos);
  CHECK(r.err.find(words) != std::string::npos);
}

}  // namespace

TEST_CASE("every shipped ffp and cpt scene is valid", "[ffp][scene]") {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(FFP_SOURCE_DIR) + "/data/scenes")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ffp_", 0) != 0 && name.rfind("cpt_", 0) != 0 && name.rfind("punch_", 0) != 0) continue;
    ScratchDir scratch;
    const ProgramResult r = run_program({"check", entry.path().string()}, scratch.path());
    INFO(name << ": " << r.err);
    CHECK(r.exit_code == 0);
    ++scenes;
  }
  CHECK(scenes >= 11);
}

TEST_CASE("a rigid FFP with stiffness keys is refused", "[ffp][scene]") {
  json s = reference();
  s["ffp"]["E_kPa"] = 2e8;
  refused(s, "ffp.E_kPa", "rigid penetrometer has no stiffness");
}

TEST_CASE("contact with both delta_deg and rough, or with neither, is refused", "[ffp][scene]") {
  json both = reference();
  both["contact"]["rough"] = true;
  refused(both, "contact.delta_deg", "not both");
  json neither = reference();
  neither["contact"] = json::object();
  refused(neither, "contact.delta_deg", "is required");
}

TEST_CASE("a deformable FFP with a rigid-body force is refused", "[ffp][scene]") {
  json s = reference();
  s["ffp"]["deformable"] = {{"E_kPa", 20000}, {"nu", 0.0}};
  s["ffp"]["rigid_body_force"] = "soil_internal_force";
  refused(s, "ffp.rigid_body_force", "rigid penetrometer only");
}

TEST_CASE("a deformable FFP with the particle projection is refused", "[ffp][scene]") {
  json s = reference();
  s["ffp"]["deformable"] = {{"E_kPa", 20000}, {"nu", 0.0}};
  s["contact"]["project_particles"] = true;
  refused(s, "contact.project_particles", "rigid penetrometer only");
  json word = reference();
  word["contact"]["project_particles"] = "yes";
  refused(word, "contact.project_particles", "true or false");
}

TEST_CASE("the particles' contact surface refuses the nodes' settings, a deformable body and eq. 1's force",
          "[ffp][scene]") {
  json s = reference();
  s["contact"]["surface"] = "particles";
  s["contact"]["detection_cells"] = 0.5;
  refused(s, "contact.detection_cells", "surface nodes only");
  json cap = reference();
  cap["contact"]["surface"] = "particles";
  cap["contact"]["velocity_scaling"] = 0.75;
  refused(cap, "contact.velocity_scaling", "surface nodes only");
  json elastic = reference();
  elastic["ffp"]["deformable"] = {{"E_kPa", 20000}, {"nu", 0.0}};
  elastic["contact"]["project_particles"] = false;
  elastic["contact"]["surface"] = "particles";
  refused(elastic, "contact.surface", "rigid penetrometer only");
  json force = reference();
  force["ffp"]["rigid_body_force"] = "soil_internal_force";
  force["contact"]["surface"] = "particles";
  refused(force, "contact.surface", "contact_impulse");
  json word = reference();
  word["contact"]["surface"] = "outline";
  refused(word, "contact.surface", "nodes");
}

TEST_CASE("damping is refused for the dynamic FFP impact", "[ffp][scene]") {
  json s = reference();
  s["solver"]["local_damping"] = 0.05;
  refused(s, "solver.local_damping", "no artificial damping");
}

TEST_CASE("a push velocity belongs to cpt, a mass and an impact velocity to ffp", "[ffp][scene]") {
  json f = reference();
  f["ffp"]["push_velocity_m_s"] = 0.02;
  refused(f, "ffp.push_velocity_m_s", "kind cpt");
  json c = cpt();
  c["ffp"]["mass_kg"] = 7.71;
  refused(c, "ffp.mass_kg", "no mass");
  json both = cpt();
  both["end_time_s"] = 1.0;
  refused(both, "end_time_s", "not both");
}

TEST_CASE("a mesh or body that does not fit the chamber is refused", "[ffp][scene]") {
  json coarse = reference();
  coarse["mesh"]["min_cell_m"] = 0.39;  // no cell between the body and the wall
  refused(coarse, "mesh.min_cell_m", "no cell between");
  json deep = reference();
  deep["mesh"]["band_below_m"] = 0.39;
  refused(deep, "mesh.band_below_m", "two cells of sand");
  json typo = reference();
  typo["ffp"]["mas_kg"] = 7.71;
  refused(typo, "ffp.mas_kg", "mass_kg");
}

TEST_CASE("the sand's disconnection density ratio must be at least 0 and below 1", "[ffp][scene]") {
  json whole = reference();
  whole["soil"]["disconnected_density_ratio"] = 1.0;  // every particle would start disconnected
  refused(whole, "soil.disconnected_density_ratio", "< 1");
  json negative = reference();
  negative["soil"]["disconnected_density_ratio"] = -0.1;
  refused(negative, "soil.disconnected_density_ratio", "≥ 0");
  json off = reference();
  off["soil"]["disconnected_density_ratio"] = 0.0;  // the rule switched off
  CHECK(check(off).exit_code == 0);
}

TEST_CASE("a flat punch has no cone angle and its plateau window lies within the push of a flat tip in a cohesive soil",
          "[ffp][scene][punch]") {
  const json punch = read_json(scene_path("punch_smooth.json"));
  json s = punch;
  s["ffp"]["cone_apex_angle_deg"] = 60;
  refused(s, "ffp.cone_apex_angle_deg", "flat tip has no cone");
  s = punch;
  s["plateau_settlement_ratio"] = {0.04, 0.2};  // 0.2 R = 1 cm, the push is 3 mm
  refused(s, "plateau_settlement_ratio", "beyond the push");
  s = punch;
  s["plateau_settlement_ratio"] = {0.06, 0.04};
  refused(s, "plateau_settlement_ratio", "from < to");
  json c = cpt();
  c["plateau_settlement_ratio"] = {0.04, 0.06};
  refused(c, "plateau_settlement_ratio", "flat in a soil with c_peak_kPa > 0");
}

TEST_CASE("phi_peak_deg = 0 (Tresca) is allowed for mohr_coulomb with a cohesion only", "[ffp][scene][punch]") {
  json s = read_json(scene_path("punch_smooth.json"));
  s["material"]["c_peak_kPa"] = 0;
  refused(s, "material.phi_peak_deg", "needs c_peak_kPa > 0");
  json c = cpt();  // ssmc
  c["material"]["phi_peak_deg"] = 0;
  refused(c, "material.phi_peak_deg", "for ssmc");
}

TEST_CASE("soil.near_spacing_m is a length that replaces particles_per_cell_near and is at most a min cell",
          "[ffp][scene]") {
  json s = reference();
  s["soil"]["near_spacing_m"] = 0.0022;
  refused(s, "soil.near_spacing_m", "not both");
  s["soil"].erase("particles_per_cell_near");
  s["soil"]["near_spacing_m"] = 0.02;  // the reference's min cell is 1 cm
  refused(s, "soil.near_spacing_m", "at most mesh.min_cell_m");
  // A third of the 1 cm cell is the reference's own 3 × 3 per cell: the same particles.
  s["soil"]["near_spacing_m"] = 0.01 / 3.0;
  const ProgramResult by_length = check(s);
  const ProgramResult by_count = check(reference());
  REQUIRE(by_length.exit_code == 0);
  auto particles = [](const std::string& out) {
    return out.substr(out.find("particles:"), out.find('\n', out.find("particles:")) - out.find("particles:"));
  };
  CHECK(particles(by_length.out) == particles(by_count.out));
}

TEST_CASE("an override to null removes the key so that its default applies", "[ffp][scene]") {
  ScratchDir scratch;
  const ProgramResult r = run_program({"check", scene_path("ffp_reference.json"), "--set",
                                       "soil.particles_per_cell_near=null", "--set", "soil.near_spacing_m=0.0022"},
                                      scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("\"near_spacing_m\": 0.0022") != std::string::npos);
}

TEST_CASE("the micropolar block: each key within its range, only its own keys, only in MPM kinds", "[ffp][scene]") {
  json micropolar = reference();
  micropolar["material"]["micropolar"] = {{"length_m", 0.0003}};
  {
    const ProgramResult r = check(micropolar);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    // The defaults filled in: G_c/G = 0.5, j = ℓ²/10.
    const std::string resolved = "resolved scene (defaults filled in):";
    REQUIRE(r.out.find(resolved) != std::string::npos);
    const json echo = json::parse(r.out.substr(r.out.find(resolved) + resolved.size()));
    CHECK(echo["material"]["micropolar"]["cosserat_shear_ratio"] == 0.5);
    CHECK(echo["material"]["micropolar"]["micro_inertia_m2"].get<double>() == Approx(9e-9).epsilon(1e-12));
    CHECK(r.out.find("map_micropolar_to_grid") != std::string::npos);
  }
  auto with = [&](const char* key, json value) {
    json s = micropolar;
    s["material"]["micropolar"][key] = value;
    return s;
  };
  refused(with("length_m", -0.001), "material.micropolar.length_m", "> 0 and ≤ 0.1 m");
  refused(with("length_m", 1.0), "material.micropolar.length_m", "> 0 and ≤ 0.1 m");
  refused(with("cosserat_shear_ratio", 0.0), "material.micropolar.cosserat_shear_ratio", "> 0 and ≤ 10");
  refused(with("micro_inertia_m2", -1.0), "material.micropolar.micro_inertia_m2", "> 0 and ≤ 1 m²");
  refused(with("d50_m", 0.0003), "material.micropolar.d50_m", "unknown key");
  json no_length = reference();
  no_length["material"]["micropolar"] = json::object();
  refused(no_length, "material.micropolar.length_m", "required");
  // A classical scene carries none of the option's keys, and builds no micropolar stage.
  const ProgramResult classical = check(reference());
  CHECK(classical.exit_code == 0);
  CHECK(classical.out.find("micropolar") == std::string::npos);
  // A material point has no gradients: the point and triaxial kinds refuse the option.
  json point = read_json(scene_path("point_triaxial_mc.json"));
  point["material"]["micropolar"] = {{"length_m", 0.0003}};
  refused(point, "material.micropolar", "option of the MPM kinds");
}
