/// Fuzzes the CSV readers that take a file: read_numeric_csv (path tables and
/// every numeric CSV) and read_lab_curve (the calibration's lab curves). The
/// input is the file's content, written to a scratch file of this process.
///
/// Findings: an exception other than SceneError or std::invalid_argument; any
/// crash, ASan or UBSan report, leak, timeout or out-of-memory; a table read
/// back whose columns differ in length.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "calibration/lab_curve.hpp"
#include "drivers/output/csv_writer.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ffp::fuzz::ScratchFile file("table.csv");
  file.write(data, size);
  ffp::fuzz::expect_only_rejections([&] {
    const ffp::CsvData table = ffp::read_numeric_csv(file.path);
    if (table.values.size() != table.columns.size()) std::abort();
    for (const auto& column : table.values)
      if (column.size() != table.values.front().size()) std::abort();
  });
  ffp::fuzz::expect_only_rejections([&] { ffp::read_lab_curve(file.path); });
  return 0;
}
