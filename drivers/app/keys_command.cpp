/// `ffp keys [KIND] [--markdown]`: the scene reference, built from the readers over the probe
/// scenes (key_reference.hpp), on standard output.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "drivers/app/commands.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/key_reference.hpp"

namespace ffp {

int command_keys(const KeysOptions& options) {
  const auto& kinds = registered_kinds();
  if (!options.kind.empty() &&
      std::none_of(kinds.begin(), kinds.end(), [&](const KindEntry& k) { return k.kind == options.kind; })) {
    std::fprintf(stderr, "ffp keys: '%s' is not a scene kind: must be one of: %s\n", options.kind.c_str(),
                 kind_list("", "").c_str());
    return 2;
  }
  try {
    const std::vector<KindReference> reference = scene_reference(default_scenes_folder(), options.kind);
    std::cout << (options.markdown ? reference_markdown(reference) : reference_text(reference)) << std::flush;
  } catch (const ReferenceError& e) {
    std::fprintf(stderr, "ffp keys: %s\n", e.what());
    return 1;
  }
  if (!std::cout) {
    std::fprintf(stderr, "ffp keys: cannot write to standard output: %s\n", std::strerror(errno));
    return 1;
  }
  return 0;
}

}  // namespace ffp
