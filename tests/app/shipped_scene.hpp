#pragma once
/// A shipped scene (data/scenes/<name>.json, `--set` overrides applied) and a
/// top-level reader past kind, name and description, as make_job leaves it for
/// a kind's reader: the scene tests call the readers in-process.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "drivers/scene/scene_reader.hpp"

namespace ffp::test_support {

inline const std::filesystem::path kSceneDir = std::filesystem::path(FFP_SOURCE_DIR) / "data" / "scenes";

class ShippedScene {
 public:
  explicit ShippedScene(const std::string& name, const std::vector<std::string>& overrides = {})
      : scene_(load_scene_file((kSceneDir / (name + ".json")).string())) {
    for (const std::string& o : overrides) apply_override(scene_, o);
    top_.emplace(scene_, "", echo_);
    top_->allow("kind", Doc("the scene kind"));
    top_->text("name", "", Doc("the scene name"));
    top_->allow("description", Doc("free text"));
  }
  ShippedScene(const ShippedScene&) = delete;
  ShippedScene& operator=(const ShippedScene&) = delete;

  SceneReader& reader() { return *top_; }
  const json& echo() const { return echo_; }
  static std::filesystem::path dir() { return kSceneDir; }

 private:
  json scene_;
  json echo_ = json::object();
  std::optional<SceneReader> top_;
};

/// The SceneError `read` throws; fails the test when it throws none.
template <class Read>
std::string scene_error(Read&& read) {
  try {
    read();
  } catch (const SceneError& e) {
    return e.what();
  }
  FAIL("no SceneError");
  return "";
}

}  // namespace ffp::test_support
