/// A saturated ffp run as a user reads it: u1/u2 in history.csv, u2 in record.csv's
/// pore_pressure_kPa, and that record read back by the `record` kind with its pore pressure.
#include <catch2/catch.hpp>

#include <fstream>

#include "cli_harness.hpp"
#include "drivers/output/csv_writer.hpp"

using ffp::test::run_ffp;
using ffp::test::Scratch;
using nlohmann::json;

TEST_CASE("saturated ffp on 2 cm: u2 goes to record.csv, and a record scene reads it back with its pore pressure",
          "[cli][record][saturated]") {
  Scratch scratch;
  const auto r = run_ffp({"run", FFP_SOURCE_DIR "/data/scenes/ffp_saturated.json", "--out", "ffp", "--quiet", "--set",
                          "mesh.min_cell_m=0.02", "--set", "end_time_s=0.02"},
                         scratch.path());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const ffp::CsvData history = ffp::read_numeric_csv(scratch.path() / "ffp" / "history.csv");
  for (const char* column : {"u1_kPa", "u1_excess_kPa", "u1_particles", "u2_kPa", "u2_excess_kPa", "u2_particles"})
    CHECK(history.has(column));
  const ffp::CsvData record = ffp::read_numeric_csv(scratch.path() / "ffp" / "record.csv");
  REQUIRE(record.has("pore_pressure_kPa"));
  // record.csv's rows are history's after the impact's (t = 0): u2 row for row.
  const auto& u2 = history.column("u2_kPa");
  const auto& u = record.column("pore_pressure_kPa");
  REQUIRE(u.size() + 1 == u2.size());
  for (std::size_t k = 0; k < u.size(); ++k) CHECK(u[k] == u2[k + 1]);
  std::ifstream summary_file(scratch.path() / "ffp" / "summary.json");
  const json summary = json::parse(summary_file);
  for (const char* key : {"u2_peak_kPa", "u2_min_kPa", "u2_dissipation_time_s", "two_phase_dt_limit_s"})
    CHECK(summary.contains(key));

  // The record kind reads the run's record.csv back as a measured water drop (the first row is its impact).
  const double first = record.column("time_s").front();
  scratch.write_json("record.json", {{"kind", "record"},
                                     {"name", "again"},
                                     {"record_csv", "ffp/record.csv"},
                                     {"medium", "water"},
                                     {"ffp", {{"mass_kg", 7.71}, {"volume_m3", 0.0032}}},
                                     {"impact_velocity_m_s", 5.6},
                                     {"impact_time_s", first}});
  const auto again = run_ffp({"run", "record.json", "--out", "again", "--quiet"}, scratch.path());
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  const ffp::CsvData read_back = ffp::read_numeric_csv(scratch.path() / "again" / "history.csv");
  REQUIRE(read_back.has("pore_pressure_kPa"));
  const auto& back = read_back.column("pore_pressure_kPa");
  REQUIRE(back.size() + 1 == u.size());  // its rows after its own impact row
  for (std::size_t k = 0; k < back.size(); ++k) CHECK(back[k] == u[k + 1]);
}
