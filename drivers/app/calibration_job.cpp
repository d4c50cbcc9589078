/// The `calibration` scene kind run: the fit of the SSMC softening factor η
/// (calibration/softening_calibration.hpp) on the scene's numerical triaxial,
/// the other mode's fit and the compare_eta curves. The keys are read in
/// calibration_scene.hpp; calibration_output.hpp writes the results.
#include <cstdio>
#include <memory>
#include <ostream>

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
    const NumericalTriaxial triaxial =
        spec_.specimen == SpecimenType::element
            ? element_test_triaxial(spec_.material, spec_.test)
            : mpm_triaxial_specimen(spec_.material, spec_.mpm, [this](double eta, const MpmTriaxialResult& r) {
                record(eta, r);
                // Ctrl-C waits for one run at most (≤ ~15 s at 0.5 cm).
                throw_if_interrupted();
              });
    const CalibrationResult result = calibrate(triaxial, spec_.settings);
    throw_if_interrupted();
    std::optional<CalibrationResult> second;
    if (spec_.compare_modes) {
      CalibrationSettings s = spec_.settings;
      s.mode = other(s.mode);
      second = calibrate(triaxial, s);
    }
    std::vector<std::pair<double, SpecimenCurve>> compared;
    for (double eta : spec_.compare_eta) compared.emplace_back(eta, run_specimen(triaxial, eta));
    if (spec_.specimen == SpecimenType::element) {
      context.steps =
          static_cast<long>(result.model_runs + (second ? second->model_runs : 0) + static_cast<int>(compared.size())) *
          spec_.test.increments;
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

    CalibrationOutcome outcome{result, std::move(second), std::move(compared), runs_, grid_};
    write_calibration_summary(spec_, outcome, context.summary);
    write_calibration_tables(spec_, outcome, context.out_dir);
    write_calibration_plots(spec_, outcome, context.out_dir);
  }

 private:
  CalibrationResult calibrate(const NumericalTriaxial& triaxial, const CalibrationSettings& settings) const {
    try {
      return calibrate_softening_factor(spec_.lab, triaxial, settings);
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

  static SpecimenCurve run_specimen(const NumericalTriaxial& triaxial, double eta) {
    try {
      return triaxial(eta);
    } catch (const PointIntegrationFailure& e) {
      throw RunFailure("calibration: the element test with η = " + format_significant(eta) + " failed: " + e.what());
    } catch (const mpm::StepFailure& e) {
      throw RunFailure("calibration: the MPM specimen with η = " + format_significant(eta) + " failed: " + e.what());
    }
  }

  void record(double eta, const MpmTriaxialResult& r) {
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
  std::vector<MpmRunRecord> runs_;
  SpecimenGrid grid_;
};

}  // namespace

std::unique_ptr<Job> make_calibration_job(SceneReader& scene, const fs::path& scene_dir) {
  return std::make_unique<CalibrationJob>(read_calibration_scene(scene, scene_dir));
}

}  // namespace ffp
