#include "drivers/app/ffp_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "drivers/app/record_output.hpp"
#include "models/voigt.hpp"
#include "reports/plot.hpp"

namespace ffp {

namespace {

namespace fs = std::filesystem;

std::vector<double> column(std::span<const FfpSample> samples, double FfpSample::*member) {
  std::vector<double> values;
  values.reserve(samples.size());
  for (const FfpSample& s : samples) values.push_back(s.*member);
  return values;
}

/// The outline as a polyline in (r, z), from the tip up to z_max.
Series outline(const mpm::FfpRun& run, double z_max) {
  Series s;
  s.title = "penetrometer";
  s.style = "lines";
  const double tip = run.tip_z_m(), length = run.geometry().shape().total_length_m();
  const double top = std::min(length, z_max - tip);
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double h = top * k / n;
    s.x.push_back(run.geometry().radius_at(std::min(h, length)));
    s.y.push_back(tip + h);
  }
  return s;
}

Plot line_plot(const std::vector<double>& x, const std::vector<double>& y, const std::string& x_label,
               const std::string& y_label, const std::string& title, const std::string& name) {
  Plot p;
  p.title = title;
  p.x_label = x_label;
  p.y_label = y_label;
  p.series = {{x, y, name}};
  p.key_position = "off";
  return p;
}

/// The soil's particles coloured by `values` (one per soil particle), the outline on
/// top, colours from 0 to colour_max (continuous unless `categories`), written to `png`.
struct Categories {
  std::string palette, tics;
};
void write_soil_map(const mpm::FfpRun& run, const std::string& title, const std::string& colour_label,
                    std::vector<double> values, double colour_max, const fs::path& png,
                    const Categories* categories = nullptr, double colour_min = 0.0) {
  const mpm::Simulation& s = run.simulation();
  const mpm::Particles& P = s.particles;
  const mpm::MaterialGroup& soil = s.groups[0];
  ColourMap map;
  map.title = title;
  map.x_label = "r (m)";
  map.y_label = "z (m)";
  map.colour_label = colour_label;
  map.x.assign(P.r.begin() + static_cast<std::ptrdiff_t>(soil.begin),
               P.r.begin() + static_cast<std::ptrdiff_t>(soil.end));
  map.y.assign(P.z.begin() + static_cast<std::ptrdiff_t>(soil.begin),
               P.z.begin() + static_cast<std::ptrdiff_t>(soil.end));
  map.value = std::move(values);
  double z_top = 0.0;
  for (double z : map.y) z_top = std::max(z_top, z);
  map.overlays.push_back(outline(run, z_top + 0.05));
  map.colour_min = colour_min;
  map.colour_max = colour_max;
  map.point_size = 0.3;
  if (categories != nullptr) map.palette = categories->palette, map.colour_tics = categories->tics;
  write_png(map, png);
}

/// The 98th percentile of `values` (0 when empty).
double percentile_98(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

std::string map_title(const mpm::FfpRun& run, const std::string& name, const char* what) {
  char title[160];
  std::snprintf(title, sizeof title, "%s: %s at t = %.3f s (penetration %.3f m)", name.c_str(), what,
                run.simulation().time_s, run.penetration_m());
  return title;
}

std::string map_file(const char* stem, double time_s) {
  char file[64];
  std::snprintf(file, sizeof file, "%s_t%.3f.png", stem, time_s);
  return file;
}

}  // namespace

void write_strain_map(const mpm::FfpRun& run, const std::string& name, double colour_max, const fs::path& plots) {
  const mpm::Simulation& s = run.simulation();
  const mpm::MaterialGroup& soil = s.groups[0];
  std::vector<double> strain;
  for (std::size_t i = soil.begin; i < soil.end; ++i) strain.push_back(deviatoric_strain(s.particles.strain[i]));
  write_soil_map(run, map_title(run, name, "deviatoric strain"), "deviatoric strain", std::move(strain), colour_max,
                 plots / map_file("deviatoric_strain", s.time_s));
}

void write_pressure_map(const mpm::FfpRun& run, const std::string& name, const fs::path& plots) {
  const mpm::Simulation& s = run.simulation();
  const mpm::MaterialGroup& soil = s.groups[0];
  std::vector<double> p_kPa;
  for (std::size_t i = soil.begin; i < soil.end; ++i) p_kPa.push_back(1e-3 * mean_pressure(s.particles.stress[i]));
  // Colours up to the 98th percentile: the few particles at the tip would otherwise take the
  // whole scale and hide the pattern of the rest.
  const double top = percentile_98(p_kPa);
  write_soil_map(run, map_title(run, name, "mean stress p"), "p (kPa)", std::move(p_kPa), top > 0.0 ? top : 1.0,
                 plots / map_file("mean_stress", s.time_s));
}

void write_excess_pore_pressure_map(const mpm::FfpRun& run, const std::string& name, const fs::path& plots) {
  const mpm::Simulation& s = run.simulation();
  const mpm::MaterialGroup& soil = s.groups[0];
  std::vector<double> excess_kPa;
  for (std::size_t i = soil.begin; i < soil.end; ++i)
    excess_kPa.push_back(1e-3 * s.two_phase->excess_pressure(s.particles, i));
  // A scale symmetric about 0 (suction blue, excess red) up to the 98th percentile of |p_e|, as the
  // mean stress map: the particles at the tip would take the whole scale.
  std::vector<double> size;
  for (const double e : excess_kPa) size.push_back(std::abs(e));
  double top = percentile_98(std::move(size));
  if (!(top > 0.0)) top = 1.0;
  const Categories diverging{"defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')", ""};
  write_soil_map(run, map_title(run, name, "excess pore pressure"), "p_e (kPa)", std::move(excess_kPa), top,
                 plots / map_file("excess_pore_pressure", s.time_s), &diverging, -top);
}

void write_localisation_map(const mpm::FfpRun& run, const std::string& name, const mpm::LocalisationMap& map,
                            const fs::path& plots) {
  const mpm::Simulation& s = run.simulation();
  const mpm::MaterialGroup& soil = s.groups[0];
  // One colour per place, at the middle of its unit step of the palette.
  std::vector<double> place;
  for (std::size_t i = soil.begin; i < soil.end; ++i) {
    switch (map.place[i]) {
      case mpm::YieldPlace::inside:
        place.push_back(0.5);
        break;
      case mpm::YieldPlace::face:
      case mpm::YieldPlace::edge:
        place.push_back(1.5);
        break;
      case mpm::YieldPlace::apex:
        place.push_back(2.5);
        break;
      case mpm::YieldPlace::localised:
        place.push_back(3.5);
        break;
    }
  }
  const Categories places{
      "defined (0 '#d0d0d0', 1 '#d0d0d0', 1 '#4575b4', 2 '#4575b4', 2 '#fdae61', 3 '#fdae61', 3 '#d73027', "
      "4 '#d73027')",
      "('elastic' 0.5, 'elliptic' 1.5, 'apex' 2.5, 'localised' 3.5)"};
  write_soil_map(run, map_title(run, name, "loss of ellipticity"), "", std::move(place), 4.0,
                 plots / map_file("localisation", s.time_s), &places);
}

void write_localisation_plot(std::span<const LocalisationRow> rows, const std::string& name, const fs::path& plots) {
  std::vector<double> t, fraction, face, edge, localised, apex;
  for (const LocalisationRow& r : rows) {
    t.push_back(r.time_s);
    fraction.push_back(r.fraction);
    face.push_back(r.face);
    edge.push_back(r.edge);
    localised.push_back(r.localised_face + r.localised_edge);
    apex.push_back(r.apex);
  }
  Plot counts = line_plot(t, face, "time (s)", "soil particles", "yielding particles", "on a face");
  counts.series.push_back({t, edge, "on an edge"});
  counts.series.push_back({t, localised, "localised (face or edge)"});
  counts.series.push_back({t, apex, "at the apex (not evaluated)"});
  counts.key_position = "top right";
  write_png_stack({line_plot(t, fraction, "time (s)", "localised share",
                             name + ": localised share of the particles on a face or an edge", name),
                   counts},
                  plots / "localisation.png");
}

void write_ffp_plots(std::span<const FfpSample> samples, const std::string& name, const fs::path& plots) {
  const std::vector<double> t = column(samples, &FfpSample::time_s), depth = column(samples, &FfpSample::penetration_m),
                            velocity = column(samples, &FfpSample::velocity_m_s),
                            deceleration = column(samples, &FfpSample::deceleration_g),
                            reaction = column(samples, &FfpSample::reaction_N);
  Plot penetration = line_plot(t, depth, "time (s)", "penetration (m)", name + ": penetration", name);
  penetration.reverse_y = true;
  write_png_stack({penetration, line_plot(t, velocity, "time (s)", "velocity (m/s)", "velocity", name),
                   line_plot(t, deceleration, "time (s)", "deceleration (g)", "deceleration", name),
                   line_plot(t, reaction, "time (s)", "reaction (N)", "reaction", name)},
                  plots / "time_histories.png");
  write_png_stack({line_plot(depth, velocity, "penetration (m)", "velocity (m/s)", name + ": velocity profile", name),
                   line_plot(depth, deceleration, "penetration (m)", "deceleration (g)", "deceleration profile", name)},
                  plots / "depth_profiles.png");
}

void write_cpt_plot(std::span<const FfpSample> samples, const std::string& name, const fs::path& plots) {
  write_png(line_plot(column(samples, &FfpSample::penetration_m), column(samples, &FfpSample::reaction_N),
                      "penetration (m)", "reaction F_0 (N)", name + ": static reaction profile", name),
            plots / "reaction_profile.png");
}

void write_pressure_settlement_plot(std::span<const FfpSample> samples, const std::string& name,
                                    const PressureSettlement& curve, const fs::path& plots) {
  std::vector<double> ratio, factor;
  for (const FfpSample& s : samples) {
    ratio.push_back(s.penetration_m / curve.base_radius_m);
    factor.push_back(s.reaction_N / curve.base_area_m2 / curve.cohesion_Pa);
  }
  Plot p =
      line_plot(ratio, factor, "settlement / radius s/R", "mean pressure / c'", name + ": pressure–settlement", name);
  const double n = curve.bearing_factor;
  p.series.push_back({{curve.from_ratio, curve.to_ratio}, {n, n}, "plateau mean"});
  p.key_position = "bottom right";
  write_png(p, plots / "pressure_settlement.png");
}

void write_simulated_record(std::span<const FfpSample> samples, const mpm::FfpDescription& model, double mass_kg,
                            const std::string& name, const fs::path& out_dir, const fs::path& plots,
                            std::span<const ShoulderPressureRow> u2) {
  RecordSettings settings;
  settings.mass_kg = mass_kg;
  settings.gravity_m_s2 = model.gravity_m_s2;
  settings.tip = {model.shape.base_radius_m, model.shape.cone_height_m()};
  settings.impact_velocity_m_s = -model.velocity_m_s;
  settings.impact_time_s = 0.0;
  settings.rate_laws = default_rate_laws();
  if (model.soil.saturated && model.soil.water_depth_m >= model.shape.total_length_m()) {
    // Under water from the start: the record kind's water drop, whose q_dyn leaves out the buoyancy
    // ρ_w g V that the run's deceleration holds (the drag: none, the run starts at the impact).
    settings.medium = DropMedium::water;
    settings.fluid_density_kg_m3 = model.soil.fluid.density_kg_m3;
    settings.volume_m3 = model.shape.volume_m3();
  }
  const InterpretedRecord record =
      interpret_record(column(samples, &FfpSample::time_s), column(samples, &FfpSample::deceleration_g), settings);
  std::vector<std::pair<std::string, std::vector<double>>> extra;
  if (!u2.empty()) {
    // The record's rows are the samples after the impact's (as the record kind cuts a measured one).
    std::vector<double> u;
    for (std::size_t k = record.impact_index + 1; k < u2.size(); ++k) u.push_back(u2[k].u2_kPa);
    if (u.size() != record.time_s.size()) throw std::logic_error("record.csv: u2 and the record's rows differ");
    extra.push_back({"pore_pressure_kPa", std::move(u)});
  }
  record_table(record, settings, extra).write(out_dir / "record.csv");
  write_record_plots(record, settings, name, plots / "record_profiles.png");
}

void write_pore_pressure_plot(std::span<const ShoulderPressureRow> rows, const std::string& name,
                              const fs::path& plots) {
  std::vector<double> t, u2, hydrostatic, excess;
  for (const ShoulderPressureRow& r : rows) {
    t.push_back(r.time_s);
    u2.push_back(r.u2_kPa);
    hydrostatic.push_back(r.u2_kPa - r.u2_excess_kPa);
    excess.push_back(r.u2_excess_kPa);
  }
  Plot pressure = line_plot(t, u2, "time (s)", "pore pressure (kPa)", name + ": shoulder pore pressure u2", "u2");
  pressure.series.push_back({t, hydrostatic, "hydrostatic at u2"});
  pressure.key_position = "top right";
  write_png_stack(
      {pressure, line_plot(t, excess, "time (s)", "excess (kPa)", "u2's excess over hydrostatic", "excess")},
      plots / "pore_pressure.png");
}

}  // namespace ffp
