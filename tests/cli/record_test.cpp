/// The `record` kind as a user runs it: a measured drop in, the interpretation
/// out; bad records refused with the row and column; every ffp run writes the
/// same columns in record.csv.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_harness.hpp"
#include "drivers/output/csv_writer.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double g = 9.81;

json record_scene(const std::string& csv) {
  return {{"kind", "record"}, {"name", "drop"}, {"record_csv", csv}, {"ffp", {{"mass_kg", 7.71}}}};
}

/// An accelerometer's record (sky positive, +g at rest): 0.05 s hanging, 0.2 s of
/// free fall, then a 6 g reading (5 g net) in the soil until the end, which comes as the
/// body stops (400 rows after a 0.2 s fall; a record going on would throw it back up).
std::string sensor_record(int rows_at_rest = 500, int rows_falling = 2000, int rows_in_soil = 400) {
  std::ostringstream csv;
  csv << "time_s,acceleration_m_s2,pore_pressure_kPa\n";
  int k = 0;
  auto row = [&](double a) {
    const double t = 1e-4 * k++;
    csv << t << ',' << a << ',' << 0.5 * (k % 7) << '\n';
  };
  for (int i = 0; i < rows_at_rest; ++i) row(g);
  for (int i = 0; i < rows_falling; ++i) row(0.0);
  for (int i = 0; i < rows_in_soil; ++i) row(6.0 * g);
  return csv.str();
}

/// The shipped synthetic record of the reference drop (impact at t = 0, 5.6 m/s), each deceleration
/// passed through `change` (its row index and value).
template <class Change>
std::string reference_record(Change change) {
  std::ifstream in(FFP_SOURCE_DIR "/data/records/ffp_reference_synthetic.csv");
  std::ostringstream csv;
  csv.precision(17);
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    if (line.empty() || line[0] == '#' || line.rfind("time_s", 0) == 0) {
      csv << line << '\n';
      continue;
    }
    csv << line.substr(0, comma) << ',' << change(row++, std::stod(line.substr(comma + 1))) << '\n';
  }
  return csv.str();
}

json reference_scene(const std::string& csv) {
  json scene = record_scene(csv);
  scene["impact_velocity_m_s"] = 5.6;
  scene["impact_time_s"] = 0.0;
  return scene;
}

std::string header_of(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

TEST_CASE("a sensor record from release gives the free-fall impact velocity and the profiles", "[cli][record]") {
  Scratch scratch;
  scratch.write("drop.csv", sensor_record());
  const auto scene = scratch.write_json("record.json", record_scene("drop.csv"));
  const auto r = run_ffp({"run", scene.string(), "--out", "out", "--quiet"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(scratch.path() / "out" / "summary.json");
  const json s = json::parse(in);
  // The reading drops from g to 0 between two samples, so the fall integrates over 2000 − ½ intervals.
  CHECK(s["impact_velocity_m_s"].get<double>() == Approx(g * 1e-4 * 1999.5).epsilon(1e-9));
  CHECK(s["impact_velocity_source"] == "integrated from rest at the first sample");
  CHECK(s["peak_deceleration_g"].get<double>() == Approx(5.0));
  const double v = s["impact_velocity_m_s"].get<double>();
  // The trapezoid spans the jump into the pulse with its mean, 2 g net, over the first interval;
  // from there 5 g stops it after v1²/(2·5g) (the stop falls between samples: 1e-6 relative).
  const double dt = 1e-4, v1 = v - 2 * g * dt, z1 = 0.5 * (v + v1) * dt;
  CHECK(s["max_penetration_m"].get<double>() == Approx(z1 + v1 * v1 / (2 * 5 * g)).epsilon(1e-5));
  CHECK(header_of(scratch.path() / "out" / "history.csv") ==
        "time_s,penetration_m,velocity_m_s,deceleration_g,q_dyn_projected_kPa,q_dyn_mantle_kPa,q_sbc_log_kPa,"
        "q_sbc_brilli_kPa,q_sbc_asinh_kPa,pore_pressure_kPa");
  CHECK(fs::exists(scratch.path() / "out" / "plots" / "depth_profiles.png"));
}

TEST_CASE("bad records exit 2 naming the row and the column and write nothing", "[cli][record]") {
  struct Case {
    std::string what, csv, must_mention;
    json extra = json::object();
  };
  const std::string good = sensor_record(10, 100, 20);
  std::string backwards = good, nan_cell = good;
  backwards.replace(backwards.find("\n0.005,"), 7, "\n0.0001,");
  nan_cell.replace(nan_cell.find("\n0.011,") + 7, 1, "nan");
  const std::vector<Case> cases = {
      {"time going back", backwards, "data row 51"},
      {"a NaN cell", nan_cell, "acceleration_m_s2"},
      {"a saturated channel", good, "saturated", {{"sensor_range_m_s2", 50.0}}},
      {"no impact", sensor_record(10, 100, 0), "no impact found"},
      {"no deceleration column", "time_s,x\n0,1\n1,2\n2,3\n", "acceleration_m_s2"},
  };
  for (const Case& c : cases) {
    DYNAMIC_SECTION(c.what) {
      Scratch scratch;
      scratch.write("drop.csv", c.csv);
      json scene = record_scene("drop.csv");
      scene.update(c.extra);
      const auto file = scratch.write_json("record.json", scene);
      const auto r = run_ffp({"run", file.string(), "--out", "out", "--quiet"}, scratch.path());
      INFO(r.err);
      CHECK(r.exit_code == 2);
      CHECK_THAT(r.err, Catch::Contains(c.must_mention));
      CHECK_FALSE(fs::exists(scratch.path() / "out"));
    }
  }
}

TEST_CASE("an ffp run writes record.csv in the record kind's columns", "[cli][record]") {
  Scratch scratch;
  const auto r = run_ffp({"run", FFP_SOURCE_DIR "/data/scenes/ffp_reference.json", "--out", "ffp", "--quiet", "--set",
                          "mesh.min_cell_m=0.02", "--set", "end_time_s=0.03"},
                         scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(header_of(scratch.path() / "ffp" / "record.csv") ==
        "time_s,penetration_m,velocity_m_s,deceleration_g,q_dyn_projected_kPa,q_dyn_mantle_kPa,q_sbc_log_kPa,"
        "q_sbc_brilli_kPa,q_sbc_asinh_kPa");
  // Read back as a measured record, the run's own history gives the same peak and a penetration
  // within the trapezoid's error of the solver's (rows hold interval means, 2e-4 s apart).
  scratch.write_json("record.json", {{"kind", "record"},
                                     {"name", "again"},
                                     {"record_csv", "ffp/history.csv"},
                                     {"ffp", {{"mass_kg", 7.71}}},
                                     {"impact_velocity_m_s", 5.6},
                                     {"impact_time_s", 0.0}});
  const auto again = run_ffp({"run", "record.json", "--out", "again", "--quiet"}, scratch.path());
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  std::ifstream a(scratch.path() / "ffp" / "summary.json"), b(scratch.path() / "again" / "summary.json");
  const json run = json::parse(a), record = json::parse(b);
  CHECK(record["peak_deceleration_g"].get<double>() == Approx(run["peak_deceleration_g"].get<double>()).epsilon(1e-8));
  // The trapezoid over interval means lags the exact velocity by ½ g Δt_row (d + 1), which integrates
  // to ½ Δt_row (v0 − v + g t) of penetration at the most.
  const auto time = ffp::read_numeric_csv(scratch.path() / "ffp" / "history.csv").column("time_s");
  double row_spacing = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k) row_spacing = std::max(row_spacing, time[k] - time[k - 1]);
  const double v_end = run["final_velocity_m_s"].get<double>();
  const double bound = 0.5 * row_spacing * (5.6 - v_end + g * 0.03);
  CHECK(std::abs(record["final_penetration_m"].get<double>() - run["final_penetration_m"].get<double>()) < bound);
}

TEST_CASE("records no impact can produce exit 2 with the reason and write nothing", "[cli][record]") {
  struct Case {
    std::string what, csv;
    std::vector<std::string> must_mention;
    json extra = json::object();
  };
  const std::vector<Case> cases = {
      {"the deceleration's sign flipped (the body would speed up from 5.6 to 11.2 m/s)",
       reference_record([](int, double d) { return -d; }),
       {"deceleration_g looks like it has the wrong sign", "never slows", "11.22 m/s", "negate the column"}},
      {"two samples of 1e308 g",
       reference_record([](int row, double d) { return row == 100 || row == 101 ? 1e308 : d; }),
       {"column 'deceleration_g'", "data row 101", "1e+308 g", "beyond the ±7.66e+03 g"}},
      {"impact_time_s after the record",
       reference_record([](int, double d) { return d; }),
       {"impact_time_s = 0.5 s is outside the record", "runs from 0 s to 0.15 s"},
       {{"impact_time_s", 0.5}}},
      {"impact_time_s before the record",
       reference_record([](int, double d) { return d; }),
       {"impact_time_s = -0.01 s is outside the record", "runs from 0 s to 0.15 s"},
       {{"impact_time_s", -0.01}}},
  };
  for (const Case& c : cases) {
    DYNAMIC_SECTION(c.what) {
      Scratch scratch;
      scratch.write("drop.csv", c.csv);
      json scene = reference_scene("drop.csv");
      scene.update(c.extra);
      const auto file = scratch.write_json("record.json", scene);
      const auto r = run_ffp({"run", file.string(), "--out", "out", "--quiet"}, scratch.path());
      INFO(r.err);
      CHECK(r.exit_code == 2);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK_THAT(r.err, Catch::StartsWith("error: drop.csv: ") || Catch::Contains("/drop.csv: "));
      for (const std::string& m : c.must_mention) CHECK_THAT(r.err, Catch::Contains(m));
      CHECK_FALSE(fs::exists(scratch.path() / "out"));
      // `ffp check` refuses it the same way.
      CHECK(run_ffp({"check", file.string()}, scratch.path()).exit_code == 2);
    }
  }
}

TEST_CASE("an implausible but possible record runs and says why in summary.json and on stderr", "[cli][record]") {
  Scratch scratch;
  // The sensor record with its impact time given 0.07 s before the real impact and the speed the
  // body had then (g × 0.13 s of fall): it falls on to 1.961 m/s, 54 % above that, before the soil.
  scratch.write("drop.csv", sensor_record());
  json scene = record_scene("drop.csv");
  scene["impact_time_s"] = 0.18;
  scene["impact_velocity_m_s"] = g * 0.13;
  const auto file = scratch.write_json("record.json", scene);
  const auto r = run_ffp({"run", file.string(), "--out", "out", "--quiet"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("warning: ") && Catch::Contains("drop.csv") &&
                        Catch::Contains("54% above the impact velocity") && Catch::Contains("too early"));
  std::ifstream in(scratch.path() / "out" / "summary.json");
  const json s = json::parse(in);
  REQUIRE(s.contains("warnings"));
  REQUIRE(s["warnings"].size() == 1);
  CHECK_THAT(s["warnings"][0].get<std::string>(), Catch::Contains("rises to 1.961 m/s"));
  // `ffp check` shows the doubt before a run.
  const auto check = run_ffp({"check", file.string()}, scratch.path());
  CHECK(check.exit_code == 0);
  CHECK_THAT(check.out, Catch::Contains("warning: the velocity rises"));
}

TEST_CASE("a record without doubts has no warnings key in its summary", "[cli][record]") {
  Scratch scratch;
  const auto r =
      run_ffp({"run", FFP_SOURCE_DIR "/data/scenes/record_reference.json", "--out", "out", "--quiet"}, scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  std::ifstream in(scratch.path() / "out" / "summary.json");
  CHECK_FALSE(json::parse(in).contains("warnings"));
}
