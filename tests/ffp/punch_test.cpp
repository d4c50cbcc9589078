/// The punch benchmarks (punch_smooth/rough.json): a rigid flat circular punch
/// on a weightless Tresca soil, exact limit mean pressure 5.69 c' (smooth,
/// Shield 1955) and 6.05 c' (rough, Eason & Shield 1960), read as the plateau
/// at a settlement small enough to be the small-strain answer. The report's
/// verification study runs them at R/h = 1.5, 3.5, 7.5 and 15.5 (the scenes'
/// own); here R/h = 2.5 and 5.5 (about 1 s each).
#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "ffp_test_support.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {

constexpr double kShieldSmooth = 5.69;
constexpr double kEasonShieldRough = 6.05;
constexpr double kPunchRadius_m = 0.05;

/// min_cell_m = R/(n + ½): the scenes put R midway between two node columns.
std::string cells_across(int n) {
  std::ostringstream s;
  s << "mesh.min_cell_m=" << std::setprecision(17) << kPunchRadius_m / (n + 0.5);
  return s.str();
}

double bearing_factor(const std::string& scene, int n, const std::vector<std::string>& extra = {}) {
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  std::vector<std::string> args = {"run",     scene_path(scene), "--out",        out.string(),
                                   "--quiet", "--set",           cells_across(n)};
  for (const std::string& e : extra) args.insert(args.end(), {"--set", e});
  const ProgramResult r = run_program(args, scratch.path());
  INFO(scene << " at R/h = " << n << ".5: " << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json summary = read_json(out / "summary.json");
  REQUIRE(summary.contains("bearing_factor"));
  return summary["bearing_factor"].get<double>();
}

}  // namespace

TEST_CASE("smooth punch on Tresca: the bearing factor approaches Shield's 5.69 as h shrinks (R/h 2.5 and 5.5)",
          "[ffp][punch]") {
  const double coarse = bearing_factor("punch_smooth.json", 2);
  const double fine = bearing_factor("punch_smooth.json", 5);
  INFO("bearing factor: R/h 2.5 " << coarse << ", 5.5 " << fine << " (exact 5.69)");
  // With the edge midway between node columns every level measured lies below the exact
  // value (5.05, 5.34, 5.52, 5.60 at R/h 2.5 to 20.5): a jump above it would mean a new error.
  CHECK(fine < kShieldSmooth);
  // First-order convergence (the punch edge): the error should fall about as h, by 2.5/5.5 =
  // 0.45 here (measured 0.55); 0.75 fails a stalled or diverging series.
  CHECK(std::abs(fine - kShieldSmooth) < 0.75 * std::abs(coarse - kShieldSmooth));
}

TEST_CASE("rough punch on Tresca at R/h 5.5: no slip bears more than a smooth face, by about 6.05/5.69",
          "[ffp][punch]") {
  const double smooth = bearing_factor("punch_smooth.json", 5);
  const double rough = bearing_factor("punch_rough.json", 5);
  INFO("bearing factor at R/h 5.5: smooth " << smooth << ", rough " << rough);
  CHECK(rough > smooth);
  // The exact ratio is 1.063; the two punches share every numerical setting but the
  // contact, so most of the mesh bias cancels in the ratio (measured 1.067): within 2 %.
  CHECK(rough / smooth == Approx(kEasonShieldRough / kShieldSmooth).epsilon(0.02));
}

TEST_CASE("smooth punch at R/h 5.5: the plateau is the small-strain limit and does not depend on the time step",
          "[ffp][punch]") {
  const double scene = bearing_factor("punch_smooth.json", 5);
  // A third of the rigidity (G/c' 1000), the window and the push scaled with the elastic
  // settlement and the P-wave speed: the plateau moves by the settlement's own effect only
  // (measured 0.07 %; G/c' 300 read at s/R 0.04–0.06 is 1.8 % higher at R/h 10.5). Bound 1 %.
  const double softer = bearing_factor("punch_smooth.json", 5,
                                       {"material.E_kPa=26000", "end_depth_m=0.0009",
                                        "plateau_settlement_ratio=[0.012,0.018]", "ffp.push_velocity_m_s=0.0087"});
  // MUSL at half the step (measured 0.02 % at R/h 10.5, where USL's plateau moves by 2.5 %: 5.18 → 5.31).
  const double half_step = bearing_factor("punch_smooth.json", 5, {"solver.courant=0.25"});
  INFO("bearing factor at R/h 5.5: scene " << scene << ", G/c' 1000 " << softer << ", Courant 0.25 " << half_step);
  CHECK(softer == Approx(scene).epsilon(0.01));
  CHECK(half_step == Approx(scene).epsilon(0.005));
}
