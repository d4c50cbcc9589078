#include "drivers/app/triaxial_scene.hpp"

#include <algorithm>

#include "drivers/app/job.hpp"
#include "drivers/app/point_scene.hpp"

namespace ffp {

namespace {

constexpr long kMaxIncrements = 1'000'000;  // every increment is kept for the work integral (~160 B each)

}  // namespace

TriaxialScene read_triaxial_scene(SceneReader& scene) {
  TriaxialScene out;
  out.name = read_scene_name(scene, "triaxial");
  SceneReader material_reader = scene.required_object("material", Doc("the specimen's law (weightless)"));
  out.material = read_material(material_reader, DensityRule::not_used);

  TriaxialTestConfig& config = out.config;
  config.law = out.material.law();
  config.cell_pressure_Pa =
      1e3 * scene.number("cell_pressure_kPa", Range::positive(1e7, "kPa"), 1.72, Doc("the cell pressure σ3"));
  config.axial_strain_max = scene.number("axial_strain_max", Range::half_open(0.0, 1.0), 0.2,
                                         Doc("the axial strain ε_a at the end").within("(0, 1)"));
  if (!(config.axial_strain_max > 0.0)) scene.fail("axial_strain_max", "must be > 0 (compression positive)");
  config.increments = scene.integer("increments", 1, kMaxIncrements, 2000, Doc("equal axial-strain increments"));
  config.strain_rate_per_s = scene.number("strain_rate_per_s", Range::positive(1e9, "1/s"), 1e-4,
                                          Doc("the axial strain rate, which only the rate law sees"));
  SceneReader specimen =
      scene.object("specimen", Doc("its size, for the force F = q A and the displacement δ = ε_a H"));
  config.specimen.height_m = specimen.number("height_m", Range::positive(100.0, "m"), 0.15, Doc("height H"));
  config.specimen.diameter_m = specimen.number("diameter_m", Range::positive(100.0, "m"), 0.07, Doc("diameter D"));
  specimen.finish("specimen (height_m, diameter_m)");
  config.newton = read_newton_settings(scene);
  // Histories beyond ~20,000 rows only slow the plots down.
  out.output_every =
      scene.integer("output_every_increments", 1, kMaxIncrements, std::max(1L, config.increments / 20000L),
                    Doc("a history.csv row every this many increments (the work integral takes every increment)")
                        .by_default("max(1, increments / 20000)"));
  scene.finish("a triaxial scene");
  return out;
}

}  // namespace ffp
