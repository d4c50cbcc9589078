/// Checks on what the `ffp` program writes (history.csv,
/// summary.json) for the reference scene on a coarse (2 cm) mesh: impulse and
/// momentum, the weight carried at rest, no deep intrusion; and the CPT's push
/// speed. Each run takes a second or a few.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ffp_test_support.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {
constexpr double kG = 9.81;
constexpr double kMass = 7.71;
}  // namespace

TEST_CASE("reference FFP on 2 cm: M (v0 - v(t)) equals the integral of (R - M g) dt from history.csv within 1 %",
          "[ffp][program][momentum]") {
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  const ProgramResult r = run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet",
                                       "--set", "mesh.min_cell_m=0.02", "--set", "output.field_times_s=[]"},
                                      scratch.path());
  REQUIRE(r.exit_code == 0);
  const CsvData h = read_numeric_csv(out / "history.csv");
  const nlohmann::json summary = read_json(out / "summary.json");
  const auto& t = h.column("time_s");
  const auto& v = h.column("velocity_m_s");
  const auto& reaction = h.column("reaction_N");
  const double v0 = 5.6, scale = kMass * v0;
  // reaction_N on a row is the mean over the interval ending there, so the
  // rectangle rule on the rows is the exact impulse; the trapezoid rule is what
  // a reader of point samples would use, and must agree too.
  double exact = 0.0, trapezoid = 0.0, worst_exact = 0.0, worst_trapezoid = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double dt = t[k] - t[k - 1];
    exact += (reaction[k] - kMass * kG) * dt;
    trapezoid += (0.5 * (reaction[k] + reaction[k - 1]) - kMass * kG) * dt;
    const double momentum = kMass * (v0 - v[k]);
    worst_exact = std::max(worst_exact, std::abs(momentum - exact) / scale);
    worst_trapezoid = std::max(worst_trapezoid, std::abs(momentum - trapezoid) / scale);
  }
  INFO("worst |M(v0 − v) − ∫(R − Mg)dt| / (M v0): rectangle " << worst_exact << ", trapezoid " << worst_trapezoid);
  CHECK(worst_exact < 0.01);
  CHECK(worst_trapezoid < 0.01);
  CHECK(summary["momentum_balance_error"].get<double>() < 1e-9);  // the exact impulse: round-off only
  // The split of the same impulse by where it is taken: the top (0.58 m above the tip)
  // never meets the sand, so cone + shaft is all of it (to the CSV's 10 digits); the
  // cone's normal part is the bearing, the rest of it the flank's friction (δ = 20°
  // against the sand sliding up: both parts push the body up).
  const double total = h.column("impulse_N_s").back(), cone = h.column("cone_impulse_N_s").back();
  const double cone_normal = h.column("cone_normal_impulse_N_s").back(), shaft = h.column("shaft_impulse_N_s").back();
  INFO("impulse " << total << " N s: cone " << cone << " (normal " << cone_normal << "), shaft " << shaft);
  CHECK(std::abs(total - cone - shaft) < 1e-6 * total);
  CHECK(cone_normal > 0.0);
  CHECK(cone_normal < cone);
  // It did stop: the FFP lost all of its momentum within the 0.15 s.
  CHECK(summary["max_penetration_m"].get<double>() > 0.1);
  CHECK(std::abs(v.back()) < 0.05 * v0);
}

TEST_CASE("reference FFP on 2 cm: no soil particle ends up deeper inside the FFP than a cell",
          "[ffp][program][intrusion]") {
  // Contact acts at the nodes of the penetrometer: a particle near the surface
  // moves with a blend of corrected and free nodes and lags behind the surface
  // until enough of its support is corrected. Once it is a full cell deep every
  // node of its linear support is a penetrometer node, so a particle deeper than
  // a cell would mean the contact failed.
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  REQUIRE(run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                       "mesh.min_cell_m=0.02", "--set", "end_time_s=0.08", "--set", "output.field_times_s=[]"},
                      scratch.path())
              .exit_code == 0);
  const nlohmann::json summary = read_json(out / "summary.json");
  INFO("deepest soil particle inside the outline: " << summary["max_soil_intrusion_m"] << " m");
  CHECK(summary["max_soil_intrusion_cells"].get<double>() < 1.0);
  // With the contact surface centred on the outline (nodes up to h/2 outside, the
  // default) the deepest particle stays within a quarter cell: 0.07 cells measured
  // here, 0.16 at 1 cm; with nodes inside the outline only, 0.71 and 0.74.
  CHECK(summary["max_soil_intrusion_cells"].get<double>() <= 0.25);
  // Disconnected sand is held at V/V0 = 1/0.5: nothing inflates past it.
  CHECK(summary["max_volume_ratio"].get<double>() <= 2.0 * (1.0 + 1e-9));
  CHECK(summary["inflated_particles_max"].get<long>() >= 0);
  CHECK(summary["wall_clamps"].get<long>() == 0);
}

TEST_CASE(
    "reference FFP on 2 cm and 1 cm: no soil particle deeper inside than a quarter cell (contact.project_particles by "
    "default)",
    "[ffp][program][intrusion][projection]") {
  // Without the projection the deepest particle creeps in while the sand slides up
  // the cone's upper flank (0.07 cells at 2 cm, 0.14 at 1 cm by 0.04 s, 0.34 and 0.41 at 0.5 and
  // 0.25 cm by the end). With it every particle found inside after a step is put back onto the
  // outline, so what is left is round-off, and one step's intrusion (before the projection) is
  // a small fraction of a cell (measured: 0.001 cells at both levels). By 0.04 s the tip is
  // 14–16 cm deep and the sand has been sliding up the whole cone for 25 ms.
  for (const char* h : {"0.02", "0.01"}) {
    ScratchDir scratch;
    const auto out = scratch.path() / "run";
    REQUIRE(run_program(
                {"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                 std::string("mesh.min_cell_m=") + h, "--set", "end_time_s=0.04", "--set", "output.field_times_s=[]"},
                scratch.path())
                .exit_code == 0);
    const nlohmann::json summary = read_json(out / "summary.json");
    INFO("h = " << h << " m: deepest soil particle inside the outline " << summary["max_soil_intrusion_m"]
                << " m, deepest before a projection " << summary["max_projection_depth_m"] << " m");
    const std::vector<std::string> stages = summary["stages"];
    CHECK(std::find(stages.begin(), stages.end(), "project_soil_particles") != stages.end());
    CHECK(summary["projected_particles_max"].get<long>() > 0);  // it did act
    CHECK(summary["max_soil_intrusion_cells"].get<double>() <= 0.25);
    CHECK(summary["max_soil_intrusion_cells"].get<double>() < 1e-9);  // on the outline to round-off
    CHECK(summary["max_projection_depth_cells"].get<double>() <= 0.25);
    CHECK(summary["momentum_balance_error"].get<double>() < 1e-9);  // positions only: the impulse stays exact
    CHECK(summary["max_penetration_m"].get<double>() > 0.1);
    CHECK(summary["wall_clamps"].get<long>() == 0);
  }
  // The control: without the projection the same 1 cm run leaves sand 0.14 cells inside (measured).
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  REQUIRE(
      run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                   "end_time_s=0.04", "--set", "contact.project_particles=false", "--set", "output.field_times_s=[]"},
                  scratch.path())
          .exit_code == 0);
  CHECK(read_json(out / "summary.json")["max_soil_intrusion_cells"].get<double>() > 0.1);
}

TEST_CASE("FFP at rest on 2 cm: the reaction equals its weight (75.6 N) within 5 %", "[ffp][program][rest]") {
  // Dropped at 1 m/s it stops within ~0.1 s; the reaction then oscillates slowly
  // (the body bouncing on the elastic sand, undamped), so the mean over the last
  // 0.15 s (several periods) is compared. 5 %: the part of a period left over in the
  // window biases the mean of an undamped swing by a few per cent.
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  REQUIRE(run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                       "mesh.min_cell_m=0.02", "--set", "end_time_s=0.4", "--set", "ffp.impact_velocity_m_s=1.0",
                       "--set", "output.field_times_s=[]"},
                      scratch.path())
              .exit_code == 0);
  const CsvData h = read_numeric_csv(out / "history.csv");
  const auto& t = h.column("time_s");
  const auto& impulse = h.column("impulse_N_s");
  std::size_t from = 0;
  while (t[from] < 0.25) ++from;
  const double mean = (impulse.back() - impulse[from]) / (t.back() - t[from]);
  INFO("mean reaction over " << t[from] << "–" << t.back() << " s: " << mean << " N; weight " << kMass * kG << " N");
  CHECK(mean == Approx(kMass * kG).epsilon(0.05));
  CHECK(std::abs(h.column("velocity_m_s").back()) < 0.02);  // at rest (1 m/s impact → < 2 cm/s)
}

TEST_CASE("CPT: the static reaction F_0 pushed at 0.25 and at 0.125 m/s agrees within its own scatter (1 cm)",
          "[ffp][program][cpt]") {
  // The sand is rate independent and the soil's inertia ρv²A is 0.6 N at 0.25 m/s.
  // The profile carries stick–slip fluctuations as large as its mean (σ ≈ 55 N on
  // ~70 N with the contact surface on the outline), so a fixed percentage says
  // little: the two means must agree within two standard errors of their
  // difference, each taken from the six 1 cm block means of 2–8 cm (blocks, not
  // rows, because neighbouring rows are correlated). Measured (0.25, 0.125,
  // 0.0625 m/s): 75.3, 70.5 and 68.5 N.
  ScratchDir scratch;
  auto run = [&](const std::string& scene, const std::string& out) {
    REQUIRE(run_program(
                {"run", scene_path(scene), "--out", (scratch.path() / out).string(), "--quiet", "--set",
                 "end_depth_m=0.08", "--set", "output.field_times_s=[]", "--set", "output.history_interval_s=0.001"},
                scratch.path())
                .exit_code == 0);
    return read_numeric_csv(scratch.path() / out / "history.csv");
  };
  // Mean over 2–8 cm and the standard error from the 1 cm block means.
  auto mean_and_error = [](const CsvData& h) {
    std::vector<double> blocks;
    for (double from = 0.02; from < 0.08 - 1e-9; from += 0.01) blocks.push_back(mean_reaction(h, from, from + 0.01));
    const double mean = mean_reaction(h, 0.02, 0.08);
    double spread = 0.0;
    for (double b : blocks) spread += (b - mean) * (b - mean);
    const double n = static_cast<double>(blocks.size());
    return std::pair{mean, std::sqrt(spread / (n - 1.0) / n)};
  };
  const auto [f_fast, e_fast] = mean_and_error(run("cpt_reference.json", "fast"));
  const auto [f_slow, e_slow] = mean_and_error(run("cpt_slow.json", "slow"));
  INFO("mean F_0 over 2–8 cm: " << f_fast << " ± " << e_fast << " N at 0.25 m/s, " << f_slow << " ± " << e_slow
                                << " N at 0.125 m/s");
  REQUIRE(f_slow > 10.0);  // a real resistance, not an empty run
  CHECK(std::abs(f_fast - f_slow) <= 2.0 * std::hypot(e_fast, e_slow));
  CHECK(std::abs(f_fast - f_slow) <= 0.25 * f_slow);  // and never a different resistance altogether
}

TEST_CASE("reference FFP on 2 cm: the tip half a cell off a node row moves the final penetration by under 3 %",
          "[ffp][program][staircase]") {
  // The staircase of a cone that does not conform to the grid is frozen when the tip
  // sits on a node row; half a cell off it the other way. Bound 3 % of the final
  // penetration: half of the 6 % that the half cell itself (1 cm) is of it. Measured here: 16.42 / 16.31 cm (−0.7 %).
  // It is not a bound on the staircase as a whole: the quarter phases give 17.43 and
  // 17.86 cm (+6.2 %, +8.8 %), and at 1 cm half a cell gives +3.8 % (the report's
  // convergence study tables the four phases at 2, 1 and 0.5 cm).
  ScratchDir scratch;
  auto final_penetration = [&](const std::string& offset) {
    const auto out = scratch.path() / ("offset_" + offset);
    REQUIRE(run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                         "mesh.min_cell_m=0.02", "--set", "mesh.tip_offset_cells=" + offset, "--set",
                         "output.field_times_s=[]"},
                        scratch.path())
                .exit_code == 0);
    return read_json(out / "summary.json")["final_penetration_m"].get<double>();
  };
  const double on_row = final_penetration("0"), off_row = final_penetration("0.5");
  INFO("final penetration: " << on_row << " m on a row, " << off_row << " m half a cell off");
  CHECK(std::abs(off_row - on_row) <= 0.03 * on_row);
}

TEST_CASE("reference FFP on 2 cm: dt_min_s is the CFL rule's smallest step, not the cut landing on end_time_s",
          "[ffp][program][time_step]") {
  // 6.3 ms ends 4 % of a step after the 42nd step (measured: the landing step was
  // 6.9e-6 s against a first step of 1.8e-4 s, which dt_min_s reported as a 26×
  // "collapse"). The CFL step itself falls only by the disconnected particles'
  // density floor (c_p ∝ 1/√ρ, ρ ≥ ρ0/2: a factor ≥ 1/√2 ≈ 0.71) and the slightly
  // larger stresses and speeds near the cone: measured 0.63 of the first step over
  // the whole 0.15 s run at 2 cm and at 1 cm. Half the first step is the bound.
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  REQUIRE(run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                       "mesh.min_cell_m=0.02", "--set", "end_time_s=0.0063", "--set", "output.field_times_s=[]"},
                      scratch.path())
              .exit_code == 0);
  const nlohmann::json summary = read_json(out / "summary.json");
  const double first = summary["dt_s"].get<double>(), smallest = summary["dt_min_s"].get<double>();
  INFO("first step " << first << " s, dt_min_s " << smallest << " s");
  CHECK(smallest <= first);
  CHECK(smallest > 0.5 * first);
}

TEST_CASE("reference FFP on 2 cm with MUSL: Courant 0.5 and 0.05 agree within 1.5 % in penetration at 60 ms",
          "[ffp][program][time_step]") {
  // The time step's own error. MUSL (strains from the remapped particle velocities)
  // converges smoothly: measured 0.1630 / 0.1638 / 0.1642 / 0.1643 m at Courant
  // 0.5 / 0.1 / 0.05 / 0.02 (0.7 % from 0.5 to 0.05). USL (strains from the updated
  // grid velocities) does not: 0.1556 / 0.1563 / 0.1606 / 0.1639 m, a 3.1 % step
  // between 0.5 and 0.05 that an elastic sand does not show (both transfers converge
  // there); the plastic return of USL's strain increments is the Courant-dependent
  // part. 1.5 % is twice MUSL's measured difference and half USL's.
  ScratchDir scratch;
  auto penetration = [&](const std::string& courant) {
    const auto out = scratch.path() / ("courant_" + courant);
    REQUIRE(run_program({"run", scene_path("ffp_reference.json"), "--out", out.string(), "--quiet", "--set",
                         "mesh.min_cell_m=0.02", "--set", "end_time_s=0.06", "--set", "solver.transfer=musl", "--set",
                         "solver.courant=" + courant, "--set", "output.field_times_s=[]"},
                        scratch.path())
                .exit_code == 0);
    return read_json(out / "summary.json")["final_penetration_m"].get<double>();
  };
  const double coarse = penetration("0.5"), fine = penetration("0.05");
  INFO("penetration at 60 ms: " << coarse << " m at Courant 0.5, " << fine << " m at 0.05");
  CHECK(std::abs(coarse - fine) <= 0.015 * fine);
}
