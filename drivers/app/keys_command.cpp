/// `ffp keys [KIND] [--markdown]`: the scene reference, built from the readers over the probe
/// scenes (key_reference.hpp), on standard output.
#include <algorithm>
#include <cstdio>

#include "drivers/app/commands.hpp"
#include "drivers/app/exit_codes.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/key_reference.hpp"
#include "drivers/output/checked_write.hpp"

namespace ffp {

int command_keys(const KeysOptions& options) {
  const auto& kinds = registered_kinds();
  if (!options.kind.empty() &&
      std::none_of(kinds.begin(), kinds.end(), [&](const KindEntry& k) { return k.kind == options.kind; })) {
    std::fprintf(stderr, "error: ffp keys: '%s' is not a scene kind: must be one of: %s\n", options.kind.c_str(),
                 kind_list("", "").c_str());
    return 2;
  }
  try {
    const std::vector<KindReference> reference = scene_reference(default_scenes_folder(), options.kind);
    write_standard_output(options.markdown ? reference_markdown(reference) : reference_text(reference));
    return 0;
  } catch (...) {  // a probe refused (ReferenceError), or standard output (WriteFailure): exit 1
    return exit_code_of_current_exception();
  }
}

}  // namespace ffp
