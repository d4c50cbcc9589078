#include "drivers/app/pore_fluid_scene.hpp"

#include <array>
#include <string>

namespace ffp {

namespace {

constexpr double kMaxFluidBulkModulus_kPa = 1e8;  // 100 GPa: stiffer than any pore fluid
constexpr double kMaxFluidDensity = 30000.0;      // as a material's
constexpr double kMaxPermeability_m_s = 1.0;      // clean gravel
constexpr double kMaxWaterDepth_m = 11000.0;      // the deepest ocean

constexpr double kMaxExcessPressure_kPa = 1e6;  // 1 GPa: beyond any soil's

const std::array<const char*, 4> kPoreKeys = {"porosity", "permeability_m_s", "permeability_law",
                                              "initial_excess_pore_pressure_kPa"};

}  // namespace

std::optional<mpm::SaturatedSoil> read_saturation(SceneReader& body) {
  const Doc saturated_doc = Doc("a saturated (two-phase) body: its pores hold the scene's `fluid`, and "
                                "`material.density_kg_m3` is its dry density ρ_d = (1 − n) ρ_s, the grains' mass per "
                                "unit volume (ρ_sat = ρ_d + n ρ_w) ([theory](../theory.md#saturated))")
                                .by_default("`false`: a dry body")
                                .within("`true`, `false`");
  const bool saturated = body.has("saturated") ? body.boolean("saturated", false, saturated_doc) : false;
  if (!body.has("saturated")) body.allow("saturated", saturated_doc);
  if (!saturated) {
    for (const char* key : kPoreKeys)
      if (body.has(key)) body.fail(key, "only with saturated: true");
    return std::nullopt;
  }
  const std::string only = "saturated: true";
  mpm::SaturatedSoil soil;
  soil.porosity = body.number("porosity", Range::open(0.0, 1.0),
                              Doc("the initial porosity n_0, pore volume over total volume").only_with(only));
  soil.permeability_m_s = body.number(
      "permeability_m_s", Range::positive(kMaxPermeability_m_s, "m/s"),
      Doc("the hydraulic conductivity k (Darcy's flux per unit hydraulic gradient); the explicit step shrinks "
          "with it (Mieremet's limit, [theory](../theory.md#saturated))")
          .only_with(only));
  soil.permeability_law =
      body.choice("permeability_law", mpm::kPermeabilityLawNames, mpm::PermeabilityLaw::constant,
                  Doc("how k follows the porosity: constant, or Kozeny–Carman k_0 [n³/(1 − n)²]/[n_0³/(1 − n_0)²]")
                      .only_with(only));
  soil.initial_excess_pressure_Pa =
      1e3 * body.number("initial_excess_pore_pressure_kPa",
                        Range::closed(-kMaxExcessPressure_kPa, kMaxExcessPressure_kPa, "kPa"), 0.0,
                        Doc("the excess pore pressure p_e over hydrostatic at t = 0, the same at every particle, "
                            "with the skeleton's stress as `initial_stress` gives it (e.g. a consolidation "
                            "problem's p_0)")
                            .only_with(only));
  return soil;
}

mpm::PoreFluid read_pore_fluid(SceneReader& scene, bool saturated, double* water_depth_m,
                               const std::string& saturated_key) {
  const Doc doc = Doc("the pore fluid of the saturated bodies")
                      .by_default("water at 20 °C")
                      .within("object")
                      .only_with("a saturated body");
  mpm::PoreFluid fluid;
  if (!saturated) {
    if (scene.has("fluid")) scene.fail("fluid", "only with a saturated body (" + saturated_key + ": true)");
    scene.allow("fluid", doc);
    return fluid;
  }
  SceneReader f = scene.object("fluid", doc);
  fluid.bulk_modulus_Pa = 1e3 * f.number("bulk_modulus_kPa", Range::positive(kMaxFluidBulkModulus_kPa, "kPa"),
                                         1e-3 * fluid.bulk_modulus_Pa, Doc("the fluid's bulk modulus K_w"));
  fluid.density_kg_m3 = f.number("density_kg_m3", Range::positive(kMaxFluidDensity, "kg/m³"), fluid.density_kg_m3,
                                 Doc("the fluid's density ρ_w"));
  if (water_depth_m != nullptr) {
    *water_depth_m = f.number(
        "water_depth_m", Range::non_negative(kMaxWaterDepth_m, "m"), 0.0,
        Doc("free water above the sand surface: the water table this high above it, so the surface carries "
            "ρ_w g × depth (drained: no excess there) and the penetrometer below the water's surface is buoyed; the "
            "water above is no medium of the model (no drag, no added mass) "
            "([theory](../theory.md#saturated-penetrometer))"));
    f.finish("fluid (bulk_modulus_kPa, density_kg_m3, water_depth_m)");
    return fluid;
  }
  f.finish("fluid (bulk_modulus_kPa, density_kg_m3)");
  return fluid;
}

ChamberDrainage read_chamber_drainage(SceneReader& soil, bool saturated) {
  const Doc doc = Doc("whether the pore water may leave through the chamber's wall and base (the sand's surface is "
                      "always drained) ([theory](../theory.md#saturated))")
                      .by_default("impermeable wall and base")
                      .within("object")
                      .only_with("soil.saturated: true");
  ChamberDrainage out;
  if (!saturated) {
    if (soil.has("drainage")) soil.fail("drainage", "only with a saturated sand (soil.saturated: true)");
    soil.allow("drainage", doc);
    return out;
  }
  SceneReader d = soil.object("drainage", doc);
  const std::string wall =
      ": impermeable (the pore water's normal velocity is zero there) or drained (no excess "
      "pore pressure)";
  out.wall = d.choice("wall", mpm::kDrainageNames, mpm::Drainage::impermeable, Doc("the lateral wall" + wall));
  out.base = d.choice("base", mpm::kDrainageNames, mpm::Drainage::impermeable, Doc("the base" + wall));
  d.finish("drainage (wall, base)");
  return out;
}

mpm::DrainageConditions read_drainage(SceneReader& boundaries, const mpm::BoundaryConditions& fixities, bool axis,
                                      bool saturated) {
  const Doc doc = Doc("which sides let the pore fluid through ([theory](../theory.md#saturated))")
                      .by_default("impermeable walls and base, a drained top")
                      .within("object")
                      .only_with("a saturated body");
  mpm::DrainageConditions drainage;
  if (!saturated) {
    if (boundaries.has("drainage"))
      boundaries.fail("drainage", "only with a saturated body (bodies[i].saturated: true)");
    boundaries.allow("drainage", doc);
    return drainage;
  }
  using mpm::Drainage;
  using mpm::Fixity;
  const std::array<std::pair<const char*, Fixity>, 4> sides = {{{axis ? "axis" : "inner", fixities.inner},
                                                                {"outer", fixities.outer},
                                                                {"bottom", fixities.bottom},
                                                                {"top", fixities.top}}};
  for (const auto& [key, fixity] : sides)
    if (fixity == Fixity::absorbing) boundaries.fail(key, "a saturated body takes no absorbing sides");
  SceneReader d = boundaries.object("drainage", doc);
  const std::string wall = "; impermeable: the liquid's normal velocity is zero there (a roller or fixed side)";
  if (!axis)
    drainage.inner = d.choice("inner", mpm::kDrainageNames, Drainage::impermeable,
                              Doc("the inner side" + wall).only_with("mesh from r > 0"));
  drainage.outer = d.choice("outer", mpm::kDrainageNames, Drainage::impermeable, Doc("the outer side" + wall));
  drainage.bottom = d.choice("bottom", mpm::kDrainageNames, Drainage::impermeable, Doc("the bottom" + wall));
  drainage.top = d.choice("top", mpm::kDrainageNames, Drainage::drained,
                          Doc("the top grid line" + wall + "; a body's free surface below it is drained"));
  const std::array<std::pair<const char*, std::pair<Drainage, Fixity>>, 4> checks = {
      {{"inner", {drainage.inner, axis ? Fixity::roller : fixities.inner}},
       {"outer", {drainage.outer, fixities.outer}},
       {"bottom", {drainage.bottom, fixities.bottom}},
       {"top", {drainage.top, fixities.top}}}};
  for (const auto& [key, pair] : checks)
    if (pair.first == Drainage::impermeable && pair.second == Fixity::free)
      d.fail(key, "is impermeable but boundaries." + std::string(key) +
                      " is free: hold the solid there too (roller or fixed), or make it drained");
  d.finish(axis ? "drainage (outer, bottom, top)" : "drainage (inner, outer, bottom, top)");
  return drainage;
}

}  // namespace ffp
