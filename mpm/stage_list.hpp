#pragma once
/// The explicit step as an ordered list of named stages, built once from the
/// model (mpm/build_stages.cpp): a model gets only the stages it needs, and
/// later features (contact, rigid body, moving mesh) are stages inserted by
/// name, e.g. stages.insert_after("integrate_grid", {"apply_contact", f}).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ffp::mpm {

class Simulation;

struct Stage {
  std::string name;
  std::function<void(Simulation&)> run;
};

class StageList {
 public:
  void append(Stage stage);
  /// Insert next to the first stage called `anchor`; throws std::invalid_argument if none.
  void insert_before(std::string_view anchor, Stage stage);
  void insert_after(std::string_view anchor, Stage stage);
  bool contains(std::string_view name) const;
  const std::vector<Stage>& items() const { return stages_; }
  std::vector<std::string> names() const;
  /// "reset_grid → compute_shape_functions → …"
  std::string describe() const;

  void run(Simulation& simulation) const {
    for (const Stage& s : stages_) s.run(simulation);
  }

 private:
  std::size_t position(std::string_view anchor) const;
  std::vector<Stage> stages_;
};

}  // namespace ffp::mpm
