/// Extremes: stiff, soft, nearly incompressible, nearly frictionless-locked
/// sand, impacts up to 200 m/s, rigid and steel penetrometers. Each case must
/// end in a finite, physical run (history finite, impulse equal to the momentum
/// change, never faster than free fall) or in exit 1/2 with a one-line cause
/// that is not the bare "non-finite … (unstable step?)" of a blown-up step.
/// On 2 cm cells, over the first milliseconds, so that each case takes ~1 s.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ffp_test_support.hpp"

using namespace ffp;
using namespace ffp::test;

namespace {

struct ExtremeCase {
  const char* name;
  const char* scene;
  std::vector<std::string> overrides;
  double end_time_s;
};

}  // namespace

TEST_CASE("extreme sand and impacts end in a finite physical run or a clear refusal", "[ffp][extremes]") {
  const std::vector<ExtremeCase> cases = {
      {"E' = 1 kPa", "ffp_reference.json", {"material.E_kPa=1"}, 0.01},
      {"E' = 1e9 kPa", "ffp_reference.json", {"material.E_kPa=1e9"}, 0.001},
      {"nu' = 0.4999", "ffp_reference.json", {"material.nu=0.4999"}, 0.005},
      {"phi' = 89 deg", "ffp_reference.json", {"material.phi_peak_deg=89"}, 0.01},
      {"20 m/s, 1 m of sand", "ffp_reference.json", {"ffp.impact_velocity_m_s=20", "soil.depth_m=1"}, 0.01},
      {"200 m/s, 2 m of sand", "ffp_reference.json", {"ffp.impact_velocity_m_s=200", "soil.depth_m=2"}, 0.006},
      {"200 m/s through the 0.4 m chamber", "ffp_reference.json", {"ffp.impact_velocity_m_s=200"}, 0.01},
      {"steel penetrometer", "ffp_steel.json", {}, 0.002},
      {"steel penetrometer at 20 m/s", "ffp_steel.json", {"ffp.impact_velocity_m_s=20", "soil.depth_m=1"}, 0.002},
  };
  for (const ExtremeCase& c : cases) {
    DYNAMIC_SECTION(c.name) {
      ScratchDir scratch;
      const auto out = scratch.path() / "run";
      std::vector<std::string> args = {"run",
                                       scene_path(c.scene),
                                       "--out",
                                       out.string(),
                                       "--quiet",
                                       "--set",
                                       "mesh.min_cell_m=0.02",
                                       "--set",
                                       "output.field_times_s=[]",
                                       "--set",
                                       "end_time_s=" + std::to_string(c.end_time_s)};
      for (const auto& o : c.overrides) {
        args.push_back("--set");
        args.push_back(o);
      }
      const ProgramResult r = run_program(args, scratch.path());
      INFO(c.name << ": exit " << r.exit_code << ", stderr: " << r.err);
      if (r.exit_code != 0) {
        CHECK((r.exit_code == 1 || r.exit_code == 2));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.err.find("non-finite") == std::string::npos);
        continue;
      }
      const nlohmann::json summary = read_json(out / "summary.json");
      CHECK(summary["momentum_balance_error"].get<double>() < 1e-9);
      const CsvData h = read_numeric_csv(out / "history.csv");
      const double v0 = summary["scene"]["ffp"]["impact_velocity_m_s"].get<double>(), g = 9.81;
      const auto& t = h.column("time_s");
      for (const auto& column : h.values)
        for (double x : column) REQUIRE(std::isfinite(x));
      const auto& dt = h.column("dt_s");
      const double dt_max = *std::max_element(dt.begin(), dt.end());
      for (std::size_t k = 0; k < t.size(); ++k) {
        // Gravity is the only force that speeds the penetrometer up. Its position
        // moves with the step's new velocity (symplectic Euler), which in free
        // fall gives v0·t + ½g·t·(t + Δt): that is the bound.
        CHECK(std::abs(h.column("velocity_m_s")[k]) <= v0 + g * t[k] + 1e-9);
        CHECK(h.column("penetration_m")[k] <= v0 * t[k] + 0.5 * g * t[k] * (t[k] + dt_max) + 1e-9);
      }
    }
  }
}
