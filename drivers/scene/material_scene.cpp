#include "drivers/scene/material_scene.hpp"

#include <algorithm>

namespace ffp {

namespace {

// Bounds wide enough for any soil or structural material, tight enough to
// catch unit mistakes and absurd inputs (E in Pa typed as kPa, ...).
constexpr double kMaxModulus_kPa = 1e9;  // 1 TPa, above diamond
constexpr double kMaxDensity = 30000.0;
constexpr double kMaxCohesion_kPa = 1e6;

ElasticConstants read_elastic(SceneReader& m) {
  ElasticConstants e;
  e.youngs_modulus_Pa = 1e3 * m.number("E_kPa", Range::positive(kMaxModulus_kPa, "kPa"), Doc("Young's modulus E'"));
  e.poisson_ratio = m.number("nu", Range::half_open(0.0, 0.5), Doc("Poisson's ratio ν'"));
  return e;
}

/// ψ of mohr_coulomb, ψ_p of ssmc without Bolton's dilatancy.
double read_peak_dilatancy_deg(SceneReader& m, double phi_deg) {
  return m.number("psi_peak_deg", Range::closed(0.0, phi_deg, "degrees", "0 ≤ ψ ≤ φ"), 0.0,
                  Doc("dilatancy angle ψ (ssmc: its peak ψ_p)")
                      .within("[0, phi_peak_deg]")
                      .only_with("model = mohr_coulomb, or ssmc without relative_density"));
}

/// The `micropolar` object (docs/theory.md#micropolar): absent, the classical continuum.
std::optional<MicropolarParameters> read_micropolar(SceneReader& m, MicropolarRule rule) {
  if (rule == MicropolarRule::refused) {
    m.refuse("micropolar", "a micropolar material is an option of the MPM kinds (mpm, ffp, cpt)");
    return std::nullopt;
  }
  const Doc doc = Doc("a micropolar (Cosserat) material: the law unchanged on the symmetric strain, plus a "
                      "micro-rotation with linear elastic skew and couple stresses "
                      "([theory](../theory.md#micropolar))")
                      .by_default("none: the classical continuum")
                      .within("object");
  if (!m.has("micropolar")) {
    m.allow("micropolar", doc);
    return std::nullopt;
  }
  SceneReader r = m.object("micropolar", doc);
  MicropolarParameters p;
  p.length_m = r.number("length_m", Range::positive(0.1, "m"),
                        Doc("the internal length ℓ of the couple stresses m = 2 G ℓ² κ (about d50: Mühlhaus & "
                            "Vardoulakis 1987)"));
  p.cosserat_shear_ratio =
      r.number("cosserat_shear_ratio", Range::positive(10.0), 0.5,
               Doc("G_c/G: the Cosserat shear modulus of the skew stress s = 2 G_c (ω_M − ω), over the law's G"));
  p.micro_inertia_m2 = r.number("micro_inertia_m2", Range::positive(1.0, "m²"), p.length_m * p.length_m / 10.0,
                                Doc("j: the micro-rotation's inertia per unit mass (ρ j per unit volume); a sphere of "
                                    "diameter d has d²/10")
                                    .by_default("length_m²/10"));
  p.friction_limited =
      r.boolean("friction_limited", false,
                Doc("whether the skew and couple stresses slip at the law's friction: |s| ≤ tan φ' p, |m| ≤ ℓ tan φ' p "
                    "(p the mean pressure; rolling resistance, Iwashita & Oda 1998); false keeps them elastic"));
  r.finish("micropolar (length_m, cosserat_shear_ratio, micro_inertia_m2, friction_limited)");
  return p;
}

}  // namespace

MaterialSpec read_material(SceneReader& m, DensityRule density, MicropolarRule micropolar) {
  MaterialSpec spec;
  spec.model = m.choice("model", {"linear_elastic", "mohr_coulomb", "ssmc"},
                        Doc("the constitutive law: each accepts only its own keys"));
  const ElasticConstants elastic = read_elastic(m);
  if (density == DensityRule::required)
    spec.density_kg_m3 =
        m.number("density_kg_m3", Range::positive(kMaxDensity, "kg/m³"), Doc("density ρ (unit weight γ = ρ g)"));
  spec.micropolar = read_micropolar(m, micropolar);

  if (spec.model == "linear_elastic") {
    spec.parameters = elastic;
    m.finish("a linear_elastic material");
    return spec;
  }

  const std::string plastic = "model = mohr_coulomb or ssmc";
  const double phi_deg = m.number("phi_peak_deg", Range::half_open(0.0, 90.0, "degrees"),
                                  Doc("friction angle φ' (ssmc: its peak φ'_p)")
                                      .within("(0, 90); 0 (Tresca) for mohr_coulomb with c_peak_kPa > 0")
                                      .only_with(plastic));
  const double cohesion_kPa =
      m.number("c_peak_kPa", Range::non_negative(kMaxCohesion_kPa, "kPa"), 0.0,
               Doc("cohesion c' (ssmc: its peak c'_p; with φ' = 0 the undrained strength s_u)").only_with(plastic));
  // φ' = 0 is Tresca, a clay's undrained strength c' = s_u: only with a cohesion, and only for MC
  // (SSMC softens φ' towards φ'_r > 0).
  if (phi_deg == 0.0 && (spec.model != "mohr_coulomb" || cohesion_kPa == 0.0))
    m.fail("phi_peak_deg", spec.model == "mohr_coulomb"
                               ? "0 (Tresca) needs c_peak_kPa > 0; otherwise 0 < φ' < 90 degrees"
                               : "must be in (0, 90) degrees for ssmc (φ' = 0 with c' > 0 is mohr_coulomb)");

  if (spec.model == "mohr_coulomb") {
    MohrCoulombParameters p;
    p.elastic = elastic;
    p.friction_angle_rad = phi_deg * kDegree;
    p.dilatancy_angle_rad = read_peak_dilatancy_deg(m, phi_deg) * kDegree;
    p.cohesion_Pa = 1e3 * cohesion_kPa;
    spec.parameters = p;
    m.finish("a mohr_coulomb material");
    return spec;
  }

  const std::string ssmc = "model = ssmc";
  StrainSofteningParameters p;
  p.elastic = elastic;
  p.friction_peak_rad = phi_deg * kDegree;
  p.friction_residual_rad =
      m.number("phi_residual_deg", Range::closed(0.0, phi_deg, "degrees", "0 < φ_r ≤ φ_p"),
               Doc("residual (critical-state) friction angle φ'_r").within("(0, phi_peak_deg]").only_with(ssmc)) *
      kDegree;
  if (p.friction_residual_rad <= 0.0) m.fail("phi_residual_deg", "must be > 0 degrees");
  p.cohesion_peak_Pa = 1e3 * cohesion_kPa;
  p.cohesion_residual_Pa = 1e3 * m.number("c_residual_kPa", Range::closed(0.0, cohesion_kPa, "kPa", "0 ≤ c_r ≤ c_p"),
                                          0.0, Doc("residual cohesion c'_r").within("[0, c_peak_kPa]").only_with(ssmc));
  p.softening_factor = m.number("eta", Range::positive(1e4),
                                Doc("softening factor η: φ', c' and ψ fall from peak to residual as exp(−η ε_d^p) "
                                    "([theory](../theory.md#ssmc))")
                                    .only_with(ssmc));
  if (m.has("relative_density") && m.has("psi_peak_deg"))
    m.fail("psi_peak_deg", "give either psi_peak_deg or relative_density (Bolton dilatancy), not both");
  p.relative_density = m.optional_number(
      "relative_density", Range::closed(0.0, 1.0),
      Doc("relative density D_r as a fraction: Bolton's transient dilatancy, which replaces psi_peak_deg "
          "([theory](../theory.md#bolton))")
          .by_default("none: a constant ψ_p")
          .only_with(ssmc));
  if (!p.relative_density) p.dilatancy_peak_rad = read_peak_dilatancy_deg(m, phi_deg) * kDegree;
  const double psi_peak_deg = p.dilatancy_peak_rad / kDegree;
  p.dilatancy_residual_rad =
      m.number("psi_residual_deg", Range::closed(0.0, p.relative_density ? phi_deg : psi_peak_deg, "degrees"), 0.0,
               Doc("residual dilatancy angle ψ_r")
                   .within("[0, psi_peak_deg]; with relative_density [0, phi_peak_deg]")
                   .only_with(ssmc)) *
      kDegree;
  const Doc rate_doc = Doc("a rate-dependent peak friction angle φ'_p(ε̇) ([theory](../theory.md#rate-law))")
                           .by_default("none: rate independent")
                           .within("object")
                           .only_with(ssmc);
  if (m.has("rate_dependence")) {
    SceneReader r = m.object("rate_dependence", rate_doc);
    p.rate.alpha_phi = r.number("alpha_phi", Range::closed(0.0, 10.0),
                                Doc("α_φ: φ'_p grows by the factor 1 + α_φ log10(ε̇/ε̇_ref) above ε̇_ref"));
    p.rate.reference_strain_rate_per_s = r.number("reference_strain_rate_per_s", Range::positive(1e6, "1/s"),
                                                  Doc("ε̇_ref, below which φ'_p is the rate-independent one"));
    p.rate.smoothing_increments = r.integer("smoothing_increments", 1, 10000, 1,
                                            Doc("the span of the moving average of ε̇, in increments (1: none)"));
    p.rate.max_friction_angle_rad =
        r.number("max_phi_deg", Range::closed(phi_deg, 89.0, "degrees", "≥ phi_peak_deg"), std::max(70.0, phi_deg),
                 Doc("upper limit of the rate-raised φ'_p")
                     .by_default("max(70, phi_peak_deg)")
                     .within("[phi_peak_deg, 89]")) *
        kDegree;
    r.finish("rate_dependence");
  } else {
    m.allow("rate_dependence", rate_doc);
  }
  spec.parameters = p;
  m.finish("an ssmc material");
  return spec;
}

json material_json(const MaterialSpec& spec) {
  json m;
  m["model"] = spec.model;
  const ElasticConstants& e = spec.elastic();
  m["E_kPa"] = 1e-3 * e.youngs_modulus_Pa;
  m["nu"] = e.poisson_ratio;
  if (spec.micropolar)
    m["micropolar"] = {{"length_m", spec.micropolar->length_m},
                       {"cosserat_shear_ratio", spec.micropolar->cosserat_shear_ratio},
                       {"micro_inertia_m2", spec.micropolar->micro_inertia_m2}};
  if (spec.micropolar && spec.micropolar->friction_limited) m["micropolar"]["friction_limited"] = true;
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&spec.parameters)) {
    m["phi_peak_deg"] = mc->friction_angle_rad / kDegree;
    m["psi_peak_deg"] = mc->dilatancy_angle_rad / kDegree;
    m["c_peak_kPa"] = 1e-3 * mc->cohesion_Pa;
  } else if (const auto* s = std::get_if<StrainSofteningParameters>(&spec.parameters)) {
    m["phi_peak_deg"] = s->friction_peak_rad / kDegree;
    m["phi_residual_deg"] = s->friction_residual_rad / kDegree;
    m["c_peak_kPa"] = 1e-3 * s->cohesion_peak_Pa;
    m["c_residual_kPa"] = 1e-3 * s->cohesion_residual_Pa;
    m["eta"] = s->softening_factor;
    if (s->relative_density) {
      m["relative_density"] = *s->relative_density;
    } else {
      m["psi_peak_deg"] = s->dilatancy_peak_rad / kDegree;
    }
    m["psi_residual_deg"] = s->dilatancy_residual_rad / kDegree;
    m["rate_dependence"] = {{"alpha_phi", s->rate.alpha_phi},
                            {"reference_strain_rate_per_s", s->rate.reference_strain_rate_per_s},
                            {"smoothing_increments", s->rate.smoothing_increments},
                            {"max_phi_deg", s->rate.max_friction_angle_rad / kDegree}};
  }
  return m;
}

MaterialState read_initial_state(SceneReader& scene, const MaterialLaw& law) {
  MaterialState state = initial_state(law);
  if (!scene.has("initial_state")) return state;
  auto* softening = std::get_if<StrainSofteningMohrCoulomb::State>(&state);
  if (softening == nullptr)
    scene.fail("initial_state", "only an ssmc material has a state (plastic_deviatoric_strain, strain_rate_per_s)");
  SceneReader s = scene.object("initial_state", Doc("the law's internal variables at the start")
                                                    .by_default("none: the virgin state")
                                                    .within("object")
                                                    .only_with("material.model = ssmc"));
  softening->plastic_deviatoric_strain = s.number("plastic_deviatoric_strain", Range::non_negative(1e6), 0.0,
                                                  Doc("the accumulated plastic deviatoric strain ε_d^p"));
  softening->strain_rate_per_s = s.number("strain_rate_per_s", Range::non_negative(1e12, "1/s"), 0.0,
                                          Doc("the smoothed deviatoric strain rate ε̇ of the rate law"));
  s.finish("initial_state");
  return state;
}

json initial_state_json(const MaterialState& state) {
  if (const auto* s = std::get_if<StrainSofteningMohrCoulomb::State>(&state))
    return {{"plastic_deviatoric_strain", s->plastic_deviatoric_strain}, {"strain_rate_per_s", s->strain_rate_per_s}};
  return nullptr;
}

std::string output_column(StateOutput output) {
  switch (unit(output)) {
    case OutputUnit::radian:
      return std::string(name(output)) + "_deg";
    case OutputUnit::per_second:
      return std::string(name(output)) + "_per_s";
    default:
      return std::string(name(output));
  }
}

double output_value(StateOutput output, double value_in_si_units) {
  return unit(output) == OutputUnit::radian ? value_in_si_units / kDegree : value_in_si_units;
}

}  // namespace ffp
