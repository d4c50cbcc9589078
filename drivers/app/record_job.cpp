/// The `record` scene kind: a measured FFP drop interpreted (drivers/ffp_record.hpp).
///
/// Its keys are read in record_scene.cpp, each declared where it is read: `ffp keys record`.
/// Refuses records no penetrometer impact can produce and flags unlikely ones
/// (drivers/record_plausibility.hpp): each doubt goes to stderr and, only when
/// there is one, to the summary's `warnings`.
/// Writes history.csv (drivers/app/record_output.hpp), plots/depth_profiles.png and the summary.
#include <cstdio>
#include <memory>
#include <ostream>

#include "drivers/app/kinds.hpp"
#include "drivers/app/record_output.hpp"
#include "drivers/app/record_scene.hpp"
#include "drivers/record_plausibility.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

class RecordJob : public Job {
 public:
  RecordJob(std::string name, RecordScene scene, RecordSamples samples, InterpretedRecord record,
            std::vector<std::string> warnings)
      : name_(std::move(name)),
        scene_(std::move(scene)),
        samples_(std::move(samples)),
        record_(std::move(record)),
        warnings_(std::move(warnings)) {}

  void describe(std::ostream& out) const override {
    out << "record: " << samples_.time_s.size() << " samples of " << samples_.channel << " from "
        << samples_.time_s.front() << " to " << samples_.time_s.back() << " s\n";
    for (const std::string& w : warnings_) out << "warning: " << w << "\n";
  }

  void run(RunContext& context) override {
    for (const std::string& w : warnings_)
      std::fprintf(stderr, "warning: %s: %s\n", scene_.record_csv.string().c_str(), w.c_str());
    std::vector<std::pair<std::string, std::vector<double>>> extra;
    if (samples_.pore_pressure_kPa) {
      const auto& u = *samples_.pore_pressure_kPa;
      extra.push_back(
          {"pore_pressure_kPa", std::vector<double>(u.begin() + static_cast<long>(record_.impact_index) + 1, u.end())});
    }
    record_table(record_, scene_.settings, extra).write(context.out_dir / "history.csv");
    context.summary = record_summary(record_, scene_.settings);
    context.summary["samples"] = samples_.time_s.size();
    context.summary["channel"] = samples_.channel;
    // Only a record that raised doubts carries the key, so a clean record's summary stays as it was.
    if (!warnings_.empty()) context.summary["warnings"] = warnings_;
    context.steps = static_cast<long>(record_.time_s.size());
    fs::create_directories(context.out_dir / "plots");
    write_record_plots(record_, scene_.settings, name_, context.out_dir / "plots" / "depth_profiles.png");
  }

 private:
  std::string name_;
  RecordScene scene_;
  RecordSamples samples_;
  InterpretedRecord record_;
  std::vector<std::string> warnings_;
};

}  // namespace

std::unique_ptr<Job> make_record_job(SceneReader& scene, const fs::path& scene_dir) {
  std::string name = read_scene_name(scene, "record");
  RecordScene record = read_record_scene(scene, scene_dir);
  scene.finish("a record scene");
  RecordSamples samples = load_record(record);
  // Interpreted and checked here, so a record no impact can produce is bad input (exit 2) before any output.
  InterpretedRecord interpreted;
  std::vector<std::string> warnings;
  try {
    interpreted = interpret_record(samples.time_s, samples.deceleration_g, record.settings);
    warnings = check_impact_kinematics(interpreted, record.settings.gravity_m_s2, samples.channel);
  } catch (const RecordError& e) {
    throw SceneError(record.record_csv.string() + ": " + e.what());
  }
  return std::make_unique<RecordJob>(std::move(name), std::move(record), std::move(samples), std::move(interpreted),
                                     std::move(warnings));
}

}  // namespace ffp
