/// Localisation with a fixed width: a strain-softening sand sheared between the walls of a
/// long hollow cylinder (verification/shear_band_cylinder.hpp) forms a shear band one cell wide
/// at every cell size as a classical continuum, and a band of a width set by ℓ, with a
/// converging load–displacement curve, as a micropolar one
/// (docs/verification.md#localisation-with-a-fixed-width).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "models/math_constants.hpp"
#include "verification/shear_band_cylinder.hpp"

using namespace ffp;
using namespace ffp::mpm;
using namespace ffp::verification;

namespace {

constexpr double kDegree = kPi / 180.0;
constexpr double kLength = 1e-3;  // ℓ: 2–5 d50 of the sand (0.2–0.5 mm); every length of the band scales with it

/// What one run at one cell size shows.
struct Level {
  double cell_m;
  BandWidth width;
  double peak_Pa;          ///< the inner wall's largest shear traction T_i = F/(r_i H)
  double traction_3mm_Pa;  ///< T_i at 3 mm of travel
  double traction_end_Pa;  ///< T_i at the end (5 mm)
  double wall_mismatch;    ///< |F_inner − F_outer|/F_inner at the end (statics: 0)
  long steps;
  double cpu_s;
  double measure_error;  ///< max |γ^p − √3 κ| over the cells / max γ^p (laws with κ; else 0)
};

Level run_level(const ShearBandCase& c, double cell_m) {
  const std::clock_t start = std::clock();
  const ShearBandRun run = run_shear_band(c, cell_m);
  const double cpu_s = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  const ShearBandRecord& last = run.history.back();
  // In simple shear κ = √(2/3 e^p:e^p) = γ^p/√3: the band's measure against the law's own.
  double measure_error = 0.0;
  for (std::size_t k = 0; k < run.radius_m.size(); ++k)
    measure_error = std::max(measure_error, std::abs(run.plastic_shear[k] - std::sqrt(3.0) * run.softening[k]));
  return {cell_m,
          band_width(run.radius_m, run.plastic_shear, c.inner_m),
          peak_of(run).inner_force / c.inner_m,
          inner_force_at(run, 3e-3) / c.inner_m,
          inner_force_at(run, c.end_displacement_m) / c.inner_m,
          std::abs(last.inner_force - last.outer_force) / last.inner_force,
          run.steps,
          cpu_s,
          measure_error / *std::ranges::max_element(run.plastic_shear)};
}

std::vector<Level> run_levels(const ShearBandCase& c, const std::vector<double>& cells_m) {
  std::vector<Level> levels;
  for (const double h : cells_m) levels.push_back(run_level(c, h));
  return levels;
}

std::string describe(const Level& l) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << "h " << l.cell_m * 1e3 << " mm: band " << l.width.half_maximum_m * 1e3
    << " mm (" << l.width.half_maximum_m / l.cell_m << " cells), moment width " << l.width.moment_m * 1e3
    << " mm; T_i peak " << l.peak_Pa / 1e3 << " kPa, at 3 mm " << l.traction_3mm_Pa / 1e3 << ", at the end "
    << l.traction_end_Pa / 1e3 << " kPa; walls differ by " << 100.0 * l.wall_mismatch << " %; " << l.steps << " steps, "
    << std::setprecision(1) << l.cpu_s << " s";
  return s.str();
}

/// Classical: the band is the wall's cell at every h. Its value sits at the cell's centre h/2,
/// the next cell's (at 3h/2) is about zero, so the half maximum lies midway: one cell, to a
/// quarter cell (the next cell's share of the maximum would have to reach a quarter).
void check_classical(const std::vector<Level>& levels) {
  for (const Level& l : levels) {
    INFO("classical " << describe(l));
    CHECK(l.width.half_maximum_m / l.cell_m == Approx(1.0).margin(0.25));
    CHECK(l.wall_mismatch < 0.005);  // quasi-static: the walls' forces agree (measured ≤ 0.2 %)
  }
}

/// Micropolar: the band keeps its width, many cells wide; between the two finest levels both
/// widths move by less than one cell of the finer (the half maximum is read off a profile with
/// one value per cell: an interpolation between cell centres); the post-peak traction's
/// differences shrink as h halves, the last a tenth of the softening it measures at most.
void check_micropolar(const std::vector<Level>& levels) {
  for (const Level& l : levels) {
    INFO("micropolar " << describe(l));
    CHECK(l.width.half_maximum_m > 8.0 * l.cell_m);  // resolved: measured 8.5 cells at h = 2 ℓ
    CHECK(l.wall_mismatch < 0.005);
  }
  const Level& coarse = levels[levels.size() - 3];
  const Level& middle = levels[levels.size() - 2];
  const Level& fine = levels.back();
  INFO("micropolar " << describe(coarse) << "\n" << describe(middle) << "\n" << describe(fine));
  CHECK(std::abs(fine.width.half_maximum_m - middle.width.half_maximum_m) < fine.cell_m);
  CHECK(std::abs(fine.width.moment_m - middle.width.moment_m) < fine.cell_m);
  const double earlier = std::abs(middle.traction_end_Pa - coarse.traction_end_Pa);
  const double later = std::abs(fine.traction_end_Pa - middle.traction_end_Pa);
  CHECK(later < earlier);
  CHECK(later < 0.1 * (fine.peak_Pa - fine.traction_end_Pa));
}

/// The band's measure γ^p = 2 ε_rz − σ_rz/G, which any law has, is the softening law's own
/// plastic strain (γ^p = √3 κ in simple shear) to 1 % of its maximum: σ_rz/G is the elastic
/// shear only while the Jaumann rate turns no normal stress into it (measured ≤ 0.05 %).
void check_measure(const std::vector<Level>& levels) {
  for (const Level& l : levels) {
    INFO(describe(l) << "; γ^p against √3 κ: " << l.measure_error);
    CHECK(l.measure_error < 0.01);
  }
}

}  // namespace

TEST_CASE(
    "shear band in a sheared hollow cylinder: one cell wide at every h when classical, "
    "of a width set by l with a converging post-peak force when micropolar",
    "[mpm][verification][micropolar][shear-band]") {
  const std::vector<double> cells = {2.0 * kLength, kLength, 0.5 * kLength};
  const std::vector<Level> classical = run_levels(paper_sand_cylinder(paper_softening_sand(), std::nullopt), cells);
  check_classical(classical);
  check_measure(classical);
  const std::vector<Level> cosserat =
      run_levels(paper_sand_cylinder(paper_softening_sand(), cylinder_micropolar(kLength)), cells);
  check_micropolar(cosserat);
  check_measure(cosserat);
  // The contrast at the finest level: the micropolar band is many classical bands wide.
  CHECK(cosserat.back().width.half_maximum_m > 10.0 * classical.back().width.half_maximum_m);
}

TEST_CASE("shear band with the micro terms held at the sand's friction: still of a fixed width set by l",
          "[mpm][verification][micropolar][shear-band]") {
  // |s| ≤ tan φ'_r p, |m| ≤ ℓ tan φ'_r p (models/micropolar.hpp): the band's regularisation must
  // survive the limits, which bound the micro terms where the grains turn far from the continuum.
  MicropolarParameters limited = cylinder_micropolar(kLength);
  limited.friction_limited = true;
  const std::vector<double> cells = {2.0 * kLength, kLength, 0.5 * kLength};
  const std::vector<Level> levels = run_levels(paper_sand_cylinder(paper_softening_sand(), limited), cells);
  check_measure(levels);
  // Many cells wide at every level, and a width that converges: where the couple stresses slip
  // the band's edge is set by the limit as well as by ℓ, and its width settles at first order
  // (measured: the half-maximum width moves 0.80 then 0.34 mm, the moment width 1.47 then
  // 0.74 mm). A band that followed h would halve instead; the bound 0.6 asks for an order
  // above 0.7 in both.
  for (const Level& l : levels) {
    INFO("micropolar, friction-limited " << describe(l));
    CHECK(l.width.half_maximum_m > 8.0 * l.cell_m);
    CHECK(l.wall_mismatch < 0.005);
  }
  const Level &coarse = levels[0], &middle = levels[1], &fine = levels[2];
  INFO("micropolar, friction-limited " << describe(coarse) << "\n" << describe(middle) << "\n" << describe(fine));
  CHECK(std::abs(fine.width.half_maximum_m - middle.width.half_maximum_m) <
        0.6 * std::abs(middle.width.half_maximum_m - coarse.width.half_maximum_m));
  CHECK(std::abs(fine.width.moment_m - middle.width.moment_m) <
        0.6 * std::abs(middle.width.moment_m - coarse.width.moment_m));
  const double earlier = std::abs(middle.traction_end_Pa - coarse.traction_end_Pa);
  const double later = std::abs(fine.traction_end_Pa - middle.traction_end_Pa);
  CHECK(later < earlier);
  CHECK(later < 0.1 * (fine.peak_Pa - fine.traction_end_Pa));
}

namespace {

/// A Markdown row of the study's tables (docs/verification.md#localisation-with-a-fixed-width).
std::string table_row(const Level& l) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << "| " << l.cell_m * 1e3 << " | " << l.width.half_maximum_m * 1e3 << " | "
    << std::setprecision(2) << l.width.half_maximum_m / l.cell_m << " | " << l.width.moment_m * 1e3 << " | "
    << std::setprecision(3) << l.peak_Pa / 1e3 << " | " << l.traction_3mm_Pa / 1e3 << " | " << l.traction_end_Pa / 1e3
    << " | " << std::setprecision(2) << 100.0 * l.wall_mismatch << " | " << l.steps << " | " << std::setprecision(1)
    << l.cpu_s << " |";
  return s.str();
}

void print_table(const std::string& title, const std::vector<Level>& levels) {
  std::cout << "\n"
            << title << "\n\n"
            << "| h (mm) | band (mm) | band (cells) | moment width (mm) | peak T_i (kPa) | T_i at 3 mm (kPa) | "
               "T_i at 5 mm (kPa) | walls differ (%) | steps | CPU (s) |\n"
            << "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Level& l : levels) std::cout << table_row(l) << "\n";
  std::cout << std::flush;
}

/// The paper's sand as a non-associated, perfectly plastic Mohr–Coulomb: φ' 39°, ψ = 0, c' 0.1 kPa.
MohrCoulomb plastic_sand() { return MohrCoulomb({{2.5e6, 0.33}, 39.0 * kDegree, 0.0, 100.0}); }

}  // namespace

TEST_CASE("shear band study: five cell sizes, the softening and the perfectly plastic sand, and l (hidden: ~5 min)",
          "[.][shear-band-study]") {
  const std::vector<double> cells = {2.0 * kLength, kLength, 0.5 * kLength, 0.25 * kLength, 0.125 * kLength};
  const std::vector<Level> classical = run_levels(paper_sand_cylinder(paper_softening_sand(), std::nullopt), cells);
  print_table("SSMC, classical", classical);
  check_classical(classical);
  check_measure(classical);
  const std::vector<Level> cosserat =
      run_levels(paper_sand_cylinder(paper_softening_sand(), cylinder_micropolar(kLength)), cells);
  print_table("SSMC, micropolar, l = 1 mm", cosserat);
  check_micropolar(cosserat);
  check_measure(cosserat);

  // The perfectly plastic sand has no peak: its classical band is the wall's cell too, kept
  // there by the 1/r stress gradient alone (the law cannot harden), whose margin over the next
  // cell, τ h/r, is 0.008 kPa at h = 0.125 mm: about the drag's dynamic share of the stress
  // (the walls differ by 0.03–0.08 %, 0.01–0.03 kPa), which lets the next cell yield a little
  // at the finest levels (measured 1.11 and 1.26 cells). The band still follows h: half a cell
  // more at most, and 16 times finer cells give a band at least 10 times narrower.
  const std::vector<Level> plastic = run_levels(paper_sand_cylinder(plastic_sand(), std::nullopt), cells);
  print_table("MC (psi = 0, c' = 0.1 kPa), classical", plastic);
  for (const Level& l : plastic) {
    INFO("classical " << describe(l));
    CHECK(l.width.half_maximum_m / l.cell_m < 1.5);
  }
  CHECK(plastic.back().width.half_maximum_m < 0.1 * plastic.front().width.half_maximum_m);
  // The micropolar skew stress hardens the response: no peak, a band of fixed width.
  const std::vector<Level> plastic_cosserat =
      run_levels(paper_sand_cylinder(plastic_sand(), cylinder_micropolar(kLength)), cells);
  print_table("MC (psi = 0, c' = 0.1 kPa), micropolar, l = 1 mm", plastic_cosserat);
  const BandWidth& finest = plastic_cosserat.back().width;
  const BandWidth& next = plastic_cosserat[cells.size() - 2].width;
  CHECK(std::abs(finest.half_maximum_m - next.half_maximum_m) < cells.back());
  CHECK(std::abs(finest.moment_m - next.moment_m) < cells.back());

  // ℓ sets the width: ℓ = 0.5, 1, 2 mm on cells of ℓ/2 in a wall of 0.1 m, each band taken 5 ℓ
  // past the peak (the same slip per unit ℓ).
  std::cout << "\nSSMC, micropolar, r 0.5-0.6 m, h = l/2, 5 l past the peak\n\n"
            << "| l (mm) | band (mm) | band / l | moment width / l | peak T_i (kPa) | CPU (s) |\n"
            << "| ---: | ---: | ---: | ---: | ---: | ---: |\n";
  std::vector<double> width_per_length;
  for (const double length : {0.5 * kLength, kLength, 2.0 * kLength}) {
    ShearBandCase c = paper_sand_cylinder(paper_softening_sand(), cylinder_micropolar(length));
    c.outer_m = 0.6;
    c.end_past_peak_m = 5.0 * length;
    c.end_displacement_m = 4e-3 + 6.0 * length;  // the peak comes at about 3.5 mm of travel
    const Level l = run_level(c, 0.5 * length);
    width_per_length.push_back(l.width.half_maximum_m / length);
    std::cout << std::fixed << std::setprecision(1) << "| " << length * 1e3 << " | " << l.width.half_maximum_m * 1e3
              << " | " << width_per_length.back() << " | " << l.width.moment_m / length << " | " << std::setprecision(3)
              << l.peak_Pa / 1e3 << " | " << std::setprecision(1) << l.cpu_s << " |\n"
              << std::flush;
  }
  // ∝ ℓ to 10 %: the band's stress gradient (1/r) and the wall's elastic travel do not scale with ℓ.
  CHECK(width_per_length.front() == Approx(width_per_length[1]).epsilon(0.1));
  CHECK(width_per_length.back() == Approx(width_per_length[1]).epsilon(0.1));
}
