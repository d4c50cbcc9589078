#pragma once
/// The "numerical triaxial" of the paper's calibration (section 4.2) as a
/// pluggable function η ↦ specimen response. The calibration only sees this
/// function, so the single-point element test used now and a meshed MPM
/// specimen later (same 0.15 m × 0.07 m specimen, 1 cm cells, where the
/// softening localises and W depends on the mesh — the reason the paper
/// matches work) plug in the same way.
#include <functional>
#include <limits>
#include <vector>

#include "drivers/triaxial_test.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"

namespace ffp {

/// What a numerical specimen with softening factor η produced, in the load
/// frame's terms (compression positive). An MPM specimen reports q = F/A and
/// ε_a = δ/H from its platen.
struct SpecimenCurve {
  std::vector<double> axial_strain;          ///< from 0, increasing; must reach the lab's last strain
  std::vector<double> deviatoric_stress_Pa;  ///< q
  std::vector<double> volumetric_strain;     ///< may be empty
  /// What the law dissipated over the whole curve, V Σ σ:Δε^p (NaN if the specimen does not say).
  double plastic_work_J = std::numeric_limits<double>::quiet_NaN();
};

/// η ↦ response. May throw (e.g. PointIntegrationFailure); the calibration
/// treats a throw during the fit as a rejected trial step.
using NumericalTriaxial = std::function<SpecimenCurve(double eta)>;

/// The drained element test (drivers/triaxial_test.hpp) with `material` whose
/// softening factor is replaced by η on each call; `test.law` is ignored.
NumericalTriaxial element_test_triaxial(const StrainSofteningParameters& material, const TriaxialTestConfig& test);

/// The same conversion for a finished element test.
SpecimenCurve specimen_curve_of(const TriaxialResult& result);

}  // namespace ffp
