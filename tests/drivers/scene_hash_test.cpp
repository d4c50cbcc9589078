/// A resolved scene's hash: FNV-1a as its authors define it, the same for the
/// same scene however its numbers are written, different for another value.
#include <catch2/catch.hpp>

#include "drivers/scene/scene_hash.hpp"

using nlohmann::json;

TEST_CASE("FNV-1a 64 gives the published values", "[drivers][hash]") {
  // Test vectors of the FNV reference code (Noll, "FNV hash", test_fnv.c: fnv1a_64 of "" and "a").
  CHECK(ffp::fnv1a_64("") == 0xcbf29ce484222325ull);
  CHECK(ffp::fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(ffp::fnv1a_64("foobar") == 0x85944171f73967e8ull);
  CHECK(ffp::hex_digits(0xaf63dc4c8601ec8cull) == "af63dc4c8601ec8c");
}

TEST_CASE("a scene's hash ignores how a number is written and its description, not a value", "[drivers][hash]") {
  const json a = json::parse(R"({"kind": "ffp", "material": {"E_kPa": 2500, "nu": 0.33}, "description": "x"})");
  const json b = json::parse(R"({"material": {"nu": 0.33, "E_kPa": 2500.0}, "kind": "ffp", "description": "y"})");
  const json c = json::parse(R"({"kind": "ffp", "material": {"E_kPa": 2500.0000001, "nu": 0.33}})");
  CHECK(ffp::scene_hash(a) == ffp::scene_hash(b));
  CHECK(ffp::scene_hash(a) != ffp::scene_hash(c));
  CHECK(ffp::scene_hash(a).size() == 16);
}

TEST_CASE("the first difference between two scenes names its key and both values", "[drivers][hash]") {
  const json ran = json::parse(R"({"material": {"E_kPa": 1000, "nu": 0.33}, "bodies": [{"m": 1}]})");
  json wanted = ran;
  wanted["material"]["E_kPa"] = 50000;
  ffp::SceneDifference d = ffp::first_difference(ran, wanted);
  CHECK(d.key == "material.E_kPa");
  CHECK(d.before == "1000.0");
  CHECK(d.after == "50000.0");
  CHECK(d.others == 0);
  CHECK(d.text("this sweep") == "material.E_kPa = 1000.0 where this sweep has 50000.0");
  wanted["bodies"][0]["m"] = 2;
  wanted["extra"] = true;
  d = ffp::first_difference(ran, wanted);
  CHECK(d.key == "bodies[0].m");
  CHECK(d.others == 2);
  CHECK(d.text("the case") == "bodies[0].m = 1.0 where the case has 2.0 (and 2 more keys)");
  CHECK(ffp::first_difference(ran, ran).key.empty());
}
