/// The moving mesh (Al-Kafaji 2013, paper Fig. 4b) and the FFP grid layout:
/// the band translates with the penetrometer, the zone below compresses and the
/// zone above stretches uniformly, and every size follows min_cell_m.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/math_constants.hpp"
#include "mpm/ffp_model.hpp"
#include "mpm/moving_mesh.hpp"
#include "mpm/simulation.hpp"

using namespace ffp;
using namespace ffp::mpm;

namespace {
constexpr double kExact = 1e-12;  // coordinates of order 1 m: round-off only
}

TEST_CASE("moving mesh: the band translates, the zones below and above scale uniformly, the ends stay",
          "[ffp][moving_mesh]") {
  const std::vector<double> z0 = {-0.4, -0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.3, 0.5};
  const MovingMesh mesh(z0, 3, 7);
  const double u = -0.07;
  const std::vector<double> z = mesh.coordinates(u);
  REQUIRE(z.size() == z0.size());
  CHECK(z.front() == -0.4);
  CHECK(z.back() == 0.5);
  for (int j = 3; j <= 7; ++j) CHECK(z[j] == Approx(z0[j] + u).epsilon(kExact));
  const double below = (z0[3] + u + 0.4) / (z0[3] + 0.4), above = (0.5 - z0[7] - u) / (0.5 - z0[7]);
  for (int j = 0; j < 3; ++j) CHECK(z[j + 1] - z[j] == Approx(below * (z0[j + 1] - z0[j])).epsilon(kExact));
  for (int j = 7; j < 9; ++j) CHECK(z[j + 1] - z[j] == Approx(above * (z0[j + 1] - z0[j])).epsilon(kExact));
  CHECK_THROWS_AS(mesh.coordinates(-0.29), StepFailure);  // the band would squeeze the zone below to ~3 %
}

TEST_CASE(
    "moving mesh: with a margin under the sand (base_row 1) the margin and the sand's base stay, the zone "
    "above the base compresses",
    "[ffp][moving_mesh]") {
  const std::vector<double> z0 = {-0.45, -0.4, -0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.3, 0.5};
  const MovingMesh mesh(z0, 4, 8, 0.0, 1);
  const double u = -0.07;
  const std::vector<double> z = mesh.coordinates(u);
  CHECK(z[0] == -0.45);
  CHECK(z[1] == -0.4);
  for (int j = 4; j <= 8; ++j) CHECK(z[j] == Approx(z0[j] + u).epsilon(kExact));
  const double below = (z0[4] + u + 0.4) / (z0[4] + 0.4);
  for (int j = 1; j < 4; ++j) CHECK(z[j + 1] - z[j] == Approx(below * (z0[j + 1] - z0[j])).epsilon(kExact));
  CHECK_THROWS_AS(MovingMesh(z0, 1, 8, 0.0, 1), std::invalid_argument);  // no compressing zone left
}

TEST_CASE(
    "moving mesh: the band stops where the compressing cells reach min_compressed_cell_m, the zones keep the "
    "limit, and going through the chamber still throws",
    "[ffp][moving_mesh]") {
  // Compressing zone [−0.4, −0.1]: three 0.1 m cells; band −0.1 … 0.1.
  const std::vector<double> z0 = {-0.4, -0.3, -0.2, -0.1, -0.05, 0.0, 0.05, 0.1, 0.3, 0.5};
  const MovingMesh free_mesh(z0, 3, 7), mesh(z0, 3, 7, 0.05);
  // The cells reach 0.05 m when the zone is half its height: u = −0.15.
  CHECK(mesh.band_stop_m() == Approx(-0.15).epsilon(kExact));
  CHECK(free_mesh.band_stop_m() == -std::numeric_limits<double>::infinity());
  const std::vector<double> above_stop = mesh.coordinates(-0.1);
  const std::vector<double> free_above_stop = free_mesh.coordinates(-0.1);
  for (std::size_t j = 0; j < z0.size(); ++j) CHECK(above_stop[j] == free_above_stop[j]);  // no change before the stop
  for (double u : {-0.15, -0.2, -0.26}) {
    INFO("u = " << u);
    const std::vector<double> z = mesh.coordinates(u);
    const std::vector<double> at_stop = free_mesh.coordinates(-0.15);
    for (std::size_t j = 0; j < z0.size(); ++j) CHECK(z[j] == Approx(at_stop[j]).epsilon(kExact));
    for (int j = 0; j < 3; ++j) CHECK(z[j + 1] - z[j] == Approx(0.05).epsilon(kExact));
  }
  CHECK_THROWS_AS(mesh.coordinates(-0.29), StepFailure);  // the penetrometer itself is at the bottom
  CHECK_THROWS_AS(MovingMesh(z0, 3, 7, -0.01), std::invalid_argument);
  // A limit at or above the zone's cells: the band never goes down.
  CHECK(MovingMesh(z0, 3, 7, 0.2).band_stop_m() == 0.0);
}

TEST_CASE("FFP grid: a node on the base radius, fine cells no smaller than min_cell_m, band around the body",
          "[ffp][moving_mesh]") {
  FfpDescription d;
  for (double h : {0.02, 0.01, 0.005}) {
    d.mesh.min_cell_m = h;
    d.mesh.max_cell_m = 3 * h;
    d.mesh.below_cell_m = 2 * h;
    const FfpGridLayout g = ffp_grid_layout(d);
    INFO("min_cell_m = " << h);
    CHECK(std::count(g.r_nodes_m.begin(), g.r_nodes_m.end(), d.shape.base_radius_m) == 1);
    CHECK(g.r_nodes_m.front() == 0.0);
    CHECK(g.r_nodes_m.back() == Approx(d.soil.radius_m).epsilon(kExact));
    CHECK(g.z_nodes_m.front() == Approx(-d.soil.depth_m).epsilon(kExact));
    double smallest = 1.0, largest = 0.0;
    for (const auto* axis : {&g.r_nodes_m, &g.z_nodes_m})
      for (std::size_t k = 1; k < axis->size(); ++k) {
        smallest = std::min(smallest, (*axis)[k] - (*axis)[k - 1]);
        largest = std::max(largest, (*axis)[k] - (*axis)[k - 1]);
      }
    CHECK(smallest == Approx(h).epsilon(1e-9));
    CHECK(largest <= 3 * h * 1.25);  // max_cell, up to the last graded cell's fit
    // The sand surface is a grid line inside the band, and the band holds the whole body.
    CHECK(std::count_if(g.z_nodes_m.begin(), g.z_nodes_m.end(), [](double z) { return std::abs(z) < 1e-12; }) == 1);
    CHECK(g.z_nodes_m[g.band_first] < 0.0);
    CHECK(g.z_nodes_m[g.band_last] > d.shape.total_length_m());
  }
}

TEST_CASE("FFP grid: tip_offset_cells puts the tip that far between two node rows of the band", "[ffp][moving_mesh]") {
  FfpDescription d;
  for (double h : {0.02, 0.01}) {
    d.mesh.min_cell_m = h;
    d.mesh.max_cell_m = 3 * h;
    d.mesh.below_cell_m = 2 * h;
    d.mesh.tip_offset_cells = 0.5;
    const FfpGridLayout g = ffp_grid_layout(d);
    double nearest = 1.0;
    for (int j = g.band_first; j <= g.band_last; ++j) nearest = std::min(nearest, std::abs(g.z_nodes_m[j]));
    INFO("min_cell_m = " << h);
    CHECK(nearest == Approx(0.5 * h).epsilon(1e-9));  // the tip (z = 0) half a cell from the nearest row
    CHECK(g.z_nodes_m[g.band_first] < 0.0);
    CHECK(g.z_nodes_m[g.band_last] > d.shape.total_length_m());
  }
  // tip_offset_cells = 1 (a whole cell: the next row) is refused by the scene reader
  // ("ffp reader: the mesh's offsets lie within a cell ...", tests/app/scene_readers_test.cpp).
}

TEST_CASE("FFP grid: edge_offset_cells puts the base radius that far past the last node column inside it",
          "[ffp][moving_mesh]") {
  FfpDescription d;
  const double R = d.shape.base_radius_m;
  for (const double h : {0.02, 0.01, R / 10.5}) {
    d.mesh.min_cell_m = h;
    d.mesh.max_cell_m = 3 * h;
    d.mesh.below_cell_m = 2 * h;
    d.mesh.min_compressed_cell_m = h;
    d.mesh.edge_offset_cells = 0.5;
    const FfpGridLayout g = ffp_grid_layout(d);
    // The last column at or inside R, and the radial cell there.
    const auto past = std::upper_bound(g.r_nodes_m.begin(), g.r_nodes_m.end(), R);
    REQUIRE(past != g.r_nodes_m.end());
    const double inside = *(past - 1), cell = *past - inside;
    INFO("min_cell_m = " << h << ": last column inside at " << inside << " m, cell " << cell << " m");
    CHECK(R - inside == Approx(0.5 * cell).epsilon(1e-9));  // R midway between two columns
    CHECK(cell >= h * (1.0 - 1e-12));                       // no cell below min_cell_m ...
    const double columns = std::round(inside / cell);
    CHECK((columns + 1.5) * h > R);  // ... and the most columns that allows
    // Uniform from the axis to the fine radius.
    for (std::size_t i = 1; i < g.r_nodes_m.size() && g.r_nodes_m[i] <= d.mesh.fine_radius_m; ++i)
      CHECK(g.r_nodes_m[i] - g.r_nodes_m[i - 1] == Approx(cell).epsilon(1e-9));
  }
  // At min_cell_m = R/(n + ½) (the loop's last) the cells are min_cell_m itself.
  const FfpGridLayout g = ffp_grid_layout(d);
  CHECK(g.r_nodes_m[1] == Approx(d.mesh.min_cell_m).epsilon(1e-12));
  // edge_offset_cells = 1 is refused by the scene reader (tests/app/scene_readers_test.cpp).
}

TEST_CASE("FFP run: the moving band follows the rigid penetrometer and no particle leaves the grid",
          "[ffp][moving_mesh]") {
  FfpDescription d;
  d.soil.law = MohrCoulomb(MohrCoulombParameters{ElasticConstants{2.5e6, 0.33}, 39.0 * kDegree, 0, 0});
  d.mesh.min_cell_m = 0.02;
  d.mesh.max_cell_m = 0.06;
  d.mesh.below_cell_m = 0.04;
  d.contact.friction = std::tan(20.0 * kDegree);
  FfpRun run(d);
  Simulation& s = run.simulation();
  const int band = run.layout().band_first + 3;
  const double z0 = s.grid.z.coordinate(band);
  while (s.time_s < 0.02) run.advance();
  // The band row sits where it started plus the tip's displacement (exact: a translation).
  CHECK(s.grid.z.coordinate(band) == Approx(z0 + (run.tip_z_m() - 0.0)).epsilon(1e-12));
  CHECK(run.penetration_m() > 0.05);  // it did move (5.6 m/s for 20 ms, decelerating)
  CHECK(s.wall_clamps == 0);
}

TEST_CASE("FFP sand: the near zone keeps its particle spacing in the taller compressing cells, K0 stress set",
          "[ffp][moving_mesh]") {
  // Paper section 4: ~10 particles per cell below the FFP, 4 elsewhere. Here 3 × 3 per
  // min-cell² near the axis, at the same spacing in the 2× taller cells of the
  // compressing zone (so the band meets the same density as it moves down), 2 × 2
  // per cell in the far field.
  FfpDescription d;
  d.mesh.min_cell_m = 0.02;
  d.mesh.max_cell_m = 0.06;
  d.mesh.below_cell_m = 0.04;
  FfpRun run(d);
  const Simulation& s = run.simulation();
  const FfpGridLayout& g = run.layout();
  auto count_in_cell = [&](int i, int j) {
    int n = 0;
    for (std::size_t p = 0; p < s.particles.size(); ++p)
      if (s.particles.r[p] > g.r_nodes_m[i] && s.particles.r[p] < g.r_nodes_m[i + 1] &&
          s.particles.z[p] > g.z_nodes_m[j] && s.particles.z[p] < g.z_nodes_m[j + 1])
        ++n;
    return n;
  };
  const int near_band = count_in_cell(0, g.band_first), near_compressing = count_in_cell(0, 1);
  const int far = count_in_cell(static_cast<int>(g.r_nodes_m.size()) - 2, 1);
  CHECK(near_band == 9);
  CHECK(near_compressing == 3 * static_cast<int>(std::lround(3 * (g.z_nodes_m[2] - g.z_nodes_m[1]) / 0.02)));
  CHECK(far == 4);
  // σ'_v = γ·depth at a particle near the bottom (tension-positive Voigt).
  const double gamma = d.soil.density_kg_m3 * d.gravity_m_s2;
  for (std::size_t p = 0; p < s.particles.size(); p += 97)
    CHECK(-s.particles.stress[p][1] == Approx(gamma * -s.particles.z[p]).epsilon(1e-12));
}
