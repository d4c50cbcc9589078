/// Bad input reaches the user as one line naming the key and what is allowed,
/// exit code 2, and no output directory.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>

#include "cli_harness.hpp"

using ffp::test::good_point_scene;
using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;

namespace {

struct BadInput {
  std::string what;
  std::function<std::string(const Scratch&)> make_scene_file;  // returns the scene path
  std::vector<std::string> extra_args;
  std::string must_mention;  // the key (or file position) the message has to name
};

std::string write_scene(const Scratch& s, const std::function<void(json&)>& edit) {
  json scene = good_point_scene();
  edit(scene);
  return s.write_json("scene.json", scene).string();
}

std::vector<BadInput> bad_inputs() {
  return {
      {"missing file", [](const Scratch& s) { return (s.path() / "nope.json").string(); }, {}, "nope.json"},
      {"empty file", [](const Scratch& s) { return s.write("scene.json", "  \n").string(); }, {}, "empty"},
      {"invalid JSON reports line and column",
       [](const Scratch& s) { return s.write("scene.json", "{\n  \"kind\": \"point\",\n  \"name\": }\n").string(); },
       {},
       "scene.json:3:"},
      {"scene is not an object",
       [](const Scratch& s) { return s.write("scene.json", "[1, 2]").string(); },
       {},
       "object"},
      {"missing kind", [](const Scratch& s) { return write_scene(s, [](json& j) { j.erase("kind"); }); }, {}, "kind"},
      {"misspelt kind",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["kind"] = "pointt"; }); },
       {},
       "kind"},
      {"kind of the wrong type",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["kind"] = 3; }); },
       {},
       "kind"},
      {"E given as a string",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["E_kPa"] = "2500"; }); },
       {},
       "material.E_kPa"},
      {"negative stiffness",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["E_kPa"] = -5; }); },
       {},
       "material.E_kPa"},
      {"Poisson ratio of one half",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["nu"] = 0.5; }); },
       {},
       "material.nu"},
      {"friction angle above 90 degrees",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["phi_peak_deg"] = 95; }); },
       {},
       "material.phi_peak_deg"},
      {"dilatancy above friction",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["psi_peak_deg"] = 45; }); },
       {},
       "material.psi_peak_deg"},
      {"negative cohesion",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["c_peak_kPa"] = -1; }); },
       {},
       "material.c_peak_kPa"},
      {"absurdly large stiffness",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["E_kPa"] = 1e300; }); },
       {},
       "material.E_kPa"},
      {"number that overflows to infinity",
       [](const Scratch& s) {
         return s
             .write("scene.json", R"({"kind": "point", "name": "x", "material": {"model": "mohr_coulomb",
           "E_kPa": 1e400, "nu": 0.3, "phi_peak_deg": 30}, "path": {"type": "isotropic"}})")
             .string();
       },
       {},
       "E_kPa"},
      {"unknown top-level key",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["materail"] = j["material"]; }); },
       {},
       "materail"},
      {"misspelt material key suggests the right one",
       [](const Scratch& s) {
         return write_scene(s, [](json& j) {
           j["material"]["E_kpa"] = 2500;
           j["material"].erase("E_kPa");
         });
       },
       {},
       "material.E_kPa"},
      {"softening factor on a Mohr-Coulomb material",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["eta"] = 8; }); },
       {},
       "material.eta"},
      {"unknown material model",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["material"]["model"] = "cam_clay"; }); },
       {},
       "material.model"},
      {"--set on a missing key",
       [](const Scratch& s) { return write_scene(s, [](json&) {}); },
       {"--set", "material.E_kpa=5"},
       "material.E_kpa"},
      {"--set with a word where a number belongs",
       [](const Scratch& s) { return write_scene(s, [](json&) {}); },
       {"--set", "material.nu=abc"},
       "material.nu"},
      {"--set NaN",
       [](const Scratch& s) { return write_scene(s, [](json&) {}); },
       {"--set", "material.nu=NaN"},
       "material.nu"},
      {"--set value beyond a double (found by fuzzing)",
       [](const Scratch& s) { return write_scene(s, [](json&) {}); },
       {"--set", "material.E_kPa=1e400"},
       "material.E_kPa"},
      {"name that would escape the output folder",
       [](const Scratch& s) { return write_scene(s, [](json& j) { j["name"] = "../escape"; }); },
       {},
       "name"},
  };
}

}  // namespace

TEST_CASE("bad input: one line naming the key, exit code 2, no output left", "[cli]") {
  for (const auto& bad : bad_inputs()) {
    DYNAMIC_SECTION(bad.what) {
      Scratch scratch;
      const std::string scene = bad.make_scene_file(scratch);
      std::vector<std::string> args = {"run", scene, "--out", (scratch.path() / "result").string()};
      args.insert(args.end(), bad.extra_args.begin(), bad.extra_args.end());
      const auto before = scratch.entries();
      const auto r = run_ffp(args, scratch.path());
      INFO("stderr: " << r.err);
      CHECK(r.exit_code == 2);
      CHECK(r.err.find(bad.must_mention) != std::string::npos);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
      CHECK(scratch.entries() == before);                        // nothing written, not even a temp dir

      // `ffp check` judges the same scene the same way.
      std::vector<std::string> check_args = {"check", scene};
      check_args.insert(check_args.end(), bad.extra_args.begin(), bad.extra_args.end());
      CHECK(run_ffp(check_args, scratch.path()).exit_code == 2);
    }
  }
}

TEST_CASE("a failed run leaves a previous result untouched", "[cli]") {
  Scratch scratch;
  const auto target = scratch.path() / "result";
  std::filesystem::create_directories(target);
  scratch.write("result/marker.txt", "previous run");
  json scene = good_point_scene();
  scene["material"]["nu"] = 0.7;
  const auto file = scratch.write_json("scene.json", scene);
  const auto r = run_ffp({"run", file.string(), "--out", target.string()}, scratch.path());
  CHECK(r.exit_code == 2);
  CHECK(std::filesystem::exists(target / "marker.txt"));
}

TEST_CASE("unknown command and option are refused", "[cli]") {
  Scratch scratch;
  CHECK(run_ffp({"frobnicate"}, scratch.path()).exit_code == 2);
  const auto file = scratch.write_json("scene.json", good_point_scene());
  const auto r = run_ffp({"run", file.string(), "--bogus"}, scratch.path());
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--bogus") != std::string::npos);
}
