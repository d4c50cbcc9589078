#pragma once
/// The scene reference (`ffp keys`, docs/reference/scenes.md): every key each kind's readers
/// accept, with what each read declares of it (scene_reader.hpp's Doc).
///
/// A reader knows its keys only as it runs, and a branchy reader runs only some of them on
/// one scene (a deformable penetrometer's keys, a meshed specimen's). So the reference runs
/// each kind's readers over probe scenes, through make_job with a KeyLog: every shipped scene
/// of the kind, and the variants below (`--set` overrides of shipped scenes) that reach the
/// branches the shipped scenes leave out. The logs are merged: a key is listed once, at its
/// generic path ("bodies[i].name"), and two reads of it must say the same.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/scene/scene_reader.hpp"

namespace ffp {

/// A shipped scene (data/scenes/<scene>.json) with `--set` overrides.
struct Probe {
  std::string scene;
  std::vector<std::string> overrides;
};

struct ReferenceKey {
  std::string path;  ///< generic: list elements as [i]
  KeyEntry entry;
};

struct KindReference {
  std::string kind, description;
  std::vector<ReferenceKey> keys;  ///< in reading order
};

/// The reference cannot be built: a probe is refused, or the reads of a key disagree.
class ReferenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The variants of shipped scenes that reach the branches the shipped scenes of `kind` leave out.
std::vector<Probe> branch_probes(std::string_view kind);

/// Every probe of `kind`: its shipped scenes in `scenes_dir` (by name), then its branch probes.
std::vector<Probe> probes_of(std::string_view kind, const std::filesystem::path& scenes_dir);

/// The reference of every kind, or of `kind` alone. Throws ReferenceError.
std::vector<KindReference> scene_reference(const std::filesystem::path& scenes_dir, std::string_view kind = "");

/// For a terminal: a block per key.
std::string reference_text(const std::vector<KindReference>& kinds);
/// docs/reference/scenes.md: one table per kind and per nested object.
std::string reference_markdown(const std::vector<KindReference>& kinds);

}  // namespace ffp
