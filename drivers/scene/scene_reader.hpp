#pragma once
/// Typed, range-checked reading of scene JSON objects.
///
/// Every value read is also written, with its default filled in, to an echo
/// object, so a run's summary.json shows the scene exactly as it was run.
/// finish() rejects keys nobody asked for, suggesting the nearest valid key:
/// a scene carries only what its kind and model use.
#include <array>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
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

/// The full path of every key the readers of one scene know (read or
/// allowed), e.g. "bodies[0].material.E_kPa": what a kind accepts, for the
/// test that ties README's key tables to the readers.
struct KeyLog {
  std::set<std::string> paths;
};

/// An enum's scene names, declared once beside the enum, in the order
/// messages list them: {value, "name"} pairs. The scene reader's choice and
/// the enum's to_string are both read from it.
template <class Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

class SceneReader {
 public:
  /// `path` is the JSON path of `object` ("" for the top level); `echo` receives
  /// the resolved values (must outlive the reader). `log`, when given, collects
  /// the keys this reader and its nested readers know.
  SceneReader(const json& object, std::string path, json& echo, KeyLog* log = nullptr);

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
  /// A file named by the text at `key`: relative to the scene's folder unless absolute, lexically normalised.
  std::filesystem::path file(std::string_view key, const std::filesystem::path& scene_dir);
  /// The same, refused unless it is a regular file (a FIFO or /dev/zero would hang its reader).
  std::filesystem::path existing_file(std::string_view key, const std::filesystem::path& scene_dir);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed, std::string_view fallback);
  /// One of an enum's names (its EnumNames table); the echo holds the name.
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names) {
    const std::vector<Enum> values = all_of(names);
    return values[choose(key, names_of(names, values), nullptr)];
  }
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names, Enum fallback) {
    return choice_among(key, names, all_of(names), fallback);
  }
  /// Only the values `allowed`, listed in that order (an axis cannot be a free boundary).
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names, std::initializer_list<Enum> allowed,
              Enum fallback) {
    return choice_among(key, names, std::vector<Enum>(allowed), fallback);
  }
  /// A list of numbers, each in range, with a length in [min_size, max_size].
  std::vector<double> numbers(std::string_view key, const Range& range, std::size_t min_size, std::size_t max_size);
  std::optional<std::vector<double>> optional_numbers(std::string_view key, const Range& range, std::size_t min_size,
                                                      std::size_t max_size);

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
  /// The index in `options` of the key's value (or of `fallback` when the key is absent).
  std::size_t choose(std::string_view key, const std::vector<std::string>& options, const std::string_view* fallback);

  template <class Enum, std::size_t N>
  Enum choice_among(std::string_view key, const EnumNames<Enum, N>& names, const std::vector<Enum>& values,
                    Enum fallback) {
    const std::string_view fallback_name = name_in(names, fallback);
    return values[choose(key, names_of(names, values), &fallback_name)];
  }
  template <class Enum, std::size_t N>
  static std::vector<Enum> all_of(const EnumNames<Enum, N>& names) {
    std::vector<Enum> values;
    for (const auto& entry : names) values.push_back(entry.first);
    return values;
  }
  template <class Enum, std::size_t N>
  static std::string_view name_in(const EnumNames<Enum, N>& names, Enum value) {
    for (const auto& entry : names)
      if (entry.first == value) return entry.second;
    return "?";
  }
  template <class Enum, std::size_t N>
  static std::vector<std::string> names_of(const EnumNames<Enum, N>& names, const std::vector<Enum>& values) {
    std::vector<std::string> out;
    for (Enum v : values) out.emplace_back(name_in(names, v));
    return out;
  }

  const json* object_;
  std::string path_;
  json* echo_;
  std::vector<std::string> known_;
  KeyLog* log_ = nullptr;
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
