#include "calibration/bounded_least_squares.hpp"

#include <cmath>
#include <exception>
#include <map>
#include <stdexcept>

#include <ceres/cost_function.h>
#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/types.h>
#include <Eigen/Dense>

namespace ffp {

namespace {

/// The model on parameters scaled to their bounds, u = (x − lower)/(upper − lower) ∈ [0, 1],
/// so that Ceres' trust region and tolerances treat each parameter alike. Every point is
/// evaluated once: Ceres asks again for a point it has (the Jacobian at an accepted step).
class BatchedModel {
 public:
  BatchedModel(const std::vector<FitParameter>& parameters, int residual_count, const BatchEvaluator& evaluate)
      : parameters_(parameters), residual_count_(residual_count), evaluate_(evaluate) {}

  std::vector<double> to_x(const double* u) const {
    std::vector<double> x(parameters_.size());
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = parameters_[j].lower + u[j] * range(j);
    return x;
  }
  double range(std::size_t j) const { return parameters_[j].upper - parameters_[j].lower; }

  /// The forward-difference neighbour along j (backward where the step would leave the bounds).
  std::vector<double> neighbour(const std::vector<double>& x, std::size_t j) const {
    std::vector<double> y = x;
    const double step = parameters_[j].step;
    y[j] = x[j] + step <= parameters_[j].upper ? x[j] + step : x[j] - step;
    return y;
  }

  /// Residuals at x and, when asked, at its p neighbours; false if any failed.
  bool residuals(const std::vector<double>& x, bool with_neighbours, std::vector<const std::vector<double>*>& out) {
    std::vector<std::vector<double>> wanted = {x};
    if (with_neighbours)
      for (std::size_t j = 0; j < parameters_.size(); ++j) wanted.push_back(neighbour(x, j));
    std::vector<std::vector<double>> missing;
    for (const auto& point : wanted)
      if (!cache_.contains(point)) missing.push_back(point);
    if (!missing.empty()) {
      const std::vector<std::vector<double>> results = evaluate_(missing);
      if (results.size() != missing.size()) throw std::logic_error("the batch evaluator returned the wrong count");
      for (std::size_t k = 0; k < missing.size(); ++k) {
        if (!results[k].empty() && results[k].size() != static_cast<std::size_t>(residual_count_))
          throw std::logic_error("the batch evaluator returned the wrong number of residuals");
        cache_[missing[k]] = results[k];
      }
    }
    out.clear();
    for (const auto& point : wanted) {
      const std::vector<double>& r = cache_.at(point);
      if (r.empty()) return false;
      out.push_back(&r);
    }
    return true;
  }

  /// What the evaluator threw (an interrupt, a broken run folder): not thrown through Ceres,
  /// which is not written for it, but kept, the fit stopped, and rethrown after Solve.
  const std::exception_ptr& pending() const { return pending_; }
  void keep(std::exception_ptr e) {
    if (!pending_) pending_ = std::move(e);
  }

  int evaluations() const { return static_cast<int>(cache_.size()); }
  int residual_count() const { return residual_count_; }
  const std::vector<FitParameter>& parameters() const { return parameters_; }

 private:
  const std::vector<FitParameter>& parameters_;
  int residual_count_;
  const BatchEvaluator& evaluate_;
  std::map<std::vector<double>, std::vector<double>> cache_;
  std::exception_ptr pending_;
};

class BatchedCost final : public ceres::CostFunction {
 public:
  explicit BatchedCost(BatchedModel& model) : model_(model) {
    set_num_residuals(model.residual_count());
    mutable_parameter_block_sizes()->push_back(static_cast<int>(model.parameters().size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::vector<double> x = model_.to_x(parameters[0]);
    const bool jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    std::vector<const std::vector<double>*> r;
    if (model_.pending()) return false;
    try {
      if (!model_.residuals(x, jacobian, r)) return false;
    } catch (...) {
      model_.keep(std::current_exception());
      return false;
    }
    const std::size_t n = r[0]->size(), p = x.size();
    std::copy(r[0]->begin(), r[0]->end(), residuals);
    if (jacobian) {
      for (std::size_t j = 0; j < p; ++j) {
        const double du = (model_.neighbour(x, j)[j] - x[j]) / model_.range(j);
        for (std::size_t i = 0; i < n; ++i) jacobians[0][i * p + j] = ((*r[j + 1])[i] - (*r[0])[i]) / du;
      }
    }
    return true;
  }

 private:
  BatchedModel& model_;
};

class RecordIterations final : public ceres::IterationCallback {
 public:
  RecordIterations(const BatchedModel& model, const std::vector<double>& u, std::vector<FitIteration>& history)
      : model_(model), u_(u), history_(history) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (model_.pending()) return ceres::SOLVER_ABORT;
    if (summary.step_is_successful || summary.iteration == 0)
      history_.push_back({summary.iteration, summary.cost, model_.to_x(u_.data())});
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const BatchedModel& model_;
  const std::vector<double>& u_;
  std::vector<FitIteration>& history_;
};

}  // namespace

BoundedFit fit_bounded_least_squares(const std::vector<FitParameter>& parameters, int residual_count,
                                     const BatchEvaluator& evaluate, const BoundedFitSettings& settings) {
  if (parameters.empty()) throw std::invalid_argument("no parameter to fit");
  if (residual_count < 1) throw std::invalid_argument("no residual to fit");
  for (const FitParameter& q : parameters) {
    if (!(q.lower < q.upper)) throw std::invalid_argument(q.name + ": lower must be below upper");
    if (!(q.initial >= q.lower && q.initial <= q.upper))
      throw std::invalid_argument(q.name + ": initial is outside its bounds");
    if (!(q.step > 0.0 && q.step < q.upper - q.lower))
      throw std::invalid_argument(q.name + ": step must be > 0 and < upper − lower");
  }
  BatchedModel model(parameters, residual_count, evaluate);
  const std::size_t p = parameters.size();
  std::vector<double> u(p);
  for (std::size_t j = 0; j < p; ++j) u[j] = (parameters[j].initial - parameters[j].lower) / model.range(j);

  BoundedFit fit;
  ceres::Problem problem;
  problem.AddResidualBlock(new BatchedCost(model), nullptr, u.data());
  for (std::size_t j = 0; j < p; ++j) {
    problem.SetParameterLowerBound(u.data(), static_cast<int>(j), 0.0);
    problem.SetParameterUpperBound(u.data(), static_cast<int>(j), 1.0);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = settings.function_tolerance;
  options.parameter_tolerance = settings.parameter_tolerance;
  options.update_state_every_iteration = true;
  RecordIterations recorder(model, u, fit.history);
  options.callbacks.push_back(&recorder);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (model.pending()) std::rethrow_exception(model.pending());
  if (summary.termination_type == ceres::FAILURE && fit.history.empty())
    throw std::runtime_error("the model failed at the initial point: " + summary.message);

  fit.values = model.to_x(u.data());
  fit.initial_cost = summary.initial_cost;
  fit.final_cost = summary.final_cost;
  fit.iterations = static_cast<int>(summary.iterations.size()) - 1;
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.termination = ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;

  // Standard errors from the forward-difference Jacobian at the solution, in the parameters' units.
  std::vector<const std::vector<double>*> r;
  const bool have = model.residuals(fit.values, true, r);
  fit.evaluations = model.evaluations();
  fit.standard_errors.assign(p, std::nullopt);
  if (!have) return fit;
  fit.residuals = *r[0];
  const std::size_t n = fit.residuals.size();
  Eigen::MatrixXd J(n, p);
  for (std::size_t j = 0; j < p; ++j) {
    const double dx = model.neighbour(fit.values, j)[j] - fit.values[j];
    for (std::size_t i = 0; i < n; ++i) J(i, j) = ((*r[j + 1])[i] - (*r[0])[i]) / dx;
  }
  fit.jacobian.assign(n, std::vector<double>(p));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < p; ++j)
      fit.jacobian[i][j] = J(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  if (n <= p) return fit;
  double ssr = 0.0;
  for (double v : fit.residuals) ssr += v * v;
  const double s2 = ssr / static_cast<double>(n - p);
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(JtJ);
  const double smallest = svd.singularValues()(static_cast<Eigen::Index>(p) - 1);
  if (!(smallest > 1e-12 * svd.singularValues()(0))) return fit;
  const Eigen::MatrixXd covariance = s2 * JtJ.inverse();
  fit.correlation.assign(p, std::vector<double>(p));
  for (std::size_t j = 0; j < p; ++j) {
    fit.standard_errors[j] = std::sqrt(covariance(j, j));
    for (std::size_t k = 0; k < p; ++k)
      fit.correlation[j][k] = covariance(j, k) / std::sqrt(covariance(j, j) * covariance(k, k));
  }
  return fit;
}

}  // namespace ffp
