/// The `inverse` scene kind: soil (and contact) parameters of an `ffp` scene
/// fitted by Ceres so that the MPM's deceleration against depth matches a
/// record (its keys: `ffp keys inverse`). Every model point is an
/// independent `ffp run` process with its own folder under runs/ (a
/// forward-difference Jacobian's p + 1 runs side by side, --jobs N, or as a
/// Slurm job array with --scheduler slurm); model and record go through the
/// same interpretation (record.csv of each run, drivers/ffp_record.hpp).
///
/// Writes summary.json (the parameters with standard errors, misfit, runs,
/// iterations), history.csv (cost and parameters per accepted iteration),
/// profile.csv (the record, the starting and the fitted run at the fit's
/// depths), plots/fit.png, and runs/<each model run>.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <ostream>
#include <thread>

#include "drivers/app/inverse_scene.hpp"
#include "drivers/app/kinds.hpp"
#include "drivers/app/program_version.hpp"
#include "drivers/app/record_output.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/output/interrupt.hpp"
#include "drivers/record_plausibility.hpp"
#include "drivers/triaxial_test.hpp"
#include "reports/plot.hpp"
#include "reports/run_pool.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

/// A deceleration–depth curve's loading branch: the rows up to the deepest point.
struct Profile {
  std::vector<double> depth_m, deceleration_g;

  static Profile loading_branch(const std::vector<double>& depth, const std::vector<double>& deceleration) {
    Profile p;
    if (depth.empty()) return p;
    const std::size_t deepest = static_cast<std::size_t>(std::max_element(depth.begin(), depth.end()) - depth.begin());
    for (std::size_t k = 0; k <= deepest; ++k) {
      if (!p.depth_m.empty() && depth[k] <= p.depth_m.back()) continue;  // keep depth increasing
      p.depth_m.push_back(depth[k]);
      p.deceleration_g.push_back(deceleration[k]);
    }
    return p;
  }

  /// Linear interpolation; beyond the deepest point, the value there (a run that
  /// stops short keeps a continuous misfit as a parameter moves).
  double at(double z) const {
    return interpolate_linear(depth_m, deceleration_g, std::clamp(z, depth_m.front(), depth_m.back()));
  }
};

struct ModelRun {
  Profile profile;
  double peak_deceleration_g = 0.0, final_penetration_m = 0.0;
};

ModelRun read_model_run(const fs::path& dir) {
  const CsvData record = read_numeric_csv(dir / "record.csv");
  ModelRun run;
  run.profile = Profile::loading_branch(record.column("penetration_m"), record.column("deceleration_g"));
  std::ifstream in(dir / "summary.json");
  const json summary = json::parse(in);
  run.peak_deceleration_g = summary.at("peak_deceleration_g").get<double>();
  run.final_penetration_m = summary.at("final_penetration_m").get<double>();
  return run;
}

class InverseJob : public Job {
 public:
  InverseJob(std::string name, InverseScene scene, std::optional<InterpretedRecord> record)
      : name_(std::move(name)), scene_(std::move(scene)), record_(std::move(record)) {
    if (scene_.profile) {
      target_ = Profile::loading_branch(record_->penetration_m, record_->deceleration_g);
      const double deepest = target_.depth_m.back();
      for (int i = 0; i < scene_.profile_points; ++i) depths_.push_back(deepest * (i + 0.5) / scene_.profile_points);
    }
  }

  void describe(std::ostream& out) const override {
    out << "inverse: " << scene_.parameters.size() << " parameter(s) of " << scene_.forward_scene.string() << "; "
        << residual_count() << " residuals";
    if (scene_.profile)
      out << " (" << scene_.profile_points << " profile depths to " << target_.depth_m.back() << " m)";
    out << "; each Jacobian is " << scene_.parameters.size() + 1 << " runs side by side\n";
  }

  /// One model run's cost (the forward scene at the initial values), and how many runs the
  /// fit makes at most: (p + 1) at the start and up to p + 1 per iteration (a trial point and,
  /// once accepted, its p neighbours), unless the bounds' line search asks for trial points of
  /// its own.
  std::optional<RunCost> cost(bool measure) override {
    const RunRequest initial = request(initial_values());
    json forward = load_scene_file(initial.scene_file.string());
    for (const std::string& o : initial.overrides) apply_override(forward, o);
    json echo;
    std::optional<RunCost> one = make_job(forward, initial.scene_file.parent_path(), echo)->cost(measure);
    if (one) one->runs = static_cast<long>((scene_.fit.max_iterations + 1) * (scene_.parameters.size() + 1));
    return one;
  }

  void run(RunContext& context) override;

 private:
  std::vector<double> initial_values() const {
    std::vector<double> x;
    for (const FitParameter& q : scene_.parameters) x.push_back(q.initial);
    return x;
  }

  /// The residual rows of each target, in the order residuals() gives them.
  struct TargetRows {
    std::string name;
    std::size_t first = 0, count = 0;
  };
  std::vector<TargetRows> targets() const {
    std::vector<TargetRows> t;
    std::size_t next = 0;
    auto add = [&](const char* name, std::size_t count) {
      t.push_back({name, next, count});
      next += count;
    };
    if (scene_.profile) add("profile", static_cast<std::size_t>(scene_.profile_points));
    if (scene_.peak_deceleration_g) add("peak_deceleration", 1);
    if (scene_.final_penetration_m) add("final_penetration", 1);
    return t;
  }
  void require_identifiable(const BoundedFit& fit) const;

  int residual_count() const {
    return (scene_.profile ? scene_.profile_points : 0) + (scene_.peak_deceleration_g ? 1 : 0) +
           (scene_.final_penetration_m ? 1 : 0);
  }

  std::vector<double> residuals(const ModelRun& run) const {
    std::vector<double> r;
    const double profile_factor = scene_.profile_weight / scene_.profile_scale_g / std::sqrt(scene_.profile_points);
    if (scene_.profile)
      for (double z : depths_) r.push_back(profile_factor * (run.profile.at(z) - target_.at(z)));
    if (const auto& t = scene_.peak_deceleration_g)
      r.push_back(t->weight * (run.peak_deceleration_g - t->value) / t->scale);
    if (const auto& t = scene_.final_penetration_m)
      r.push_back(t->weight * (run.final_penetration_m - t->value) / t->scale);
    return r;
  }

  RunRequest request(const std::vector<double>& x) const {
    return RunRequest{"ffp", scene_.forward_scene, model_run_overrides(scene_, x), 0.0};
  }

  std::string name_;
  InverseScene scene_;
  std::optional<InterpretedRecord> record_;
  Profile target_;
  std::vector<double> depths_;
};

/// A fit whose Jacobian says that no fitted parameter moves a target (or that a parameter
/// moves no target) cannot identify what it reports: its "convergence" is Ceres finding a
/// zero gradient. "Moves" is a change, over the parameter's difference step, above 1e-9 of
/// the target's residuals: record.csv carries 10 significant digits, so a smaller change is
/// the digits the runs are read with (a parameter the model ignores changes nothing at all).
void InverseJob::require_identifiable(const BoundedFit& fit) const {
  if (fit.jacobian.empty()) return;  // the model failed at the solution: said by the summary
  const std::vector<FitParameter>& parameters = scene_.parameters;
  std::vector<char> moves_a_target(parameters.size(), 0);
  std::string unmoved, norms;
  for (const TargetRows& target : targets()) {
    double residual_norm = 0.0;
    for (std::size_t i = target.first; i < target.first + target.count; ++i)
      residual_norm += fit.residuals[i] * fit.residuals[i];
    residual_norm = std::sqrt(residual_norm);
    bool moved = false;
    norms += (norms.empty() ? "" : "; ") + target.name + ":";
    for (std::size_t j = 0; j < parameters.size(); ++j) {
      double column = 0.0;  // |∂r/∂x_j| over the target's rows
      for (std::size_t i = target.first; i < target.first + target.count; ++i)
        column += fit.jacobian[i][j] * fit.jacobian[i][j];
      column = std::sqrt(column);
      char text[96];
      std::snprintf(text, sizeof text, " %s %.3g", parameters[j].name.c_str(), column);
      norms += text;
      if (column * parameters[j].step > 1e-9 * residual_norm) {
        moved = true;
        moves_a_target[j] = 1;
      }
    }
    if (!moved) unmoved += (unmoved.empty() ? "" : ", ") + target.name;
  }
  std::string idle;
  for (std::size_t j = 0; j < parameters.size(); ++j)
    if (!moves_a_target[j]) idle += (idle.empty() ? "" : ", ") + parameters[j].name;
  if (unmoved.empty() && idle.empty()) return;
  std::string problem;
  if (!unmoved.empty()) problem = "no fitted parameter moves the target " + unmoved;
  if (!idle.empty()) problem += (problem.empty() ? "" : "; ") + idle + " moves no target";
  throw RunFailure("inverse: not identifiable: " + problem +
                   " (Jacobian column norms |dr/dx| at the solution, per unit of each parameter: " + norms +
                   "); fit parameters that change every target, or drop the target");
}

void InverseJob::run(RunContext& context) {
  const fs::path runs = context.out_dir / "runs";
  const int jobs =
      context.jobs > 0 ? context.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const Scheduler scheduler = context.slurm ? Scheduler::slurm : Scheduler::local;
  int batches = 0, failed = 0;
  std::string last_failure;
  auto run_points = [&](const std::vector<std::vector<double>>& points) {
    std::vector<RunRequest> requests;
    for (const auto& x : points) requests.push_back(request(x));
    return run_all("/proc/self/exe", requests, runs, program_version(), jobs, scheduler);
  };
  const BatchEvaluator evaluate = [&](const std::vector<std::vector<double>>& points) {
    ++batches;
    if (context.show_progress)
      std::fprintf(stderr, "inverse %s: batch %d, %zu model run(s)\n", name_.c_str(), batches, points.size());
    const std::vector<RunOutcome> outcomes = run_points(points);
    std::vector<std::vector<double>> out;
    for (const RunOutcome& o : outcomes) {
      if (o.exit_code != 0) {
        ++failed;
        last_failure = o.error;
        out.emplace_back();  // Ceres steps around a point whose run failed
        continue;
      }
      try {
        const ModelRun run = read_model_run(o.out_dir);
        if (run.profile.depth_m.empty()) throw std::runtime_error("its record.csv has no row after the impact");
        out.push_back(residuals(run));
      } catch (const std::exception& e) {  // a run that finished but cannot be read: a failed point
        ++failed;
        last_failure = o.out_dir.filename().string() + ": " + e.what();
        out.emplace_back();
      }
    }
    return out;
  };
  BoundedFit fit;
  try {
    fit = fit_bounded_least_squares(scene_.parameters, residual_count(), evaluate, scene_.fit);
  } catch (const Interrupted&) {
    throw;  // Ctrl-C: exit 130, not a failed fit
  } catch (const std::runtime_error& e) {
    throw RunFailure(std::string("inverse: ") + e.what() +
                     (last_failure.empty() ? "" : " (last run error: " + last_failure + ")"));
  }
  require_identifiable(fit);

  const std::vector<RunOutcome> ends = run_points({initial_values(), fit.values});  // both cached by now
  const ModelRun start = read_model_run(ends[0].out_dir), fitted = read_model_run(ends[1].out_dir);

  // history.csv: the accepted iterations.
  std::vector<std::string> columns = {"iteration", "cost"};
  for (const FitParameter& q : scene_.parameters) columns.push_back(q.name);
  CsvTable history(columns);
  for (const FitIteration& it : fit.history) {
    std::vector<double> row = {static_cast<double>(it.iteration), it.cost};
    row.insert(row.end(), it.values.begin(), it.values.end());
    history.add_row(row);
  }
  history.write(context.out_dir / "history.csv");

  json& sum = context.summary;
  json parameters = json::object();
  for (std::size_t j = 0; j < scene_.parameters.size(); ++j) {
    const FitParameter& q = scene_.parameters[j];
    parameters[q.name] = {{"value", fit.values[j]},
                          {"standard_error", fit.standard_errors[j] ? json(*fit.standard_errors[j]) : json(nullptr)},
                          {"initial", q.initial},
                          {"lower", q.lower},
                          {"upper", q.upper},
                          {"step", q.step}};
  }
  sum["parameters"] = parameters;
  if (!fit.correlation.empty()) sum["correlation"] = fit.correlation;
  sum["cost_initial"] = fit.initial_cost;
  sum["cost_final"] = fit.final_cost;
  sum["residuals"] = fit.residuals.size();
  sum["iterations"] = fit.iterations;
  sum["converged"] = fit.converged;
  sum["termination"] = fit.termination;
  sum["model_runs"] = fit.evaluations;
  sum["failed_model_runs"] = failed;
  sum["run_batches"] = batches;
  sum["jobs"] = jobs;
  sum["scheduler"] = context.slurm ? "slurm" : "local";
  sum["fitted_run"] = fs::relative(ends[1].out_dir, context.out_dir).string();
  sum["initial_run"] = fs::relative(ends[0].out_dir, context.out_dir).string();
  sum["fitted_peak_deceleration_g"] = fitted.peak_deceleration_g;
  sum["fitted_final_penetration_m"] = fitted.final_penetration_m;
  sum["initial_peak_deceleration_g"] = start.peak_deceleration_g;
  sum["initial_final_penetration_m"] = start.final_penetration_m;
  if (record_) {
    sum["record_peak_deceleration_g"] = record_->peak_deceleration_g;
    sum["record_max_penetration_m"] = record_->max_penetration_m;
  }
  if (scene_.peak_deceleration_g) sum["target_peak_deceleration_g"] = scene_.peak_deceleration_g->value;
  if (scene_.final_penetration_m) sum["target_final_penetration_m"] = scene_.final_penetration_m->value;
  context.steps = fit.iterations;

  const fs::path plots = context.out_dir / "plots";
  fs::create_directories(plots);
  Plot p;
  p.title = name_ + ": deceleration against depth";
  p.x_label = "net deceleration (g)";
  p.y_label = "depth (m)";
  p.reverse_y = true;
  p.key_position = "bottom right";
  if (scene_.profile) {
    double squares = 0.0;
    CsvTable profile({"depth_m", "record_deceleration_g", "initial_deceleration_g", "fitted_deceleration_g"});
    for (double z : depths_) {
      profile.add_row({z, target_.at(z), start.profile.at(z), fitted.profile.at(z)});
      squares += std::pow(fitted.profile.at(z) - target_.at(z), 2);
    }
    profile.write(context.out_dir / "profile.csv");
    sum["profile_rms_misfit_g"] = std::sqrt(squares / static_cast<double>(depths_.size()));
    p.series.push_back({record_->deceleration_g, record_->penetration_m, "record", "points pointtype 7 pointsize 0.4"});
  }
  p.series.push_back({start.profile.deceleration_g, start.profile.depth_m, "starting run", "lines dashtype 2"});
  p.series.push_back({fitted.profile.deceleration_g, fitted.profile.depth_m, "fitted run"});
  write_png(p, plots / "fit.png");
}

}  // namespace

std::unique_ptr<Job> make_inverse_job(SceneReader& scene, const fs::path& scene_dir) {
  std::string name = read_scene_name(scene, "inverse");
  InverseScene inverse = read_inverse_scene(scene, scene_dir);
  scene.finish("an inverse scene");
  std::optional<InterpretedRecord> record;
  if (inverse.record) {
    const RecordSamples samples = load_record(*inverse.record);
    try {
      record = interpret_record(samples.time_s, samples.deceleration_g, inverse.record->settings);
      for (const std::string& w :
           check_impact_kinematics(*record, inverse.record->settings.gravity_m_s2, samples.channel))
        std::fprintf(stderr, "warning: %s: %s\n", inverse.record->record_csv.string().c_str(), w.c_str());
    } catch (const RecordError& e) {
      throw SceneError("record.record_csv: " + inverse.record->record_csv.string() + ": " + e.what());
    }
    if (inverse.profile && record->max_penetration_m <= 0.0)
      throw SceneError("record: the record never penetrates (its deepest point is at " +
                       std::to_string(record->max_penetration_m) + " m): nothing to match");
  }
  return std::make_unique<InverseJob>(std::move(name), std::move(inverse), std::move(record));
}

}  // namespace ffp
