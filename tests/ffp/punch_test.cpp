/// The punch benchmarks (punch_smooth/rough.json): a rigid flat circular punch
/// on a weightless Tresca soil, exact limit mean pressure 5.69 c' (smooth,
/// Shield 1955) and 6.05 c' (rough, Eason & Shield 1960). The report's
/// verification study runs them at 1, 0.5 and 0.25 cm; here the two coarse
/// levels of the smooth punch and the rough one at 1 cm (2 s and 9 s), and the
/// smooth one at 1 cm with the whole strain averaged per cell (strain_smoothing full).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "ffp_test_support.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {

constexpr double kShieldSmooth = 5.69;
constexpr double kEasonShieldRough = 6.05;

double bearing_factor(const std::string& scene, double min_cell_m, const std::string& smoothing = "volumetric") {
  ScratchDir scratch;
  const auto out = scratch.path() / "run";
  const ProgramResult r = run_program({"run", scene_path(scene), "--out", out.string(), "--quiet", "--set",
                                       "mesh.min_cell_m=" + std::to_string(min_cell_m), "--set",
                                       "output.field_times_s=[]", "--set", "solver.strain_smoothing=" + smoothing},
                                      scratch.path());
  INFO(scene << " at " << min_cell_m << " m: " << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json summary = read_json(out / "summary.json");
  REQUIRE(summary.contains("bearing_factor"));
  return summary["bearing_factor"].get<double>();
}

}  // namespace

TEST_CASE("smooth punch on Tresca: the bearing factor falls towards Shield's 5.69 as h halves (1 and 0.5 cm)",
          "[ffp][punch]") {
  const double coarse = bearing_factor("punch_smooth.json", 0.01);
  const double fine = bearing_factor("punch_smooth.json", 0.005);
  INFO("bearing factor: 1 cm " << coarse << ", 0.5 cm " << fine << " (exact 5.69)");
  // The soil cannot carry less than the exact limit unless it leaks past the
  // punch (a contact failure); the discretisation over-predicts (the report).
  CHECK(fine > kShieldSmooth);
  // Refining must approach the exact value, not move away from it or stall.
  CHECK(std::abs(fine - kShieldSmooth) < 0.9 * std::abs(coarse - kShieldSmooth));
}

TEST_CASE("rough punch on Tresca at 1 cm: no slip bears more than a smooth face, by about 6.05/5.69", "[ffp][punch]") {
  const double smooth = bearing_factor("punch_smooth.json", 0.01);
  const double rough = bearing_factor("punch_rough.json", 0.01);
  INFO("bearing factor at 1 cm: smooth " << smooth << ", rough " << rough);
  CHECK(rough > smooth);
  // The exact ratio is 1.063; the two punches share every numerical setting but the
  // contact, so most of the mesh bias cancels in the ratio: within 3 % of it.
  CHECK(rough / smooth == Approx(kEasonShieldRough / kShieldSmooth).epsilon(0.03));
}

TEST_CASE("smooth punch at 1 cm: averaging the whole strain per cell removes most of the plastic over-stiffness",
          "[ffp][punch]") {
  // The excess of the default (volumetric) smoothing is mostly the cells' stiffness in
  // isochoric plastic flow: with one strain per cell (full) the 1 cm plateau falls from
  // 6.63 to 5.95 (measured), near what one particle per cell gives (5.94). It is not the
  // default: its elastic stiffness is half the volumetric one (hourglass-like freedom,
  // README), and it does not approach 5.69 as h shrinks (5.95, 5.95, 6.06 at 1, 0.5, 0.25 cm).
  const double volumetric = bearing_factor("punch_smooth.json", 0.01);
  const double full = bearing_factor("punch_smooth.json", 0.01, "full");
  INFO("bearing factor at 1 cm: volumetric " << volumetric << ", full " << full << " (exact 5.69)");
  // Still above the exact value, as at every level measured ...
  CHECK(full > kShieldSmooth);
  // ... but at most half the volumetric smoothing's excess (measured: 0.26 of 0.94).
  CHECK(full - kShieldSmooth < 0.5 * (volumetric - kShieldSmooth));
}
