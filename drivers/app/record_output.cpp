#include "drivers/app/record_output.hpp"

#include <cstdio>

#include "reports/plot.hpp"

namespace ffp {

std::vector<RateCorrection> default_rate_laws() {
  return {{RateLaw::logarithmic, 0.1}, {RateLaw::brilli, 0.31}, {RateLaw::inverse_hyperbolic_sine, 0.1}};
}

namespace {
std::string q_sbc_column(const RateCorrection& c) { return "q_sbc_" + std::string(rate_law_name(c.law)) + "_kPa"; }
}  // namespace

CsvTable record_table(const InterpretedRecord& r, const RecordSettings& s,
                      const std::vector<std::pair<std::string, std::vector<double>>>& extra) {
  std::vector<std::string> columns = {"time_s",         "penetration_m",       "velocity_m_s",
                                      "deceleration_g", "q_dyn_projected_kPa", "q_dyn_mantle_kPa"};
  for (const RateCorrection& c : s.rate_laws) columns.push_back(q_sbc_column(c));
  for (const auto& [name, values] : extra) columns.push_back(name);
  CsvTable table(columns);
  for (std::size_t k = 0; k < r.time_s.size(); ++k) {
    std::vector<double> row = {r.time_s[k],         r.penetration_m[k],       r.velocity_m_s[k],
                               r.deceleration_g[k], r.q_dyn_projected_kPa[k], r.q_dyn_mantle_kPa[k]};
    for (const auto& q : r.q_sbc_kPa) row.push_back(q[k]);
    for (const auto& [name, values] : extra) row.push_back(values[k]);
    table.add_row(row);
  }
  return table;
}

nlohmann::json record_summary(const InterpretedRecord& r, const RecordSettings& s) {
  nlohmann::json sum;
  sum["peak_deceleration_g"] = r.peak_deceleration_g;
  sum["time_of_peak_s"] = r.time_of_peak_s;
  sum["depth_of_peak_m"] = r.depth_of_peak_m;
  sum["max_penetration_m"] = r.max_penetration_m;
  sum["final_penetration_m"] = r.final_penetration_m;
  sum["impact_velocity_m_s"] = r.impact_velocity_m_s;
  sum["impact_velocity_source"] = r.impact_velocity_integrated ? "integrated from rest at the first sample" : "given";
  sum["impact_time_s"] = r.impact_time_s;
  sum["impact_time_source"] = r.impact_detected ? "detected" : "given";
  sum["reference_velocity_m_s"] = s.reference_velocity_m_s;
  sum["q_sbc_area"] = s.q_sbc_on_mantle ? "mantle" : "projected";
  nlohmann::json laws = nlohmann::json::object();
  for (const RateCorrection& c : s.rate_laws) laws[std::string(rate_law_name(c.law))] = {{"K", c.k}};
  sum["rate_laws"] = laws;
  return sum;
}

void write_record_plots(const InterpretedRecord& r, const RecordSettings& s, const std::string& name,
                        const std::filesystem::path& png) {
  // Depth on the vertical axis, growing downward, as FFP profiles are drawn.
  auto profile = [&](const std::string& x_label, const std::string& title) {
    Plot p;
    p.title = title;
    p.x_label = x_label;
    p.y_label = "depth (m)";
    p.reverse_y = true;
    p.key_position = "off";
    return p;
  };
  Plot deceleration = profile("net deceleration (g)", name + ": deceleration");
  deceleration.series = {{r.deceleration_g, r.penetration_m, "deceleration"}};
  Plot velocity = profile("velocity (m/s)", "velocity");
  velocity.series = {{r.velocity_m_s, r.penetration_m, "velocity"}};
  Plot q_dyn = profile("q_dyn (kPa)", "dynamic bearing pressure");
  q_dyn.series = {{r.q_dyn_projected_kPa, r.penetration_m, "projected area"},
                  {r.q_dyn_mantle_kPa, r.penetration_m, "mantle area", "lines dashtype 2"}};
  q_dyn.key_position = "bottom right";
  // Logarithmic: q runs from the tip's first touch (a tiny area) down over decades; q ≤ 0 (the body
  // lifted off) is left out of a log axis.
  q_dyn.log_x = true;
  std::vector<Plot> panels = {deceleration, velocity, q_dyn};
  if (!s.rate_laws.empty()) {
    Plot q_sbc = profile("q_sbc (kPa)", std::string("quasi-static bearing (v_ref ") +
                                            std::to_string(s.reference_velocity_m_s).substr(0, 4) + " m/s, " +
                                            (s.q_sbc_on_mantle ? "mantle" : "projected") + " area)");
    for (std::size_t k = 0; k < s.rate_laws.size(); ++k) {
      char label[64];
      std::snprintf(label, sizeof label, "%s K = %g", std::string(rate_law_name(s.rate_laws[k].law)).c_str(),
                    s.rate_laws[k].k);
      q_sbc.series.push_back({r.q_sbc_kPa[k], r.penetration_m, label});
    }
    q_sbc.key_position = "bottom right";
    q_sbc.log_x = true;
    panels.push_back(q_sbc);
  }
  write_png_stack(panels, png, 900, 340);
}

}  // namespace ffp
