#pragma once
/// A single material point driven along a path on which each of the six
/// stress/strain components is either strain- or stress-controlled (the
/// element test of GEOS's TriaxialDriver and MFront's MTest).
///
/// Pure numerics: a typed config in, a typed history out; no files, no output.
/// Per increment the strain-controlled components are prescribed; the strain
/// increments of the stress-controlled ones are found by Newton on
/// σ_S(Δε) = σ_S,target with the algorithmic tangent of the whole increment
/// (forward differences of the law), a backtracking line search, and a bounded
/// number of iterations. A step that does not converge throws
/// PointIntegrationFailure with everything needed to repeat it.
#include <array>
#include <functional>
#include <stdexcept>
#include <variant>
#include <vector>

#include "models/material_law.hpp"
#include "models/voigt.hpp"

namespace ffp {

enum class Control : unsigned char { strain, stress };
using ControlSet = std::array<Control, 6>;

/// One leg of the path: every component moves linearly from its value at the
/// leg's start to `target` in `increments` equal increments over `duration_s`.
/// Strain targets are total strains measured from the start of the path;
/// stress targets are stresses (Pa). Tension positive, tensor shears.
struct PathSegment {
  ControlSet control{};
  Voigt target = Voigt::Zero();
  int increments = 1;
  double duration_s = 1.0;
};

/// Any law (models/material_law.hpp); its state is a MaterialState of the same alternative.
using PointLaw = MaterialLaw;

struct NewtonSettings {
  int max_iterations = 25;
  double relative_tolerance = 1e-10;  ///< on the stress residual, relative to the stress scale of the step
};

struct PointConfig {
  PointLaw law = LinearElastic(ElasticConstants{});
  Voigt initial_stress = Voigt::Zero();
  MaterialState initial_state;  ///< must hold the law's alternative (see initial_state(law))
  std::vector<PathSegment> segments;
  NewtonSettings newton;
  long record_every = 1;  ///< keep every n-th increment (the last one always)
};

/// The point after an increment.
struct PointRecord {
  long step = 0;  ///< increments done (0: the initial state)
  double time_s = 0.0;
  Voigt strain = Voigt::Zero();  ///< total strain from the start of the path
  Voigt stress = Voigt::Zero();
  MaterialState state;
  ReturnRegion region = ReturnRegion::elastic;
  int newton_iterations = 0;
  double plastic_work_J_m3 = 0.0;  ///< Σ σ_mid : Δε^p so far
  double work_input_J_m3 = 0.0;    ///< Σ σ_mid : Δε so far
};

struct PointHistory {
  std::vector<PointRecord> records;  ///< records[0] is the initial state
  long increments = 0;
  int max_newton_iterations = 0;
};

/// A step that did not converge, with what is needed to repeat it alone:
/// start it from `stress_start`, `state_start`, and drive it with `control`,
/// the strain-controlled increments `prescribed_strain_increment` and the
/// stress targets `target_stress`.
class PointIntegrationFailure : public std::runtime_error {
 public:
  PointIntegrationFailure(const std::string& message) : std::runtime_error(message) {}

  long step = 0;    ///< 1-based increment that failed
  int segment = 0;  ///< 0-based path segment
  Voigt stress_start = Voigt::Zero();
  Voigt strain_start = Voigt::Zero();
  MaterialState state_start;
  ControlSet control{};
  Voigt prescribed_strain_increment = Voigt::Zero();  ///< strain-controlled components
  Voigt target_stress = Voigt::Zero();                ///< stress-controlled components
  Voigt last_strain_increment = Voigt::Zero();        ///< Newton's last iterate
  double residual_Pa = 0.0;
  double dt_s = 0.0;
};

/// `on_step(done, total)` is called after each increment (progress, Ctrl-C).
PointHistory integrate_point(const PointConfig& config, const std::function<void(long done, long total)>& on_step = {});

}  // namespace ffp
