#pragma once
/// Reading an `integration_error` scene: how accurate the constitutive
/// integration is against its run time (drivers/integration_study.hpp).
/// Reading only; integration_error_job runs it.
///
/// Its keys, each declared where integration_error_scene.cpp reads it:
/// `ffp keys integration_error` (docs/reference/scenes.md). The material is an
/// ssmc one with a constant ψ_p: the Mohr-Coulomb runs use its peak φ', ψ, c'.
#include "drivers/integration_study.hpp"
#include "drivers/scene/scene_reader.hpp"
#include "models/strain_softening_mohr_coulomb.hpp"

namespace ffp {

struct IntegrationErrorScene {
  StrainSofteningParameters material;
  TriaxialErrorStudy study;  ///< its law is set per run (ssmc, then mohr_coulomb)
  IsoErrorMapStudy maps;     ///< its law and start are set per map
};

/// Reads every key after kind/name and finish()es the scene. SceneError on bad input.
IntegrationErrorScene read_integration_error_scene(SceneReader& scene);

}  // namespace ffp
