/// CSV written by RFC 4180 (section 2): a field is quoted only when it must be,
/// so the numeric tables every run writes are byte for byte what they were.
#include <catch2/catch.hpp>

#include "drivers/output/csv_writer.hpp"

using ffp::csv_field;
using ffp::CsvTable;

TEST_CASE("a CSV field is quoted when it holds a comma, a double quote, CR or LF, its quotes doubled",
          "[drivers][csv]") {
  CHECK(csv_field("runs,2024") == "\"runs,2024\"");
  CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(csv_field("carriage\rreturn") == "\"carriage\rreturn\"");
  CHECK(csv_field("O'Brien drops") == "O'Brien drops");  // nothing RFC 4180 reserves
  CHECK(csv_field("") == "");
  CHECK(csv_field("time_s") == "time_s");
}

TEST_CASE("a numeric table keeps its plain header and %.10g numbers, and only a header that needs it is quoted",
          "[drivers][csv]") {
  CsvTable plain({"time_s", "penetration_m"});
  plain.add_row({0.001, -2.5e-7});
  CHECK(plain.to_string() == "time_s,penetration_m\n0.001,-2.5e-07\n");
  CsvTable odd({"a,b", "c"});
  odd.add_row({1.0, 2.0});
  CHECK(odd.to_string() == "\"a,b\",c\n1,2\n");
}
