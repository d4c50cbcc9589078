#include "drivers/output/csv_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "drivers/output/run_directory.hpp"
#include "drivers/scene/input_file.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CsvTable needs at least one column");
}

void CsvTable::add_row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) throw std::invalid_argument("CsvTable row has the wrong number of values");
  data_.insert(data_.end(), values.begin(), values.end());
}

std::vector<double> CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) throw std::invalid_argument("no column " + name);
  const std::size_t c = static_cast<std::size_t>(it - columns_.begin());
  std::vector<double> out;
  for (std::size_t r = 0; r < rows(); ++r) out.push_back(data_[r * columns_.size() + c]);
  return out;
}

std::string CsvTable::to_string() const {
  std::string out;
  for (std::size_t c = 0; c < columns_.size(); ++c) out += (c ? "," : "") + csv_field(columns_[c]);
  out += '\n';
  char buffer[32];
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      std::snprintf(buffer, sizeof buffer, "%.10g", data_[r * columns_.size() + c]);
      if (c) out += ',';
      out += buffer;
    }
    out += '\n';
  }
  return out;
}

void CsvTable::write(const std::filesystem::path& file) const { write_file_atomically(file, to_string()); }

bool CsvData::has(const std::string& name) const {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

const std::vector<double>& CsvData::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::invalid_argument("no column " + name);
  return values[static_cast<std::size_t>(it - columns.begin())];
}

namespace {
std::vector<std::string> split_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}
}  // namespace

CsvData read_numeric_csv(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string text = read_input_file(file, kCsvFileLimit);
  CsvData data;
  std::string line;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {  // line by line, without a second copy of the text
    const std::size_t end = std::min(text.find('\n', start), text.size());
    line.assign(text, start, end - start);
    start = end + 1;
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (line[line.find_first_not_of(" \t")] == '#') continue;  // comment lines
    const auto cells = split_line(line);
    if (data.columns.empty()) {
      data.columns = cells;
      data.values.assign(cells.size(), {});
      continue;
    }
    if (cells.size() != data.columns.size())
      throw SceneError(name + ":" + std::to_string(line_number) + ": has " + std::to_string(cells.size()) +
                       " cells, the header has " + std::to_string(data.columns.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string& cell = cells[c];
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (cell.empty() || end != cell.c_str() + cell.size())
        throw SceneError(name + ":" + std::to_string(line_number) + ": column '" + data.columns[c] + "': '" + cell +
                         "' is not a number");
      if (!std::isfinite(v))
        throw SceneError(name + ":" + std::to_string(line_number) + ": column '" + data.columns[c] +
                         "': must be a finite number, got '" + cell + "'");
      data.values[c].push_back(v);
    }
    data.lines.push_back(line_number);
  }
  if (data.columns.empty()) throw SceneError(name + ": the CSV file is empty (expected a header row and data)");
  return data;
}

}  // namespace ffp
