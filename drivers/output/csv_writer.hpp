#pragma once
/// Plain CSV tables: a header row, then rows of numbers (%.10g). Every text
/// field is written by RFC 4180, so any reader of CSV splits it as written.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace ffp {

/// One field as RFC 4180 (section 2, rules 5–7) writes it: enclosed in double
/// quotes when it holds a comma, a double quote, CR or LF, its double quotes
/// doubled; otherwise unchanged (numbers never need quotes).
std::string csv_field(std::string_view text);

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

/// A numeric CSV read back (first row is the header; blank lines and '#'
/// comments skipped; a UTF-8 byte-order mark accepted). Errors name file, row
/// and column: missing columns, non-numeric cells, NaN/inf; and the file itself
/// when it is not a regular file or is larger than kCsvFileLimit (input_file.hpp).
struct CsvData {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  std::vector<std::size_t> lines;           // the file's line of each row, for messages
  bool has(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
};
CsvData read_numeric_csv(const std::filesystem::path& file);

}  // namespace ffp
