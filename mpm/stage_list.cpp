#include "mpm/stage_list.hpp"

#include <stdexcept>

namespace ffp::mpm {

void StageList::append(Stage stage) { stages_.push_back(std::move(stage)); }

std::size_t StageList::position(std::string_view anchor) const {
  for (std::size_t i = 0; i < stages_.size(); ++i)
    if (stages_[i].name == anchor) return i;
  throw std::invalid_argument("no stage named " + std::string(anchor) + " in " + describe());
}

void StageList::insert_before(std::string_view anchor, Stage stage) {
  const auto at = static_cast<std::ptrdiff_t>(position(anchor));
  stages_.insert(stages_.begin() + at, std::move(stage));
}

void StageList::insert_after(std::string_view anchor, Stage stage) {
  const auto at = static_cast<std::ptrdiff_t>(position(anchor)) + 1;
  stages_.insert(stages_.begin() + at, std::move(stage));
}

bool StageList::contains(std::string_view name) const {
  for (const Stage& s : stages_)
    if (s.name == name) return true;
  return false;
}

std::vector<std::string> StageList::names() const {
  std::vector<std::string> out;
  for (const Stage& s : stages_) out.push_back(s.name);
  return out;
}

std::string StageList::describe() const {
  std::string out;
  for (const Stage& s : stages_) {
    if (!out.empty()) out += " → ";
    out += s.name;
  }
  return out;
}

}  // namespace ffp::mpm
