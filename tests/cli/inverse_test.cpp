/// The `inverse` kind as a user runs it: a synthetic record made by the solver
/// itself is fitted back to the parameters that made it; bad fits are refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "cli_harness.hpp"
#include "drivers/output/csv_writer.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

const std::vector<std::string> kCoarse = {"mesh.min_cell_m=0.02", "end_time_s=0.08"};

json inverse_scene(const std::string& record_csv) {
  return {{"kind", "inverse"},
          {"name", "synthetic"},
          {"forward_scene", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json"},
          {"forward_overrides", kCoarse},
          {"record",
           {{"record_csv", record_csv},
            {"ffp", {{"mass_kg", 7.71}}},
            {"impact_velocity_m_s", 5.6},
            {"impact_time_s", 0.0}}},
          {"parameters",
           {{{"key", "material.phi_peak_deg"}, {"initial", 35.0}, {"lower", 30.0}, {"upper", 50.0}},
            {{"key", "material.E_kPa"}, {"initial", 4000.0}, {"lower", 1000.0}, {"upper", 8000.0}}}}};
}

}  // namespace

TEST_CASE("a synthetic record of the solver is fitted back to its phi and E within two standard errors",
          "[cli][inverse]") {
  Scratch scratch;
  // The record: the reference FFP at 2 cm cells with φ'_p = 39° and E' = 2500 kPa (the scene's
  // own), its deceleration with Gaussian noise of 1 % of the peak added to every row.
  std::vector<std::string> args = {"run", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json", "--out", "truth",
                                   "--quiet"};
  for (const auto& o : kCoarse) args.insert(args.end(), {"--set", o});
  args.insert(args.end(), {"--set", "output.field_times_s=[]"});
  const auto truth = run_ffp(args, scratch.path());
  INFO(truth.err);
  REQUIRE(truth.exit_code == 0);
  const ffp::CsvData history = ffp::read_numeric_csv(scratch.path() / "truth" / "history.csv");
  const auto& t = history.column("time_s");
  const auto& d = history.column("deceleration_g");
  const double peak = *std::max_element(d.begin(), d.end());
  std::mt19937 engine(1);
  std::normal_distribution<double> noise(0.0, 0.01 * peak);
  std::ostringstream csv;
  csv.precision(10);
  csv << "time_s,deceleration_g\n";
  for (std::size_t k = 0; k < t.size(); ++k) csv << t[k] << ',' << d[k] + noise(engine) << '\n';
  scratch.write("record.csv", csv.str());
  scratch.write_json("inverse.json", inverse_scene("record.csv"));

  const auto fit = run_ffp({"run", "inverse.json", "--out", "fit", "--quiet", "--jobs", "2"}, scratch.path());
  INFO(fit.err);
  REQUIRE(fit.exit_code == 0);
  const json s = read_json(scratch.path() / "fit" / "summary.json");
  INFO(s.dump(1));
  CHECK(s["converged"].get<bool>());
  for (const auto& [key, truth_value] : {std::pair{"material.phi_peak_deg", 39.0}, {"material.E_kPa", 2500.0}}) {
    const json& p = s["parameters"][key];
    REQUIRE(p["standard_error"].is_number());
    CHECK(std::abs(p["value"].get<double>() - truth_value) < 2.0 * p["standard_error"].get<double>());
  }
  // The fit leaves the record at the noise: its rms misfit is about the 1 % noise it was given.
  CHECK(s["profile_rms_misfit_g"].get<double>() < 1.5 * 0.01 * peak);
  CHECK(s["cost_final"].get<double>() < 0.05 * s["cost_initial"].get<double>());
  // Every model run keeps its folder; the fitted one is named.
  CHECK(fs::exists(scratch.path() / "fit" / s["fitted_run"].get<std::string>() / "record.csv"));
  std::size_t folders = 0;
  for (const auto& entry : fs::directory_iterator(scratch.path() / "fit" / "runs")) folders += entry.is_directory();
  CHECK(static_cast<long>(folders) == s["model_runs"].get<long>());
  CHECK(fs::exists(scratch.path() / "fit" / "plots" / "fit.png"));
  CHECK(fs::exists(scratch.path() / "fit" / "profile.csv"));
}

TEST_CASE("an inverse scene that cannot be fitted exits 2 naming the key", "[cli][inverse]") {
  struct Case {
    std::string what, must_mention;
    std::function<void(json&)> edit;
  };
  const std::vector<Case> cases = {
      {"a key that is not a soil parameter", "parameters[0].key",
       [](json& j) { j["parameters"][0]["key"] = "mesh.min_cell_m"; }},
      {"an upper bound the forward scene refuses", "parameters[0].upper",
       [](json& j) { j["parameters"][0]["upper"] = 95.0; }},
      {"an initial value outside the bounds", "parameters[1].initial",
       [](json& j) { j["parameters"][1]["initial"] = 9000.0; }},
      {"a forward scene of another kind", "forward_scene",
       [](json& j) { j["forward_scene"] = FFP_SOURCE_DIR "/data/scenes/cpt_reference.json"; }},
      {"nothing to fit", "nothing to fit", [](json& j) { j.erase("record"); }},
      // Each model run refuses a name that cannot name a folder: so must the check.
      {"a forward override the model runs would refuse", "forward_overrides: the forward scene refuses it: name:",
       [](json& j) { j["forward_overrides"].push_back("name=two words"); }},
  };
  for (const Case& c : cases) {
    DYNAMIC_SECTION(c.what) {
      Scratch scratch;
      scratch.write("record.csv", "time_s,deceleration_g\n0,-1\n0.001,5\n0.002,5\n0.003,5\n");
      json scene = inverse_scene("record.csv");
      c.edit(scene);
      scratch.write_json("inverse.json", scene);
      const auto r = run_ffp({"run", "inverse.json", "--out", "fit", "--quiet"}, scratch.path());
      INFO(r.err);
      CHECK(r.exit_code == 2);
      CHECK_THAT(r.err, Catch::Contains(c.must_mention));
      CHECK_FALSE(fs::exists(scratch.path() / "fit"));
      // `ffp check` refuses what the run refuses.
      const auto check = run_ffp({"check", "inverse.json"}, scratch.path());
      CHECK(check.exit_code == 2);
      CHECK_THAT(check.err, Catch::Contains(c.must_mention));
    }
  }
}

TEST_CASE("a fitted parameter that cannot move the target is reported as not identifiable, not converged",
          "[cli][inverse]") {
  // The calibrated SSMC with φ'_r = φ'_p and ψ_p = ψ_r = 0 does not soften: η multiplies
  // (φ'_p − φ'_r) = 0 and (ψ_p − ψ_r) = 0, so the runs at any η are the same to the last bit
  // and the peak deceleration does not move with it. Ceres sees a zero gradient and would
  // stop at once with CONVERGENCE.
  Scratch scratch;
  const json scene = {{"kind", "inverse"},
                      {"name", "idle_eta"},
                      {"forward_scene", FFP_SOURCE_DIR "/data/scenes/ffp_calibrated.json"},
                      {"forward_overrides",
                       {"mesh.min_cell_m=0.02", "end_time_s=0.02", "output.history_interval_s=0.001",
                        "material.phi_residual_deg=60", "material.psi_peak_deg=0"}},
                      {"peak_deceleration", {{"target_g", 15.0}}},
                      {"parameters", {{{"key", "material.eta"}, {"initial", 10.0}, {"lower", 1.0}, {"upper", 50.0}}}}};
  scratch.write_json("inverse.json", scene);
  const auto r = run_ffp({"run", "inverse.json", "--out", "fit", "--quiet"}, scratch.path());
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("not identifiable") && Catch::Contains("peak_deceleration") &&
                        Catch::Contains("material.eta 0"));
  // One line says it (the run pool's lines before it list the model runs).
  const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
  CHECK(last.rfind("error: inverse: not identifiable", 0) == 0);
  CHECK_FALSE(fs::exists(scratch.path() / "fit"));
}
