#include "drivers/app/integration_error_scene.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "drivers/scene/material_scene.hpp"

namespace ffp {

IntegrationErrorScene read_integration_error_scene(SceneReader& scene) {
  SceneReader material_reader = scene.required_object(
      "material", Doc("an ssmc material with a constant psi_peak_deg; the Mohr–Coulomb runs take its peak φ', ψ_p, "
                      "c'"));
  const MaterialSpec material = read_material(material_reader, DensityRule::not_used);
  if (material.model != "ssmc")
    scene.fail("material.model", "must be ssmc here (the Mohr-Coulomb runs use its peak strength)");
  // Bolton's ψ_p follows p', which a Mohr-Coulomb comparison cannot: it would
  // silently run with ψ = 0.
  material_reader.refuse(
      "relative_density",
      "not allowed here: the Mohr-Coulomb runs need a constant dilatancy; give psi_peak_deg instead");
  TriaxialErrorStudy study;
  study.cell_pressure_Pa = 1e3 * scene.number("cell_pressure_kPa", Range::positive(1e7, "kPa"), 1.72,
                                              Doc("the cell pressure σ3, also the confinement of the maps"));
  study.axial_strain_max =
      scene.number("axial_strain_max", Range::open(0.0, 1.0), 0.2, Doc("the axial strain ε_a at the end"));
  study.strain_rate_per_s = scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4,
                                         Doc("the axial strain rate, which only the rate law sees"));
  study.reference_increments = scene.integer("reference_increments", 10, 100'000'000, 100000,
                                             Doc("increments of the reference run the others are measured against"));
  const Doc increments = Doc("the increment counts whose error and run time are measured")
                             .by_default("[10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000]")
                             .within("1 to 100 whole numbers in [1, 1e8], each below reference_increments");
  if (scene.has("increments")) {
    const std::vector<double> n = scene.numbers("increments", Range::closed(1, 1e8), 1, 100, increments);
    study.increments.clear();
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (n[i] != std::floor(n[i])) scene.fail("increments[" + std::to_string(i) + "]", "must be a whole number");
      if (n[i] >= study.reference_increments)
        scene.fail("increments[" + std::to_string(i) + "]", "must be below reference_increments");
      study.increments.push_back(static_cast<int>(n[i]));
    }
  } else {
    scene.allow("increments", increments);  // the default list; summary.json lists the runs made
  }
  study.min_timing_s = scene.number("min_timing_s", Range::closed(0.0, 60.0, "s"), 0.05,
                                    Doc("a short run is repeated until this much time is measured"));
  SceneReader maps_reader = scene.object("maps", Doc("the iso-error maps of one increment"));
  IsoErrorMapStudy maps;
  maps.confining_Pa = study.cell_pressure_Pa;
  maps.points_x = maps_reader.integer("points_x", 2, 1000, 21,
                                      Doc("grid points of a map along x, the triaxial-compression deviatoric strain"));
  maps.points_y = maps_reader.integer("points_y", 2, 1000, 41,
                                      Doc("grid points of a map along y, the orthogonal (Lode) deviatoric strain"));
  maps.max_multiple = maps_reader.number("max_trial_over_yield_strain", Range::positive(1000), 10.0,
                                         Doc("the maps' extent, as a multiple of the yield strain"));
  maps.reference_substeps =
      maps_reader.integer("reference_substeps", 2, 1'000'000, 2000, Doc("substeps of the reference increment"));
  maps_reader.finish("maps");
  scene.finish("an integration_error scene");
  return {std::get<StrainSofteningParameters>(material.parameters), study, maps};
}

}  // namespace ffp
