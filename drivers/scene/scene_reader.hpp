#pragma once
/// Typed, range-checked reading of scene JSON objects.
///
/// Every value read is also written, with its default filled in, to an echo
/// object, so a run's summary.json shows the scene exactly as it was run.
/// finish() rejects keys nobody asked for, suggesting the nearest valid key:
/// a scene carries only what its kind and model use.
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/scene/scene_error.hpp"

namespace ffp {

using json = nlohmann::json;

/// Closed or open bounds on a number; `unit` only decorates messages.
struct Range {
  double min = -std::numeric_limits<double>::max();
  double max = std::numeric_limits<double>::max();
  bool min_open = false;
  bool max_open = false;
  std::string_view unit = "";

  static Range positive(double max, std::string_view unit = "") { return {0.0, max, true, false, unit}; }
  static Range non_negative(double max, std::string_view unit = "") { return {0.0, max, false, false, unit}; }
  static Range closed(double min, double max, std::string_view unit = "") { return {min, max, false, false, unit}; }
  static Range half_open(double min, double max, std::string_view unit = "") { return {min, max, false, true, unit}; }
  static Range open(double min, double max, std::string_view unit = "") { return {min, max, true, true, unit}; }

  bool contains(double v) const;
  std::string describe() const;  ///< e.g. "> 0 and ≤ 1e+09 kPa"
};

class SceneReader {
 public:
  /// `path` is the JSON path of `object` ("" for the top level); `echo` receives
  /// the resolved values (must outlive the reader).
  SceneReader(const json& object, std::string path, json& echo);

  const std::string& path() const { return path_; }
  bool has(std::string_view key) const;

  double number(std::string_view key, const Range& range);
  double number(std::string_view key, const Range& range, double fallback);
  std::optional<double> optional_number(std::string_view key, const Range& range);
  int integer(std::string_view key, long min, long max);
  int integer(std::string_view key, long min, long max, long fallback);
  bool boolean(std::string_view key, bool fallback);
  std::string text(std::string_view key);
  std::string text(std::string_view key, std::string_view fallback);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed,
                     std::string_view fallback);
  /// A list of numbers, each in range, with a length in [min_size, max_size].
  std::vector<double> numbers(std::string_view key, const Range& range, std::size_t min_size,
                              std::size_t max_size);
  std::optional<std::vector<double>> optional_numbers(std::string_view key, const Range& range,
                                                      std::size_t min_size, std::size_t max_size);

  /// A nested object; absent objects read as {} when `required` is false.
  SceneReader object(std::string_view key, bool required = false);
  /// Elements of an array of objects.
  std::vector<SceneReader> objects(std::string_view key, std::size_t min_size, std::size_t max_size);
  /// Raw JSON value (copied to the echo unchanged), for free-form parts.
  std::optional<json> raw(std::string_view key);

  /// Mark a key as known without reading it (e.g. a comment field).
  void allow(std::string_view key);
  /// Reject every key that was not read or allowed. `context` names why keys
  /// are limited, e.g. "a mohr_coulomb material".
  void finish(std::string_view context = "");

  /// Throws SceneError "path.key: message".
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

 private:
  const json* find(std::string_view key);
  std::string child_path(std::string_view key) const;

  const json* object_;
  std::string path_;
  json* echo_;
  std::vector<std::string> known_;
};

/// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(std::string_view a, std::string_view b);
/// The closest candidate to `word` if it is plausibly a typo, else "".
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

/// Parse scene text; syntax errors become SceneError with line and column.
json parse_scene_text(const std::string& text, const std::string& source_name);
/// Read and parse a scene file (missing/empty/unreadable files are SceneErrors).
json load_scene_file(const std::string& file_path);
/// Apply one `--set key.path=value` override (value parsed as JSON, else a string;
/// `null` removes the key, so that its default applies).
void apply_override(json& scene, const std::string& assignment);

}  // namespace ffp
