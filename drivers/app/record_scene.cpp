#include "drivers/app/record_scene.hpp"

#include <cmath>
#include <limits>

#include "drivers/app/record_output.hpp"
#include "drivers/output/csv_writer.hpp"
#include "drivers/record_plausibility.hpp"
#include "drivers/scene/material_scene.hpp"

namespace ffp {

namespace fs = std::filesystem;

namespace {

/// A rate law's f_SR in words (drivers/ffp_record.cpp cites each beside its line).
std::string rate_law_formula(RateLaw law) {
  switch (law) {
    case RateLaw::logarithmic:
      return "f = 1 + K log10(v/v_ref) (Dayal & Allen 1975)";
    case RateLaw::brilli:
      return "f = 1 + K v_max log10(v/v_ref) (Brilli et al.)";
    case RateLaw::inverse_hyperbolic_sine:
      return "f = 1 + (K/ln 10) asinh(v/v_ref) (Randolph & Hope 2004)";
  }
  return "";
}

}  // namespace

RecordScene read_record_scene(SceneReader& scene, const fs::path& scene_dir) {
  RecordScene out;
  RecordSettings& s = out.settings;
  out.record_csv = scene.existing_file(
      "record_csv", scene_dir, kCsvFileLimit,
      Doc("the record: time_s and exactly one of deceleration_g (net, + while slowing: 0 at rest, −1 in free fall) or "
          "acceleration_m_s2 (the accelerometer's reading, sky positive: +g at rest); optionally pore_pressure_kPa"));
  if (scene.has("sensor_range_g") && scene.has("sensor_range_m_s2"))
    scene.fail("sensor_range_m_s2", "give the full scale once, in the unit of the record's channel");
  const Doc full_scale = Doc("the channel's full scale, in the unit of the record's channel: a sample at or beyond it "
                             "is saturated")
                             .by_default("none: 5 or more equal samples at the record's maximum inside a pulse are");
  if (scene.has("sensor_range_g"))
    out.sensor_range = scene.number("sensor_range_g", Range::positive(1e5, "g"), full_scale);
  if (scene.has("sensor_range_m_s2"))
    out.sensor_range = scene.number("sensor_range_m_s2", Range::positive(1e6, "m/s²"), full_scale);

  SceneReader f = scene.required_object("ffp", Doc("the penetrometer"));
  s.mass_kg = f.number("mass_kg", Range::positive(1e5, "kg"), Doc("its mass"));
  s.tip.base_radius_m =
      f.number("base_radius_m", Range::positive(10.0, "m"), 0.04375, Doc("its radius R, for the contact areas"));
  if (f.choice("tip", {"cone", "flat"}, "cone", Doc("a cone, or a flat circular base")) == "flat") {
    if (f.has("cone_apex_angle_deg")) f.fail("cone_apex_angle_deg", "a flat tip has no cone (give tip: cone for one)");
    s.tip.cone_height_m = 0.0;
  } else {
    const double apex = f.number("cone_apex_angle_deg", Range::open(0.0, 180.0, "degrees"), 60.0,
                                 Doc("full apex angle of the cone").only_with("tip = cone")) *
                        kDegree;
    s.tip.cone_height_m = s.tip.base_radius_m / std::tan(0.5 * apex);
  }
  s.medium = scene.choice("medium", kDropMediumNames, DropMedium::air, Doc("the fluid the penetrometer falls through"));
  if (s.medium == DropMedium::water) {
    s.volume_m3 =
        f.number("volume_m3", Range::positive(1e3, "m³", "the penetrometer's, for its buoyancy"),
                 Doc("its volume, for the buoyancy of a water drop").within("(0, 1000]").only_with("medium = water"));
  } else if (f.has("volume_m3")) {
    f.fail("volume_m3", "enters only a water drop's buoyancy (give medium: water)");
  }
  f.finish("the ffp of a record (mass_kg, tip, cone_apex_angle_deg, base_radius_m, volume_m3 for a water drop)");

  s.fluid_density_kg_m3 = scene.number(
      "fluid_density_kg_m3", Range::non_negative(2e4, "kg/m³"), s.medium == DropMedium::water ? 1020.0 : 1.2,
      Doc("the fluid's density, for buoyancy and drag").by_default("1.2 (air), 1020 (water)"));
  s.drag_coefficient = scene.number("drag_coefficient", Range::non_negative(10.0), 0.0,
                                    Doc("C_D of the fluid's drag ½ ρ C_D π R² v² (0: none)"));
  s.gravity_m_s2 = scene.number("gravity_m_s2", Range::positive(100.0, "m/s²"), 9.81, Doc("gravity g"));
  if (scene.has("impact_velocity_m_s"))
    s.impact_velocity_m_s =
        scene.number("impact_velocity_m_s", Range::positive(1e3, "m/s", "+ down"),
                     Doc("the speed at impact").by_default("none: integrated from rest at the record's first sample"));
  if (scene.has("impact_time_s")) {
    if (scene.has("impact_threshold_g"))
      scene.fail("impact_threshold_g", "detects the impact; with impact_time_s given there is nothing to detect");
    s.impact_time_s = scene.number("impact_time_s", Range::closed(-1e6, 1e6, "s"),
                                   Doc("the time of the impact").by_default("none: detected (impact_threshold_g)"));
  } else {
    s.impact_threshold_g = scene.number("impact_threshold_g", Range::open(-1.0, 1e4, "g", "net deceleration"), 1.0,
                                        Doc("the net deceleration whose first crossing marks the impact pulse (its "
                                            "rise's start is the impact)")
                                            .only_with("no impact_time_s"));
  }

  const Doc laws_doc = Doc("the rate laws f_SR that turn q_dyn into q_sbc = q_dyn / f_SR; only the laws named are "
                           "computed ([theory](../theory.md#record-laws))")
                           .by_default("all three at their K")
                           .within("object");
  if (!scene.has("rate_laws")) {
    scene.allow("rate_laws", laws_doc);
    s.rate_laws = default_rate_laws();
  } else {
    SceneReader laws = scene.object("rate_laws", laws_doc);
    s.reference_velocity_m_s =
        laws.number("reference_velocity_m_s", Range::positive(100.0, "m/s"), 0.02, Doc("v_ref: f = 1 at or below it"));
    s.q_sbc_on_mantle =
        laws.choice("q_sbc_area", {"projected", "mantle"}, "projected",
                    Doc("the area q_sbc is taken on: the projected area π r(z)² or the cone's mantle")) == "mantle";
    for (const RateCorrection& fallback : default_rate_laws()) {
      const std::string_view name = rate_law_name(fallback.law);
      if (!laws.has(name)) continue;
      SceneReader law =
          laws.object(name, Doc(rate_law_formula(fallback.law)).by_default("none: not computed").within("object"));
      s.rate_laws.push_back(
          {fallback.law, law.number("K", Range::closed(0.0, 100.0), fallback.k, Doc("the law's factor K"))});
      law.finish(std::string("rate_laws.") + std::string(name) + " (K)");
    }
    laws.finish("rate_laws (reference_velocity_m_s, q_sbc_area, log, brilli, asinh: each {K})");
  }
  return out;
}

RecordSamples load_record(const RecordScene& scene) {
  const std::string name = scene.record_csv.string();
  const CsvData data = read_numeric_csv(scene.record_csv);
  RecordSamples out;
  if (!data.has("time_s")) throw SceneError(name + ": the record needs a time_s column");
  const bool net = data.has("deceleration_g"), sensor = data.has("acceleration_m_s2");
  if (net == sensor)
    throw SceneError(name +
                     ": the record needs exactly one of the columns deceleration_g (net, + while slowing) or "
                     "acceleration_m_s2 (the accelerometer's reading, sky positive)");
  out.channel = net ? "deceleration_g" : "acceleration_m_s2";
  out.time_s = data.column("time_s");
  const std::vector<double>& channel = data.column(out.channel);
  try {
    check_record_channel(out.time_s, channel, out.channel, scene.sensor_range);
    if (data.has("pore_pressure_kPa")) {
      out.pore_pressure_kPa = data.column("pore_pressure_kPa");
      // Time only: a pore pressure may hold its value for long, which is no saturation.
      check_record_channel(out.time_s, *out.pore_pressure_kPa, "pore_pressure_kPa",
                           std::numeric_limits<double>::infinity());
    }
  } catch (const RecordError& e) {
    throw SceneError(name + ": " + e.what());
  }
  out.deceleration_g = channel;
  // The sensor reads the specific force: +g at rest, 0 in free fall; the net deceleration is a/g − 1.
  if (sensor)
    for (double& d : out.deceleration_g) d = d / scene.settings.gravity_m_s2 - 1.0;
  try {
    check_deceleration_bound(out.time_s, out.deceleration_g, out.channel, scene.settings);
  } catch (const RecordError& e) {
    throw SceneError(name + ": " + e.what());
  }
  return out;
}

}  // namespace ffp
