#include "calibration/numerical_triaxial.hpp"

namespace ffp {

SpecimenCurve specimen_curve_of(const TriaxialResult& result) {
  SpecimenCurve curve;
  curve.axial_strain = result.axial_strain;
  curve.deviatoric_stress_Pa = result.deviatoric_stress_Pa;
  curve.volumetric_strain = result.volumetric_strain;
  curve.plastic_work_J = result.plastic_work_J_total;
  return curve;
}

NumericalTriaxial element_test_triaxial(const StrainSofteningParameters& material, const TriaxialTestConfig& test) {
  return [material, test](double eta) {
    StrainSofteningParameters p = material;
    p.softening_factor = eta;
    TriaxialTestConfig config = test;
    config.law = StrainSofteningMohrCoulomb(p);
    return specimen_curve_of(run_triaxial_test(config));
  };
}

}  // namespace ffp
