#pragma once
/// A scene kind (`point`, `triaxial`, `calibration`, `ffp`, `cpt`) is a factory
/// that reads and validates its keys into a Job; the program runs the Job into
/// a temporary output directory and writes summary.json around it.
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/app/run_cost.hpp"
#include "drivers/scene/scene_reader.hpp"

namespace ffp {

struct RunContext {
  std::filesystem::path out_dir;    ///< temporary directory to write into
  std::filesystem::path scene_dir;  ///< folder of the scene file (relative paths in scenes start here)
  bool show_progress = true;
  json summary = json::object();  ///< the figures the job reports
  long steps = 0;                 ///< increments or time steps taken
  /// Runs a job may start as `ffp run` processes of its own (an inverse fit's model runs):
  /// at most this many at once (0: one per core), on this machine or through Slurm.
  int jobs = 0;
  bool slurm = false;
};

/// A run that failed numerically (not bad input): exit code 1. When
/// `reproducer` is an object, the program saves it as a scene that repeats the
/// failing step.
class RunFailure : public std::runtime_error {
 public:
  explicit RunFailure(const std::string& message, json reproducer = nullptr)
      : std::runtime_error(message), reproducer_(std::move(reproducer)) {}
  const json& reproducer() const { return reproducer_; }

 private:
  json reproducer_;
};

class Job {
 public:
  virtual ~Job() = default;
  virtual void run(RunContext& context) = 0;
  /// What `ffp check` prints beyond "valid" (e.g. the time step and its limit).
  virtual void describe(std::ostream&) const {}
  /// What a run will cost (run_cost.hpp): an MPM kind's steps and particles, with `measure`
  /// also a probe's rate (which steps the job's model and then builds it afresh, so that the
  /// run starts as if never probed); none for the kinds that take seconds.
  virtual std::optional<RunCost> cost(bool /*measure*/) { return std::nullopt; }
};

/// Reads the kind's keys from the top-level scene reader (kind and name are
/// already read) and finish()es it. Throws SceneError on bad input.
using JobFactory = std::unique_ptr<Job> (*)(SceneReader& scene, const std::filesystem::path& scene_dir);

struct KindEntry {
  std::string_view kind;
  std::string_view description;
  JobFactory make;
};

/// Every kind this build can run.
const std::vector<KindEntry>& registered_kinds();

/// The kinds' names, each between `open` and `close`, comma separated.
std::string kind_list(std::string_view open, std::string_view close);

/// The scene's `name` (the kind when absent): make_job reads it, and a kind's reader
/// that needs its value reads it again through this, with the same Doc.
std::string read_scene_name(SceneReader& scene, std::string_view kind);

/// Validate a scene (overrides already applied): returns the job and fills `echo`;
/// `log`, when given, collects every key the kind's readers know.
std::unique_ptr<Job> make_job(const json& scene, const std::filesystem::path& scene_dir, json& echo,
                              KeyLog* log = nullptr);

}  // namespace ffp
