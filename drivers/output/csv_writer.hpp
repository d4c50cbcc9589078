#pragma once
/// Plain CSV tables: a header row, then rows of numbers (%.10g).
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace ffp {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);
  void add_row(const std::vector<double>& values);
  void add_row(std::initializer_list<double> values) { add_row(std::vector<double>(values)); }
  std::size_t rows() const { return data_.size() / columns_.size(); }
  const std::vector<std::string>& columns() const { return columns_; }
  std::vector<double> column(const std::string& name) const;
  std::string to_string() const;
  /// Written via a temporary file and renamed.
  void write(const std::filesystem::path& file) const;

 private:
  std::vector<std::string> columns_;
  std::vector<double> data_;
};

/// A numeric CSV read back (first row is the header). Errors name file, row
/// and column: missing columns, non-numeric cells, NaN/inf.
struct CsvData {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  bool has(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
};
CsvData read_numeric_csv(const std::filesystem::path& file);

}  // namespace ffp
