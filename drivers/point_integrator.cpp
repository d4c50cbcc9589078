#include "drivers/point_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/LU>
#include <Eigen/QR>

namespace ffp {

namespace {

/// One law update on copies: what an increment Δε would do from (σ_n, state_n).
struct Evaluation {
  Voigt stress;
  MaterialState state;
  ReturnRegion region;
};

Evaluation evaluate(const PointLaw& law, const Voigt& stress_start, const MaterialState& state_start,
                    const Voigt& strain_increment, double dt) {
  Evaluation e{stress_start, state_start, ReturnRegion::elastic};
  e.region = update(law, e.stress, strain_increment, e.state, dt);
  return e;
}

/// Elastic stiffness as a 6×6 acting on tensor-shear Voigt vectors (Δσ_12 = 2G Δε_12).
Eigen::Matrix<double, 6, 6> elastic_matrix(const ElasticConstants& e) {
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  const double lambda = e.lame_lambda();
  const double g = e.shear_modulus();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d(i, j) = lambda;
    d(i, i) += 2.0 * g;
    d(i + 3, i + 3) = 2.0 * g;
  }
  return d;
}

/// Δε^e = C Δσ.
Voigt elastic_strain(const ElasticConstants& e, const Voigt& stress_increment) {
  const double mean = trace(stress_increment) / 3.0;
  Voigt out = deviator(stress_increment) / (2.0 * e.shear_modulus());
  for (int i = 0; i < 3; ++i) out[i] += mean / (3.0 * e.bulk_modulus());
  return out;
}

using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

/// One increment with mixed control, solved for the strain increments of the
/// stress-controlled components S, starting from (σ_n, state_n).
class MixedStep {
 public:
  struct Outcome {
    bool converged = false;
    SmallVector unknowns;
    Voigt strain_increment;
    Evaluation result;
    int iterations = 0;
    double residual = 0.0;
    double tolerance = 0.0;
  };

  MixedStep(const PointLaw& law, const ElasticConstants& elastic, const Eigen::Matrix<double, 6, 6>& stiffness,
            const PointRecord& start, const std::array<int, 6>& stress_components, int stress_count,
            const Voigt& prescribed_strain_increment, const Voigt& target_stress, double dt,
            const NewtonSettings& newton)
      : law_(law),
        elastic_(elastic),
        stiffness_(stiffness),
        start_(start),
        components_(stress_components),
        count_(stress_count),
        prescribed_(prescribed_strain_increment),
        target_(target_stress),
        dt_(dt),
        newton_(newton),
        elastic_block_(stress_count, stress_count) {
    for (int a = 0; a < count_; ++a)
      for (int b = 0; b < count_; ++b) elastic_block_(a, b) = stiffness_(components_[a], components_[b]);
  }

  /// Elastic predictor for a fraction of the step: D_SS Δε_S = Δσ_S − D_SE Δε_E.
  SmallVector elastic_guess(double fraction) const {
    const Voigt elastic_stress = start_.stress + stiffness_ * (fraction * prescribed_);
    SmallVector rhs(count_);
    for (int j = 0; j < count_; ++j) {
      const int i = components_[j];
      rhs[j] = start_.stress[i] + fraction * (target_[i] - start_.stress[i]) - elastic_stress[i];
    }
    return elastic_block_.partialPivLu().solve(rhs);
  }

  /// Newton with a finite-difference tangent and backtracking, on the step
  /// scaled by `fraction` (continuation uses fractions < 1).
  Outcome solve(SmallVector x, double fraction) const {
    const Voigt prescribed = fraction * prescribed_;
    Voigt target = Voigt::Zero();
    for (int j = 0; j < count_; ++j) {
      const int i = components_[j];
      target[i] = start_.stress[i] + fraction * (target_[i] - start_.stress[i]);
    }
    double stress_scale = start_.stress.cwiseAbs().maxCoeff();
    for (int j = 0; j < count_; ++j) stress_scale = std::max(stress_scale, std::abs(target[components_[j]]));
    stress_scale = std::max(stress_scale, 1e-9 * elastic_.youngs_modulus_Pa);

    Outcome out;
    out.tolerance = newton_.relative_tolerance * stress_scale;
    auto increment_of = [&](const SmallVector& unknowns) {
      Voigt increment = prescribed;
      for (int j = 0; j < count_; ++j) increment[components_[j]] = unknowns[j];
      return increment;
    };
    auto residual_of = [&](const Evaluation& e) {
      SmallVector r(count_);
      for (int j = 0; j < count_; ++j) r[j] = e.stress[components_[j]] - target[components_[j]];
      return r;
    };
    Voigt increment = increment_of(x);
    Evaluation result = evaluate(law_, start_.stress, start_.state, increment, dt_);
    SmallVector r = residual_of(result);
    double norm = r.cwiseAbs().maxCoeff();
    int iterations = 0;
    while (!(norm <= out.tolerance) && iterations < newton_.max_iterations && std::isfinite(norm)) {
      ++iterations;
      // Algorithmic tangent ∂σ_S/∂Δε_S of the whole increment, by forward differences.
      const double h = std::sqrt(std::numeric_limits<double>::epsilon()) *
                       std::max({increment.cwiseAbs().maxCoeff(), stress_scale / elastic_.youngs_modulus_Pa, 1e-12});
      SmallMatrix tangent(count_, count_);
      for (int j = 0; j < count_; ++j) {
        Voigt perturbed = increment;
        perturbed[components_[j]] += h;
        tangent.col(j) = (residual_of(evaluate(law_, start_.stress, start_.state, perturbed, dt_)) - r) / h;
      }
      // On a Mohr-Coulomb edge the two stresses held equal by the edge make the
      // tangent rank deficient (triaxial: only σ_r, not how ε11 and ε33 split,
      // is determined). The minimum-norm correction leaves the split where it
      // was (symmetric from a symmetric start) instead of drifting along the
      // null direction in the finite-difference noise (~1e-8 relative).
      Eigen::CompleteOrthogonalDecomposition<SmallMatrix> decomposition;
      decomposition.setThreshold(1e-6);
      decomposition.compute(tangent);
      // Where the response is flat (at the apex) nothing is left; the elastic block always solves.
      const SmallVector direction = decomposition.rank() > 0 ? SmallVector(-decomposition.solve(r))
                                                             : SmallVector(-elastic_block_.partialPivLu().solve(r));
      double alpha = 1.0;
      for (int backtrack = 0;; ++backtrack) {
        const SmallVector candidate = x + alpha * direction;
        const Voigt candidate_increment = increment_of(candidate);
        Evaluation e = evaluate(law_, start_.stress, start_.state, candidate_increment, dt_);
        const SmallVector candidate_r = residual_of(e);
        const double candidate_norm = candidate_r.cwiseAbs().maxCoeff();
        if (candidate_norm < norm || backtrack == 10) {
          x = candidate;
          increment = candidate_increment;
          result = std::move(e);
          r = candidate_r;
          norm = candidate_norm;
          break;
        }
        alpha *= 0.5;
      }
    }
    out.converged = norm <= out.tolerance;
    out.unknowns = x;
    out.strain_increment = increment;
    out.result = std::move(result);
    out.iterations = iterations;
    out.residual = norm;
    return out;
  }

 private:
  const PointLaw& law_;
  const ElasticConstants& elastic_;
  const Eigen::Matrix<double, 6, 6>& stiffness_;
  const PointRecord& start_;
  std::array<int, 6> components_;
  int count_;
  Voigt prescribed_;
  Voigt target_;
  double dt_;
  NewtonSettings newton_;
  SmallMatrix elastic_block_;
};

}  // namespace

PointHistory integrate_point(const PointConfig& config, const std::function<void(long, long)>& on_step) {
  if (config.initial_state.index() != config.law.index())
    throw std::invalid_argument("integrate_point: the initial state does not belong to the law");
  const ElasticConstants& elastic = elastic_constants(config.law);
  const Eigen::Matrix<double, 6, 6> stiffness = elastic_matrix(elastic);

  long total = 0;
  for (const auto& s : config.segments) total += s.increments;

  PointHistory history;
  PointRecord current;
  current.stress = config.initial_stress;
  current.state = config.initial_state;
  history.records.push_back(current);

  long step = 0;
  for (std::size_t segment_index = 0; segment_index < config.segments.size(); ++segment_index) {
    const PathSegment& segment = config.segments[segment_index];
    std::array<int, 6> stress_components{};
    int stress_count = 0;
    for (int i = 0; i < 6; ++i)
      if (segment.control[i] == Control::stress) stress_components[stress_count++] = i;
    const Voigt strain_at_start = current.strain;
    const Voigt stress_at_start = current.stress;
    const double dt = segment.duration_s / segment.increments;
    SmallVector previous_solution;  // Δε_S of the last increment: the best first guess in a steady leg

    for (int k = 1; k <= segment.increments; ++k) {
      ++step;
      const double fraction = static_cast<double>(k) / segment.increments;
      Voigt strain_increment = Voigt::Zero();
      Voigt target_stress = Voigt::Zero();
      for (int i = 0; i < 6; ++i) {
        const double start = segment.control[i] == Control::strain ? strain_at_start[i] : stress_at_start[i];
        const double goal = start + fraction * (segment.target[i] - start);
        if (segment.control[i] == Control::strain) {
          strain_increment[i] = goal - current.strain[i];
        } else {
          target_stress[i] = goal;
        }
      }

      Evaluation result;
      int iterations = 0;
      if (stress_count == 0) {
        result = evaluate(config.law, current.stress, current.state, strain_increment, dt);
      } else {
        const MixedStep mixed(config.law, elastic, stiffness, current, stress_components, stress_count,
                              strain_increment, target_stress, dt, config.newton);
        MixedStep::Outcome outcome =
            mixed.solve(previous_solution.size() == stress_count ? previous_solution : mixed.elastic_guess(1.0), 1.0);
        iterations = outcome.iterations;
        // Continuation when Newton cannot find the step from afar (e.g. a trial
        // deep in the apex region, where the response is flat): solve the same
        // single step scaled by 1/2^m, 2/2^m, ..., 1, each guess extrapolated
        // linearly from the last two. The accepted answer is still one law
        // update of the whole increment.
        for (int levels = 2; !outcome.converged && levels <= 12; levels += 2) {
          const int parts = 1 << levels;
          SmallVector before = SmallVector::Zero(stress_count), last = mixed.elastic_guess(1.0 / parts);
          double before_fraction = 0.0, last_fraction = 0.0;
          bool followed = true;
          for (int part = 1; part <= parts && followed; ++part) {
            const double f = static_cast<double>(part) / parts;
            const SmallVector guess =
                part <= 2
                    ? mixed.elastic_guess(f)
                    : SmallVector(last + (f - last_fraction) / (last_fraction - before_fraction) * (last - before));
            outcome = mixed.solve(guess, f);
            iterations += outcome.iterations;
            followed = outcome.converged;
            before = last;
            before_fraction = last_fraction;
            last = outcome.unknowns;
            last_fraction = f;
          }
        }
        if (!outcome.converged) {
          std::ostringstream message;
          message << "point integrator: increment " << step << " (segment " << segment_index + 1 << ", " << k << " of "
                  << segment.increments << ") did not converge in " << config.newton.max_iterations
                  << " Newton iterations, with continuation: stress residual " << outcome.residual << " Pa > tolerance "
                  << outcome.tolerance << " Pa (a stress target beyond the strength, or a path the law cannot follow)";
          PointIntegrationFailure failure(message.str());
          failure.step = step;
          failure.segment = static_cast<int>(segment_index);
          failure.stress_start = current.stress;
          failure.strain_start = current.strain;
          failure.state_start = current.state;
          failure.control = segment.control;
          failure.prescribed_strain_increment = strain_increment;
          failure.target_stress = target_stress;
          failure.last_strain_increment = outcome.strain_increment;
          failure.residual_Pa = outcome.residual;
          failure.dt_s = dt;
          throw failure;
        }
        strain_increment = outcome.strain_increment;
        result = std::move(outcome.result);
        previous_solution = outcome.unknowns;
      }

      const Voigt stress_increment = result.stress - current.stress;
      const Voigt mid_stress = current.stress + 0.5 * stress_increment;
      const Voigt plastic_strain = strain_increment - elastic_strain(elastic, stress_increment);
      current.step = step;
      current.time_s += dt;
      current.strain += strain_increment;
      current.stress = result.stress;
      current.state = result.state;
      current.region = result.region;
      current.newton_iterations = iterations;
      current.plastic_work_J_m3 += contract(mid_stress, plastic_strain);
      current.work_input_J_m3 += contract(mid_stress, strain_increment);
      history.max_newton_iterations = std::max(history.max_newton_iterations, iterations);
      if (step % std::max(config.record_every, 1L) == 0 || step == total) history.records.push_back(current);
      if (on_step) on_step(step, total);
    }
  }
  history.increments = step;
  return history;
}

}  // namespace ffp
