/// The chamber's echo: the reference FFP in the paper's chamber (0.4 m deep,
/// 0.4 m in radius, a fixed base and a wall on rollers) and in deeper, wider and
/// larger ones. The sand's p-wave, reflected by the base and the wall, returns
/// to the cone while it is still decelerating; the study predicts when from the
/// elastic wave speed and measures when each chamber's reaction leaves the
/// largest chamber's; and the paper's chamber with absorbing walls.
#include <array>
#include <cmath>

#include "models/elastic.hpp"
#include "reports/studies/ffp_figures.hpp"
#include "reports/studies/studies.hpp"
#include "reports/studies/study_helpers.hpp"

namespace ffp {

namespace {

struct Chamber {
  double depth_m, radius_m;
  bool absorbing;  ///< soil.walls absorbing instead of the paper's rigid walls
  const char* label;
};

// The paper's chamber first; the largest is the one the others are compared with (its own echo
// returns after the others have left it); last the paper's chamber with absorbing walls.
constexpr std::array<Chamber, 6> kChambers = {{{0.4, 0.4, false, "paper's chamber, 0.4 m deep × 0.4 m radius"},
                                               {0.8, 0.4, false, "twice as deep"},
                                               {0.4, 0.8, false, "twice as wide"},
                                               {0.8, 0.8, false, "twice as deep and wide"},
                                               {1.6, 1.6, false, "four times as deep and wide"},
                                               {0.4, 0.4, true, "paper's chamber, absorbing walls"}}};
constexpr std::size_t kLargest = 4;
constexpr std::size_t kAbsorbing = 5;
static_assert(kChambers[kLargest].depth_m == 1.6 && kChambers[kAbsorbing].absorbing);

// A chamber's reaction has left the largest chamber's when their 2 ms means differ by more than this
// share of the largest chamber's peak (the reaction's step-to-step noise is a few per cent of it).
constexpr double kDepartureShare = 0.05;
constexpr double kMeanWindow_s = 0.002;

/// The p-wave speed of the scene's linear-elastic sand, c_p = √(M/ρ).
double p_wave_speed_m_s(const nlohmann::json& material) {
  const ElasticConstants elastic{1e3 * material.at("E_kPa").get<double>(), material.at("nu").get<double>()};
  return elastic.p_wave_speed(material.at("density_kg_m3").get<double>());
}

/// The 2 ms running mean of the reaction at each history row.
std::vector<double> mean_reaction(const CsvData& h) {
  const auto& t = h.column("time_s");
  const auto& f = h.column("reaction_N");
  std::vector<double> mean(t.size());
  std::size_t first = 0;
  double sum = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    sum += f[k];
    while (t[first] <= t[k] - kMeanWindow_s) sum -= f[first++];
    mean[k] = sum / static_cast<double>(k - first + 1);
  }
  return mean;
}

/// When the base's echo reaches the tip: the wave leaves the surface at impact, goes down to the base
/// and back up to the tip, c_p t = 2H − z(t).
double base_echo_s(const CsvData& h, double depth_m, double c_p) {
  const auto& t = h.column("time_s");
  const auto& z = h.column("penetration_m");
  for (std::size_t k = 0; k < t.size(); ++k)
    if (c_p * t[k] >= 2 * depth_m - z[k]) return t[k];
  return std::nan("");
}

/// When the wall's echo reaches the cone: out from the cone's side and back, 2(R − R_cone)/c_p.
double wall_echo_s(double radius_m, double cone_radius_m, double c_p) { return 2 * (radius_m - cone_radius_m) / c_p; }

}  // namespace

Study ffp_chamber_study(const std::filesystem::path& scenes_dir) {
  Study study;
  study.title = "The chamber's echo: the reference FFP in larger chambers";
  for (const auto& c : kChambers) {
    study.runs.push_back(
        scene_run(scenes_dir, "ffp_reference.json", c.label,
                  {"soil.depth_m=" + fixed(c.depth_m, 2), "soil.radius_m=" + fixed(c.radius_m, 2),
                   std::string("soil.walls=") + (c.absorbing ? "absorbing" : "rigid"), "output.field_times_s=[]"}));
    // Far from the cone the cells grow, so the particles grow about as the square root of the area.
    study.runs.back().expected_wall_s = 2.0 * std::sqrt(c.depth_m * c.radius_m / (0.4 * 0.4));
  }
  study.write = [](const StudyResults& results, StudyOutput& out) {
    auto& md = out.document;
    const auto reference = results.summary(kLargest);
    const auto paper = results.summary(0);
    if (reference.empty() || paper.empty()) {
      md.paragraph("The paper's or the largest chamber's run failed; the comparison is left out.");
      return;
    }
    const double c_p = p_wave_speed_m_s(paper.at("scene").at("material"));
    const double cone_radius_m = paper.at("scene").at("ffp").at("base_radius_m").get<double>();
    const CsvData largest = results.history(kLargest);
    const std::vector<double> largest_mean = mean_reaction(largest);
    double largest_peak_N = 0;
    for (double f : largest_mean) largest_peak_N = std::max(largest_peak_N, f);
    const double largest_echo_s = std::min(base_echo_s(largest, kChambers[kLargest].depth_m, c_p),
                                           wall_echo_s(kChambers[kLargest].radius_m, cone_radius_m, c_p));
    md.paragraph(
        "The reference scene (1 cm mesh, the scene's settings) in the paper's chamber (section 3: 0.8 m across, "
        "0.4 m of sand on a fixed base, the wall on rollers) and in chambers two and four times as deep or as wide. "
        "The sand is linear elastic inside its yield surface, E' = " +
        fixed(paper.at("scene").at("material").at("E_kPa").get<double>(), 0) +
        " kPa, so its p-wave travels at c_p = √(M/ρ) = " + fixed(c_p, 1) +
        " m/s, and what the impact sends down and out comes back to the cone from the base after t with c_p t = 2H − "
        "z(t) (z the tip's depth) and from the wall after 2(R − R_cone)/c_p. The largest chamber's echoes return "
        "after " +
        fixed(1000 * largest_echo_s, 1) +
        " ms, so until then it stands for a sand without walls; each other chamber's reaction is said to leave it "
        "when their 2 ms means differ by more than " +
        fixed(100 * kDepartureShare, 0) + " % of the largest chamber's peak (" + fixed(largest_peak_N, 0) + " N).");
    std::vector<std::vector<std::string>> rows;
    std::vector<LabelledRun> runs;
    for (std::size_t i = 0; i < kChambers.size(); ++i) {
      runs.push_back({i, kChambers[i].label});
      if (!results.ok(i)) {
        rows.push_back({kChambers[i].label, "FAILED: " + results.outcome(i).error});
        continue;
      }
      const CsvData h = results.history(i);
      const bool echoes = !kChambers[i].absorbing;
      const double base_s = echoes ? base_echo_s(h, kChambers[i].depth_m, c_p) : std::nan("");
      const double wall_s = echoes ? wall_echo_s(kChambers[i].radius_m, cone_radius_m, c_p) : std::nan("");
      std::string departure = "–";
      if (i != kLargest) {
        const std::vector<double> mean = mean_reaction(h);
        const auto& t = h.column("time_s");
        departure = "none before " + fixed(1000 * largest_echo_s, 1);
        for (std::size_t k = 0; k < t.size() && t[k] < largest_echo_s; ++k) {
          if (t[k] < kMeanWindow_s) continue;
          if (std::abs(mean[k] - interpolate(largest.column("time_s"), largest_mean, t[k])) >
              kDepartureShare * largest_peak_N) {
            departure = fixed(1000 * t[k], 1);
            break;
          }
        }
      }
      rows.push_back(
          {kChambers[i].label, fixed(kChambers[i].depth_m, 1), fixed(kChambers[i].radius_m, 1), fixed(1000 * base_s, 1),
           fixed(1000 * wall_s, 1), departure, fixed(figure(results, i, "peak_deceleration_2ms_g"), 2),
           fixed(1000 * figure(results, i, "time_of_peak_s"), 1),
           fixed(100 * figure(results, i, "max_penetration_m"), 2),
           fixed(100 * figure(results, i, "final_penetration_m"), 2), fixed(100 * figure(results, i, "rebound_m"), 2)});
    }
    md.table({"chamber", "depth H [m]", "radius R [m]", "base echo [ms]", "wall echo [ms]",
              "reaction leaves the largest's [ms]", "2 ms peak [g]", "time of peak [ms]", "max penetration [cm]",
              "final penetration [cm]", "rebound [cm]"},
             rows);
    const double peak_paper = figure(results, 0, "peak_deceleration_2ms_g");
    const double peak_largest = figure(results, kLargest, "peak_deceleration_2ms_g");
    md.paragraph(
        "Every chamber's run is the same until its first echo returns, and leaves the largest chamber's a few "
        "milliseconds after (the echo builds up over the wave's rise). In the paper's chamber the base's and the "
        "wall's echoes return together, and the 2 ms peak deceleration, " +
        fixed(peak_paper, 2) + " g at " + fixed(1000 * figure(results, 0, "time_of_peak_s"), 1) + " ms, is " +
        fixed(100 * std::abs(peak_paper / peak_largest - 1), 0) +
        (peak_paper >= peak_largest ? " % above" : " % below") + " the largest chamber's " + fixed(peak_largest, 2) +
        " g (the likely mechanism: the returned compression raises the mean stress around the cone, and with it the "
        "strength of a sand whose strength is its friction). The later dip of the reaction and its second rise "
        "come after the echoes as well. The experiment's chamber has the paper's size; how much of this its record "
        "carries depends on the real sand's wave speed and on how stiff its walls are, which the model takes as " +
        fixed(c_p, 1) + " m/s and rigid.");
    const double peak_absorbing = figure(results, kAbsorbing, "peak_deceleration_2ms_g");
    const double deepest_absorbing = figure(results, kAbsorbing, "max_penetration_m");
    const double deepest_largest = figure(results, kLargest, "max_penetration_m");
    md.paragraph(
        "With absorbing walls (soil.walls absorbing: dashpots ρc_p and ρc_s on the base and the wall, with the "
        "springs of a viscous-spring boundary, α G/R, R the distance from the impact point) the paper's chamber "
        "gives a 2 ms peak of " +
        fixed(peak_absorbing, 2) + " g and a deepest penetration of " + fixed(100 * deepest_absorbing, 2) +
        " cm, against the largest chamber's " + fixed(peak_largest, 2) + " g and " + fixed(100 * deepest_largest, 2) +
        " cm (" + fixed(100 * (peak_absorbing / peak_largest - 1), 1) + " % and " +
        fixed(100 * (deepest_absorbing / deepest_largest - 1), 1) + " %; with the rigid walls " +
        fixed(100 * (peak_paper / peak_largest - 1), 1) + " % and " +
        fixed(100 * (figure(results, 0, "max_penetration_m") / deepest_largest - 1), 1) +
        " %): the setting for a drop into a sand that goes on beyond the model, as in the field.");
    ffp_time_histories_figure(results, runs, "Chamber size", "chamber_echo.png", out);
  };
  return study;
}

}  // namespace ffp
