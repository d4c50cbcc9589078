/// Fuzzes `--set key.path=value` parsing: each input line is one assignment
/// given to apply_override on a copy of data/scenes/ffp_reference.json (loaded
/// once), and make_job validates the result, as `ffp run --set ...` does. The
/// job is never run.
///
/// Findings: an exception other than SceneError, std::invalid_argument or a
/// nlohmann::json exception; any crash, ASan or UBSan report, leak, timeout or
/// out-of-memory (an override may ask for a mesh too large to allocate: the
/// size must be refused with a SceneError before allocation).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "drivers/app/job.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path scene_dir = std::filesystem::path(FFP_SOURCE_DIR) / "data" / "scenes";
  static const ffp::json reference = ffp::load_scene_file((scene_dir / "ffp_reference.json").string());
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  ffp::fuzz::expect_only_rejections([&] {
    ffp::json scene = reference;
    for (std::string assignment; std::getline(lines, assignment);) ffp::apply_override(scene, assignment);
    ffp::json echo;
    ffp::make_job(scene, scene_dir, echo);
  });
  return 0;
}
