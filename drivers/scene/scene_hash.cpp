#include "drivers/scene/scene_hash.hpp"

#include <cstdio>
#include <vector>

namespace ffp {

std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash) {
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;  // the 64-bit FNV prime
  }
  return hash;
}

std::string hex_digits(std::uint64_t hash) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

namespace {
void numbers_as_doubles(nlohmann::json& node) {
  if (node.is_number()) {
    node = node.get<double>();
  } else if (node.is_object() || node.is_array()) {
    for (auto& child : node) numbers_as_doubles(child);
  }
}
}  // namespace

nlohmann::json canonical_scene(const nlohmann::json& echo) {
  nlohmann::json scene = echo;
  if (scene.is_object()) scene.erase("description");
  numbers_as_doubles(scene);
  return scene;
}

std::string scene_hash(const nlohmann::json& echo) { return hex_digits(fnv1a_64(canonical_scene(echo).dump())); }

namespace {
/// "/bodies/0/E_kPa" (a JSON pointer, RFC 6901) as the scenes' keys are written: "bodies[0].E_kPa".
std::string dotted(const nlohmann::json::json_pointer& pointer) {
  std::string key;
  nlohmann::json::json_pointer rest = pointer;
  std::vector<std::string> tokens;
  while (!rest.empty()) {
    tokens.insert(tokens.begin(), rest.back());
    rest.pop_back();
  }
  for (const std::string& token : tokens) {
    const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    key += index ? "[" + token + "]" : (key.empty() ? "" : ".") + token;
  }
  return key;
}
}  // namespace

SceneDifference first_difference(const nlohmann::json& before_echo, const nlohmann::json& after_echo) {
  const nlohmann::json before = canonical_scene(before_echo), after = canonical_scene(after_echo);
  const nlohmann::json patch = nlohmann::json::diff(before, after);  // RFC 6902 operations, before → after
  SceneDifference difference;
  if (patch.empty()) return difference;
  const nlohmann::json& op = patch.front();
  const nlohmann::json::json_pointer where(op.at("path").get<std::string>());
  difference.key = where.empty() ? "the scene" : dotted(where);
  difference.before = op.at("op") == "add" ? "none" : before.at(where).dump();
  difference.after = op.at("op") == "remove" ? "none" : op.at("value").dump();
  difference.others = patch.size() - 1;
  return difference;
}

std::string SceneDifference::text(std::string_view other) const {
  std::string words = key + " = " + before + " where " + std::string(other) + " has " + after;
  if (others > 0) words += " (and " + std::to_string(others) + " more keys)";
  return words;
}

}  // namespace ffp
