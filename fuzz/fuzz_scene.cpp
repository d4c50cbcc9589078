/// Fuzzes the scene reader of every kind: the input is the text of a scene
/// file, parsed as `ffp run` parses it (parse_scene_text, an object required)
/// and validated by make_job. The job is never run.
///
/// Findings: an exception other than SceneError, std::invalid_argument or a
/// nlohmann::json exception; any crash, ASan or UBSan report, leak, timeout or
/// out-of-memory (a scene may ask for a mesh too large to allocate: the size
/// must be refused with a SceneError before allocation).
#include <cstddef>
#include <cstdint>
#include <string>

#include "drivers/app/job.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Relative paths in the seeds (lab curves, path tables) start where the scenes live.
  static const std::filesystem::path scene_dir = std::filesystem::path(FFP_SOURCE_DIR) / "data" / "scenes";
  const std::string text(reinterpret_cast<const char*>(data), size);
  ffp::fuzz::expect_only_rejections([&] {
    const ffp::json scene = ffp::parse_scene_text(text, "fuzz.json");
    if (!scene.is_object()) return;  // load_scene_file refuses it before make_job
    ffp::json echo;
    ffp::make_job(scene, scene_dir, echo);
  });
  return 0;
}
