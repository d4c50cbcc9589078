/// The `calibration` scene kind run: the fit of the SSMC softening factor η
/// (calibration/softening_calibration.hpp) on the scene's numerical triaxial,
/// the other mode's fit and the compare_eta curves. The keys are read in
/// calibration_scene.hpp; calibration_output.hpp writes the results.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>
#include <ostream>
#include <thread>

#include "drivers/app/calibration_output.hpp"
#include "drivers/app/calibration_scene.hpp"
#include "drivers/app/job.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/memory_check.hpp"
#include "drivers/output/interrupt.hpp"
#include "mpm/simulation.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

CalibrationMode other(CalibrationMode mode) {
  return mode == CalibrationMode::dissipated_work ? CalibrationMode::curve_least_squares
                                                  : CalibrationMode::dissipated_work;
}

class CalibrationJob : public Job {
 public:
  explicit CalibrationJob(CalibrationScene spec) : spec_(std::move(spec)) {}

  void describe(std::ostream& out) const override {
    out << "calibration: η of the ssmc by " << to_string(spec_.settings.mode) << " on " << spec_.lab_file.string()
        << " (" << spec_.lab.axial_strain.size() << " points, ε_a to " << spec_.lab.axial_strain.back() << "), η in ["
        << spec_.settings.eta_min << ", " << spec_.settings.eta_max << "], ";
    if (spec_.specimen == SpecimenType::element) {
      out << "element test with " << spec_.test.increments << " increments\n";
    } else {
      const MpmTriaxialConfig& m = spec_.mpm;
      out << "MPM specimen with " << m.cell_m << " m cells (" << to_string(m.platens) << " platens at "
          << m.platen_velocity_m_s << " m/s)\n";
      describe_memory(out, specimen_size(m));
    }
  }

  void run(RunContext& context) override {
    const bool mpm = spec_.specimen == SpecimenType::mpm;
    const NumericalTriaxial triaxial = mpm ? mpm_triaxial_specimen(spec_.material, spec_.mpm,
                                                                   [this](double eta, const MpmTriaxialResult& r) {
                                                                     record(eta, r);
                                                                     // Ctrl-C waits for one run at most (≤ ~15 s at 0.5
                                                                     // cm).
                                                                     throw_if_interrupted();
                                                                   })
                                           : element_test_triaxial(spec_.material, spec_.test);
    // One store of runs for both fits and the compare_eta curves: no η runs twice. The
    // MPM specimen's runs go side by side (--jobs, default one per core); the element
    // test's take milliseconds and stay on this thread.
    const int concurrency = !mpm               ? 1
                            : context.jobs > 0 ? context.jobs
                                               : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    SpecimenRuns runs(triaxial, concurrency);
    const CalibrationResult result = calibrate(runs, spec_.settings);
    throw_if_interrupted();
    std::optional<CalibrationResult> second;
    if (spec_.compare_modes) {
      CalibrationSettings s = spec_.settings;
      s.mode = other(s.mode);
      second = calibrate(runs, s);
    }
    std::vector<std::pair<double, SpecimenCurve>> compared;
    run_specimens(runs, spec_.compare_eta);
    for (double eta : spec_.compare_eta) compared.emplace_back(eta, runs.at(eta));
    if (spec_.specimen == SpecimenType::element) {
      context.steps = static_cast<long>(runs.runs()) * spec_.test.increments;
    } else {
      context.steps = 0;
      for (const MpmRunRecord& r : runs_) context.steps += r.steps;
    }

    if (!result.work_decreases_with_eta)
      std::fprintf(stderr,
                   "warning: W(η) does not decrease strictly along the scan (see work_scan.csv): "
                   "the dissipated-work criterion may match more than one η\n");
    if (result.at_bound)
      std::fprintf(stderr, "warning: the fitted η = %s lies on a bound of [%s, %s]\n",
                   format_significant(result.eta).c_str(), format_significant(spec_.settings.eta_min).c_str(),
                   format_significant(spec_.settings.eta_max).c_str());

    CalibrationOutcome outcome{result, std::move(second), std::move(compared), runs_,
                               grid_,  runs.runs(),       runs.concurrency()};
    write_calibration_summary(spec_, outcome, context.summary);
    write_calibration_tables(spec_, outcome, context.out_dir);
    write_calibration_plots(spec_, outcome, context.out_dir);
  }

 private:
  CalibrationResult calibrate(SpecimenRuns& runs, const CalibrationSettings& settings) const {
    try {
      return calibrate_softening_factor(spec_.lab, runs, settings);
    } catch (const CalibrationFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) + "): " + e.what());
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) +
                       "): the element test failed: " + e.what());
    } catch (const mpm::StepFailure& e) {
      throw RunFailure(std::string("calibration (") + to_string(settings.mode) +
                       "): the MPM specimen failed: " + e.what());
    }
  }

  static void run_specimens(SpecimenRuns& runs, const std::vector<double>& etas) {
    // run_all rethrows the first failure in the order of etas: the first η still not run.
    auto failed = [&] {
      const auto eta = std::find_if(etas.begin(), etas.end(), [&](double e) { return !runs.has(e); });
      return eta == etas.end() ? std::string("?") : format_significant(*eta);
    };
    try {
      runs.run_all(etas);
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure("calibration: the element test with η = " + failed() + " failed: " + e.what());
    } catch (const mpm::StepFailure& e) {
      throw RunFailure("calibration: the MPM specimen with η = " + failed() + " failed: " + e.what());
    }
  }

  // Called from the runs' threads.
  void record(double eta, const MpmTriaxialResult& r) {
    const std::lock_guard lock(record_mutex_);
    MpmRunRecord k;
    k.eta = eta;
    k.steps = r.steps;
    k.wall_time_s = r.wall_time_s;
    k.platen_force_imbalance = r.platen_force_imbalance;
    k.bulge_at_peak[0] = r.bulge_at_peak_min;
    k.bulge_at_peak[1] = r.bulge_at_peak_max;
    k.bulge_at_end[0] = r.bulge_at_end_min;
    k.bulge_at_end[1] = r.bulge_at_end_max;
    k.work_steps_J = r.work_steps_J;
    k.work_curve_J = r.work_curve_J;
    k.work_piston_J = r.work_piston_J;
    k.wall_clamps = r.wall_clamps;
    runs_.push_back(k);
    grid_ = {r.cells_r, r.cells_z, r.cell_r_m, r.cell_z_m, r.particles, r.ramp_time_s};
  }

  CalibrationScene spec_;
  std::mutex record_mutex_;
  std::vector<MpmRunRecord> runs_;
  SpecimenGrid grid_;
};

}  // namespace

std::unique_ptr<Job> make_calibration_job(SceneReader& scene, const fs::path& scene_dir) {
  return std::make_unique<CalibrationJob>(read_calibration_scene(scene, scene_dir));
}

}  // namespace ffp
