#include "reports/studies/saturated_runs.hpp"

#include <cmath>
#include <cstdlib>

namespace ffp {

double SaturatedParameters::undrained_share() const {
  return ffp::undrained_share(constrained_modulus_Pa, fluid_bulk_modulus_Pa, porosity);
}

double SaturatedParameters::consolidation_coefficient_m2_s() const {
  return ffp::consolidation_coefficient(permeability_m_s, fluid_density_kg_m3, constrained_modulus_Pa, porosity,
                                        fluid_bulk_modulus_Pa, kConductivityGravity_m_s2);
}

BiotColumn SaturatedParameters::biot() const {
  return BiotColumn{constrained_modulus_Pa, fluid_bulk_modulus_Pa,    porosity, dry_density_kg_m3, fluid_density_kg_m3,
                    permeability_m_s,       kConductivityGravity_m_s2};
}

namespace {

/// The echoed scene's first body, its fluid and mesh: E_c = E (1 − ν)/((1 + ν)(1 − 2ν)).
SaturatedParameters parameters_of(const nlohmann::json& scene) {
  SaturatedParameters p;
  const nlohmann::json& body = scene.at("bodies").at(0);
  const nlohmann::json& material = body.at("material");
  const double E = 1e3 * material.at("E_kPa").get<double>(), nu = material.at("nu").get<double>();
  p.constrained_modulus_Pa = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  p.poisson_ratio = nu;
  p.dry_density_kg_m3 = material.at("density_kg_m3").get<double>();
  p.porosity = body.at("porosity").get<double>();
  p.permeability_m_s = body.at("permeability_m_s").get<double>();
  p.initial_excess_pressure_Pa = 1e3 * body.at("initial_excess_pore_pressure_kPa").get<double>();
  p.fluid_bulk_modulus_Pa = 1e3 * scene.at("fluid").at("bulk_modulus_kPa").get<double>();
  p.fluid_density_kg_m3 = scene.at("fluid").at("density_kg_m3").get<double>();
  if (scene.contains("gravity_m_s2") && scene["gravity_m_s2"].is_number())
    p.gravity_m_s2 = scene["gravity_m_s2"].get<double>();
  p.top_m = body.at("region").at("z_max_m").get<double>();
  p.radius_m = body.at("region").at("r_max_m").get<double>();
  p.cell_r_m = scene.at("mesh").at("cell_r_m").get<double>();
  p.cell_z_m = scene.at("mesh").at("cell_z_m").get<double>();
  if (scene.contains("surface_pressures") && !scene["surface_pressures"].empty()) {
    const nlohmann::json& load = scene["surface_pressures"].at(0);
    p.load_Pa = 1e3 * load.at("pressure_kPa").get<double>();
    p.ramp_s = load.at("ramp_time_s").get<double>();
  }
  if (body.contains("initial_stress")) p.k0 = body["initial_stress"].at("k0").get<double>();
  return p;
}

std::vector<double> scaled(const std::vector<double>& x, double factor) {
  std::vector<double> out(x);
  for (double& v : out) v *= factor;
  return out;
}

}  // namespace

std::optional<SaturatedRun> read_saturated_run(const StudyResults& results, std::size_t run) {
  const nlohmann::json summary = results.summary(run);
  const CsvData history = results.history(run);
  if (summary.empty() || !history.has("time_s")) return std::nullopt;
  SaturatedRun out;
  try {
    out.parameters = parameters_of(summary.at("scene"));
    out.wall_time_s = summary.at("wall_time_s").get<double>();
    out.steps = summary.at("steps").get<long>();
    out.time_s = history.column("time_s");
    for (const nlohmann::json& probe : summary.at("scene").at("output").at("probes")) {
      ProbeHistory h;
      h.name = probe.at("name").get<std::string>();
      const std::string c = h.name + "_";
      h.r_m = history.column(c + "r_m");
      h.z_m = history.column(c + "z_m");
      h.pore_pressure_Pa = scaled(history.column(c + "pore_pressure_kPa"), 1e3);
      h.excess_pressure_Pa = scaled(history.column(c + "excess_pore_pressure_kPa"), 1e3);
      h.stress_rr_Pa = scaled(history.column(c + "sigma_rr_kPa"), 1e3);
      h.stress_zz_Pa = scaled(history.column(c + "sigma_zz_kPa"), 1e3);
      h.r0_m = h.r_m.front();
      h.z0_m = h.z_m.front();
      out.probes.push_back(std::move(h));
    }
  } catch (const std::exception&) {  // a key or column missing: the run is not one of these
    return std::nullopt;
  }
  return out;
}

std::size_t nearest_row(const std::vector<double>& time_s, double t_s) {
  std::size_t best = 0;
  for (std::size_t j = 1; j < time_s.size(); ++j)
    if (std::abs(time_s[j] - t_s) < std::abs(time_s[best] - t_s)) best = j;
  return best;
}

}  // namespace ffp
