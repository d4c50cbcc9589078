#include "reports/studies/shear_band_section.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "reports/plot.hpp"
#include "verification/shear_band_cylinder.hpp"

namespace ffp {

namespace {

using verification::ShearBandRun;

/// ℓ of the verification's cylinder: 2–5 d50 of the sand's 0.2–0.5 mm bracket, so that the band
/// (about 16 ℓ) spans many cells of sizes that run in seconds; every length of the band scales
/// with ℓ (docs/verification.md#localisation-with-a-fixed-width).
constexpr double kLength_m = 1e-3;
/// 4 ℓ to ℓ/2: the micropolar band from 4 to 32 cells wide. Each halving costs about four times
/// the level before (twice the cells, twice the steps); the two finer levels of
/// docs/verification.md (ℓ/4, ℓ/8) would add about twenty times the finest level's time.
const std::vector<double> kCells_m = {4 * kLength_m, 2 * kLength_m, kLength_m, kLength_m / 2};
/// The wall's travel at which the post-peak forces are compared (the run's end) and an earlier one.
constexpr double kEarlyTravel_m = 3e-3;

/// One level of one continuum.
struct CylinderLevel {
  double cell_m;
  ShearBandRun run;
  verification::BandWidth width;
  double peak_Pa, early_Pa, end_Pa;  ///< the inner wall's shear traction T_i = F/(2π r_i H)
  double wall_mismatch;              ///< |F_inner − F_outer|/F_inner at the end (statics: 0)
  double wall_s;
};

struct Continuum {
  std::string name;
  std::vector<CylinderLevel> levels;
};

Continuum run_levels(const std::string& name, const verification::ShearBandCase& c) {
  Continuum out{name, {}};
  for (const double h : kCells_m) {
    const auto start = std::chrono::steady_clock::now();
    ShearBandRun run = verification::run_shear_band(c, h);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto& last = run.history.back();
    CylinderLevel level{h,
                        {},
                        verification::band_width(run.radius_m, run.plastic_shear, c.inner_m),
                        verification::peak_of(run).inner_force / c.inner_m,
                        verification::inner_force_at(run, kEarlyTravel_m) / c.inner_m,
                        verification::inner_force_at(run, c.end_displacement_m) / c.inner_m,
                        std::abs(last.inner_force - last.outer_force) / last.inner_force,
                        wall_s};
    level.run = std::move(run);
    out.levels.push_back(std::move(level));
  }
  return out;
}

std::string in_mm(double length_m, int decimals) { return fixed(1e3 * length_m, decimals); }

std::vector<std::vector<std::string>> table_rows(const std::vector<Continuum>& continua) {
  std::vector<std::vector<std::string>> rows;
  for (const Continuum& c : continua)
    for (const CylinderLevel& l : c.levels)
      rows.push_back({c.name, in_mm(l.cell_m, 2), in_mm(l.width.half_maximum_m, 2),
                      fixed(l.width.half_maximum_m / l.cell_m, 2), in_mm(l.width.moment_m, 2),
                      fixed(l.peak_Pa / 1e3, 3), fixed(l.early_Pa / 1e3, 3), fixed(l.end_Pa / 1e3, 3),
                      fixed(100 * l.wall_mismatch, 2), std::to_string(l.run.steps), fixed(l.wall_s, 2)});
  return rows;
}

std::string level_label(const CylinderLevel& l) { return "h = " + in_mm(l.cell_m, 2) + " mm"; }

/// γ^p across the annulus, one panel per continuum, one curve per level.
void profiles_figure(const std::vector<Continuum>& continua, double inner_m, StudyOutput& out) {
  std::vector<Plot> panels;
  for (const Continuum& c : continua) {
    Plot p{c.name + ": plastic shear strain across the annulus at the end",
           "distance from the inner wall (mm)",
           "plastic shear strain γ^p",
           {}};
    for (const CylinderLevel& l : c.levels) {
      Series s{{}, l.run.plastic_shear, level_label(l), "linespoints pointsize 0.5"};
      for (const double r : l.run.radius_m) s.x.push_back(1e3 * (r - inner_m));
      p.series.push_back(std::move(s));
    }
    panels.push_back(std::move(p));
  }
  const std::string name = "shear_band_profiles.png";
  if (write_png_stack(panels, out.figures_dir / name))
    out.document.figure(out.figures_relative + "/" + name,
                        "Plastic shear strain γ^p = |2 ε_rz − σ_rz/G| of each cell against the distance from the "
                        "dragged inner wall, at the end of the wall's travel");
}

/// T_i against the wall's travel, one panel per continuum, one curve per level.
void force_figure(const std::vector<Continuum>& continua, double inner_m, StudyOutput& out) {
  std::vector<Plot> panels;
  for (const Continuum& c : continua) {
    Plot p{c.name + ": the inner wall's shear traction", "wall travel (mm)", "T_i (kPa)", {}};
    p.key_position = "bottom right";
    for (const CylinderLevel& l : c.levels) {
      Series s{{}, {}, level_label(l)};
      const auto& h = l.run.history;
      const std::size_t stride = std::max<std::size_t>(1, h.size() / 1500);  // a figure's worth of points
      for (std::size_t k = 0; k < h.size(); k += stride) {
        s.x.push_back(1e3 * h[k].displacement_m);
        s.y.push_back(h[k].inner_force / inner_m / 1e3);
      }
      p.series.push_back(std::move(s));
    }
    panels.push_back(std::move(p));
  }
  const std::string name = "shear_band_forces.png";
  if (write_png_stack(panels, out.figures_dir / name))
    out.document.figure(out.figures_relative + "/" + name,
                        "The inner wall's shear traction T_i = F/(2π r_i H) against its travel (the wall force per "
                        "metre of height is 2π r_i T_i)");
}

/// "a / b / c" of f over the levels.
template <class F>
std::string over_levels(const Continuum& c, F f, int decimals) {
  std::string s;
  for (const CylinderLevel& l : c.levels) s += (s.empty() ? "" : " / ") + fixed(f(l), decimals);
  return s;
}

/// "a, b and c": |f(level k+1) − f(level k)| for each halving.
template <class F>
std::string steps_over_levels(const Continuum& c, F f, int decimals) {
  std::string s;
  const auto& v = c.levels;
  for (std::size_t k = 1; k < v.size(); ++k)
    s += (k == 1 ? "" : k + 1 == v.size() ? " and " : ", ") + fixed(std::abs(f(v[k]) - f(v[k - 1])), decimals);
  return s;
}

void describe(const Continuum& classical, const Continuum& micropolar, double wall_s, StudyOutput& out) {
  const auto cells = [](const CylinderLevel& l) { return l.width.half_maximum_m / l.cell_m; };
  const auto width_mm = [](const CylinderLevel& l) { return 1e3 * l.width.half_maximum_m; };
  const auto end_kPa = [](const CylinderLevel& l) { return l.end_Pa / 1e3; };
  const CylinderLevel& finest = micropolar.levels.back();
  const auto [fewest, most] = std::minmax_element(classical.levels.begin(), classical.levels.end(),
                                                  [&](const auto& a, const auto& b) { return cells(a) < cells(b); });
  out.document.paragraph(
      "*Classical:* the band is " + fixed(cells(*fewest), 2) + " to " + fixed(cells(*most), 2) +
      " cells wide at every level (" + over_levels(classical, width_mm, 2) +
      " mm): its width follows h. *Micropolar* (ℓ = " + in_mm(kLength_m, 1) +
      " mm): " + over_levels(micropolar, width_mm, 2) + " mm, " + over_levels(micropolar, cells, 1) +
      " cells; it moves by " + steps_over_levels(micropolar, width_mm, 2) + " mm per halving of h and is " +
      fixed(finest.width.half_maximum_m / kLength_m, 1) +
      " ℓ wide at the finest level. The post-peak force converges with it: T_i at " + in_mm(5e-3, 0) +
      " mm of travel " + over_levels(micropolar, end_kPa, 3) + " kPa, steps " +
      steps_over_levels(micropolar, end_kPa, 3) + " kPa against " + fixed((finest.peak_Pa - finest.end_Pa) / 1e3, 2) +
      " kPa of softening since the peak; the classical curves drop from the same peak to the residual (" +
      over_levels(classical, end_kPa, 3) + " kPa at the end) more steeply the finer the cell.");
  // Each halving costs the measured ratio of the two finest micropolar levels again.
  const double ratio = finest.wall_s / micropolar.levels[micropolar.levels.size() - 2].wall_s;
  out.document.paragraph(
      "The " + std::to_string(classical.levels.size() + micropolar.levels.size()) + " cylinder runs took " +
      fixed(wall_s, 1) + " s of wall time in the report's own process, the finest micropolar level " +
      fixed(finest.wall_s, 1) + " s, " + fixed(ratio, 1) +
      " times the level before it (twice the cells, twice the steps). The levels stop at ℓ/2 to keep the report "
      "cheap: ℓ/4 and ℓ/8 would add about " +
      fixed(finest.wall_s * (ratio + ratio * ratio), 0) +
      " s more; they, and the band's width against ℓ, are in docs/verification.md#localisation-with-a-fixed-width.");
}

}  // namespace

ShearBandFindings write_shear_band_section(StudyOutput& out) {
  const auto sand = verification::paper_softening_sand();
  const verification::ShearBandCase classical_case = verification::paper_sand_cylinder(sand, std::nullopt);
  const verification::ShearBandCase micropolar_case =
      verification::paper_sand_cylinder(sand, verification::cylinder_micropolar(kLength_m));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Continuum> continua = {run_levels("classical", classical_case),
                                           run_levels("micropolar", micropolar_case)};
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double r_i = classical_case.inner_m;
  out.document.paragraph(
      "The paper's sand as SSMC (φ'_p 39° → φ'_r 32°, η = 8, ψ = 0, c' = 0) sheared between the walls of a long "
      "hollow cylinder (r_i = " +
      fixed(r_i, 2) + " m, r_o = " + fixed(classical_case.outer_m, 2) +
      " m, p0 = " + fixed(classical_case.confinement_Pa / 1e3, 0) +
      " kPa, the inner wall dragged axially, the outer fixed; verification/shear_band_cylinder.hpp, "
      "docs/verification.md#localisation-with-a-fixed-width), as a classical continuum and as a micropolar one "
      "(G_c = G/2, j = ℓ²), at cells of 4 ℓ to ℓ/2. The band is where γ^p exceeds half its largest value (one value "
      "per cell, linear between cell centres); the moment width is 2 ∫ (r − r_i) γ^p dr / ∫ γ^p dr.");
  out.document.table(
      {"continuum", "h (mm)", "band (mm)", "band (cells)", "moment width (mm)", "peak T_i (kPa)",
       "T_i at " + in_mm(kEarlyTravel_m, 0) + " mm (kPa)",
       "T_i at " + in_mm(classical_case.end_displacement_m, 0) + " mm (kPa)", "walls differ (%)", "steps", "wall (s)"},
      table_rows(continua));
  describe(continua[0], continua[1], wall_s, out);
  profiles_figure(continua, r_i, out);
  force_figure(continua, r_i, out);
  const CylinderLevel& finest = continua[1].levels.back();
  return {finest.width.half_maximum_m / kLength_m, wall_s};
}

}  // namespace ffp
