/// Fuzzes the point kind's path table (`path.table_csv`): the input is the CSV
/// file, written to a scratch file of this process that a fixed general-path
/// point scene (Mohr-Coulomb sand starting at 1.72 kPa) names; make_job reads
/// and checks it. The job is never run.
///
/// Findings: an exception other than SceneError, std::invalid_argument or a
/// nlohmann::json exception; any crash, ASan or UBSan report, leak, timeout or
/// out-of-memory.
#include <cstddef>
#include <cstdint>

#include "drivers/app/job.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ffp::fuzz::ScratchFile file("path.csv");
  static const ffp::json scene = {
      {"kind", "point"},
      {"material", {{"model", "mohr_coulomb"}, {"E_kPa", 2500}, {"nu", 0.33}, {"phi_peak_deg", 50}}},
      {"initial_pressure_kPa", 1.72},
      {"path", {{"type", "general"}, {"table_csv", file.path.string()}, {"increments_per_row", 200}}}};
  file.write(data, size);
  ffp::fuzz::expect_only_rejections([&] {
    ffp::json echo;
    ffp::make_job(scene, file.path.parent_path(), echo);
  });
  return 0;
}
