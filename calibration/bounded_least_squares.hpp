#pragma once
/// A Ceres least-squares fit of a few bounded parameters whose model is costly
/// and run in batches: the evaluator receives every point a step needs (the
/// point, and for a Jacobian its forward-difference neighbours) at once, so the
/// caller can run them side by side (an MPM run per point, as the `inverse`
/// kind does). Standard errors from the Jacobian at the solution,
/// cov = s² (JᵀJ)⁻¹ with s² = Σr²/(n − p): the residuals are taken to carry
/// independent noise of one common size, which the fit estimates.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ffp {

struct FitParameter {
  std::string name;
  double initial = 0.0, lower = 0.0, upper = 1.0;
  double step = 0.0;  ///< forward-difference step (> 0), in the parameter's unit
};

struct FitIteration {
  int iteration = 0;
  double cost = 0.0;  ///< ½ Σ r²
  std::vector<double> values;
};

struct BoundedFit {
  std::vector<double> values;
  std::vector<std::optional<double>> standard_errors;  ///< absent when n ≤ p or JᵀJ is singular
  std::vector<std::vector<double>> correlation;        ///< empty when the errors are absent
  std::vector<double> residuals;                       ///< at the solution
  /// ∂r_i/∂x_j at the solution (n × p, forward differences over each parameter's step, in the
  /// parameters' units); empty when the model failed there.
  std::vector<std::vector<double>> jacobian;
  double initial_cost = 0.0, final_cost = 0.0;
  int iterations = 0;
  int evaluations = 0;  ///< distinct points evaluated
  bool converged = false;
  std::string termination;
  std::vector<FitIteration> history;
};

/// Residuals at each point of a batch; an empty vector marks a point whose model failed.
using BatchEvaluator = std::function<std::vector<std::vector<double>>(const std::vector<std::vector<double>>& points)>;

struct BoundedFitSettings {
  int max_iterations = 20;
  double function_tolerance = 1e-4;   ///< relative change of the cost that ends the fit
  double parameter_tolerance = 1e-4;  ///< relative step, on parameters scaled to their bounds
};

/// Throws std::invalid_argument for bad bounds or steps, std::runtime_error when
/// the model fails at the initial point; what the evaluator throws (e.g. an
/// interrupt) stops the fit and is rethrown as it was.
BoundedFit fit_bounded_least_squares(const std::vector<FitParameter>& parameters, int residual_count,
                                     const BatchEvaluator& evaluate, const BoundedFitSettings& settings = {});

}  // namespace ffp
