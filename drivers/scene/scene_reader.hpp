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
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/scene/input_file.hpp"
#include "drivers/scene/scene_error.hpp"

namespace ffp {

using json = nlohmann::json;

/// Closed or open bounds on a number. `unit` and `note` decorate messages and the scene
/// reference: "m" and "≤ radius_m" describe as "… m (≤ radius_m)".
struct Range {
  double min = -std::numeric_limits<double>::max();
  double max = std::numeric_limits<double>::max();
  bool min_open = false;
  bool max_open = false;
  std::string_view unit = "";
  std::string_view note = "";

  static Range positive(double max, std::string_view unit = "", std::string_view note = "") {
    return {0.0, max, true, false, unit, note};
  }
  static Range non_negative(double max, std::string_view unit = "", std::string_view note = "") {
    return {0.0, max, false, false, unit, note};
  }
  static Range closed(double min, double max, std::string_view unit = "", std::string_view note = "") {
    return {min, max, false, false, unit, note};
  }
  static Range half_open(double min, double max, std::string_view unit = "", std::string_view note = "") {
    return {min, max, false, true, unit, note};
  }
  static Range open(double min, double max, std::string_view unit = "", std::string_view note = "") {
    return {min, max, true, true, unit, note};
  }

  bool contains(double v) const;
  std::string describe() const;  ///< e.g. "> 0 and ≤ 1e+09 kPa"
  std::string interval() const;  ///< e.g. "(0, 1e9]", "≥ 0", with the note: "(0, 10] (≤ radius_m)"
};

/// What the scene reference (`ffp keys`, docs/reference/scenes.md) says of a key, written
/// beside the read that accepts it: its meaning in one line. The read itself gives the unit,
/// the range or names allowed and the default; what depends on other keys is said here in
/// words, and so is the branch of the scene the key belongs to.
struct Doc {
  explicit Doc(std::string meaning) : meaning(std::move(meaning)) {}
  /// A default computed from other keys, or what an absent key means: "3 × mesh.min_cell_m".
  Doc by_default(std::string words) const {
    Doc d = *this;
    d.fallback = std::move(words);
    return d;
  }
  /// Bounds or values that depend on other keys: "[0, phi_peak_deg]".
  Doc within(std::string words) const {
    Doc d = *this;
    d.range = std::move(words);
    return d;
  }
  /// The other keys it needs, or the branch it belongs to: "material.model = ssmc".
  Doc only_with(std::string keys) const {
    Doc d = *this;
    d.condition = std::move(keys);
    return d;
  }

  std::string meaning, fallback, range, condition;
};

/// A key as the scene reference lists it: the read's Doc with the read's own facts.
struct KeyEntry {
  std::string meaning;
  std::string unit;       ///< "" where dimensionless or not a number
  std::string fallback;   ///< "required", "none", the default value or words
  std::string allowed;    ///< the range, the names or the shape of the value
  std::string condition;  ///< the keys it needs; "" where always accepted
  bool operator==(const KeyEntry&) const = default;
};

/// Every key the readers of one scene know (read or allowed), by full path
/// ("bodies[0].material.E_kPa"), in the order first read: what a kind accepts,
/// for the scene reference (drivers/app/key_reference.hpp).
struct KeyLog {
  std::vector<std::string> order;
  std::map<std::string, KeyEntry> entries;
  std::vector<std::string> conflicts;  ///< keys read twice with different entries

  void note(const std::string& path, KeyEntry entry);
  void drop(const std::string& path);
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
  /// the keys this reader and its nested readers know, each with its Doc.
  SceneReader(const json& object, std::string path, json& echo, KeyLog* log = nullptr);

  const std::string& path() const { return path_; }
  bool has(std::string_view key) const;

  double number(std::string_view key, const Range& range, const Doc& doc);
  double number(std::string_view key, const Range& range, double fallback, const Doc& doc);
  std::optional<double> optional_number(std::string_view key, const Range& range, const Doc& doc);
  int integer(std::string_view key, long min, long max, const Doc& doc);
  int integer(std::string_view key, long min, long max, long fallback, const Doc& doc);
  bool boolean(std::string_view key, bool fallback, const Doc& doc);
  /// Read (and echoed) only when given: a key added after scenes were shipped keeps their
  /// echo, hence their outputs, as they were. The Doc says what its absence means.
  std::optional<bool> optional_boolean(std::string_view key, const Doc& doc);
  std::string text(std::string_view key, const Doc& doc);
  std::string text(std::string_view key, std::string_view fallback, const Doc& doc);
  /// A file named by the text at `key`: relative to the scene's folder unless absolute, lexically normalised.
  std::filesystem::path file(std::string_view key, const std::filesystem::path& scene_dir, const Doc& doc);
  /// The same, refused unless it is a regular file within `limit` (input_file.hpp: a named pipe or
  /// /dev/zero would hang its reader).
  std::filesystem::path existing_file(std::string_view key, const std::filesystem::path& scene_dir,
                                      const InputFileLimit& limit, const Doc& doc);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed, const Doc& doc);
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed, std::string_view fallback,
                     const Doc& doc);
  /// One of an enum's names (its EnumNames table); the echo holds the name.
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names, const Doc& doc) {
    const std::vector<Enum> values = all_of(names);
    return values[choose(key, names_of(names, values), nullptr, doc)];
  }
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names, Enum fallback, const Doc& doc) {
    return choice_among(key, names, all_of(names), fallback, doc);
  }
  /// Only the values `allowed`, listed in that order (an axis cannot be a free boundary).
  template <class Enum, std::size_t N>
  Enum choice(std::string_view key, const EnumNames<Enum, N>& names, std::initializer_list<Enum> allowed, Enum fallback,
              const Doc& doc) {
    return choice_among(key, names, std::vector<Enum>(allowed), fallback, doc);
  }
  /// A list of numbers, each in range, with a length in [min_size, max_size].
  std::vector<double> numbers(std::string_view key, const Range& range, std::size_t min_size, std::size_t max_size,
                              const Doc& doc);
  std::optional<std::vector<double>> optional_numbers(std::string_view key, const Range& range, std::size_t min_size,
                                                      std::size_t max_size, const Doc& doc);

  /// A nested object; absent, it reads as {}.
  SceneReader object(std::string_view key, const Doc& doc);
  /// A nested object that must be there.
  SceneReader required_object(std::string_view key, const Doc& doc);
  /// Elements of an array of objects.
  std::vector<SceneReader> objects(std::string_view key, std::size_t min_size, std::size_t max_size, const Doc& doc);
  /// Raw JSON value (copied to the echo unchanged), for free-form parts.
  std::optional<json> raw(std::string_view key, const Doc& doc);

  /// Mark a key as known without reading it (e.g. a comment field, or an object read
  /// only when present): the Doc says in words what it holds and what its absence means.
  void allow(std::string_view key, const Doc& doc);
  /// Refuse a key that a shared reader (read_material) takes but this scene does not: fail with
  /// `reason` if it is there, and leave it out of the log either way.
  void refuse(std::string_view key, const std::string& reason);
  /// Reject every key that was not read or allowed. `context` names why keys
  /// are limited, e.g. "a mohr_coulomb material".
  void finish(std::string_view context = "");

  /// Throws SceneError "path.key: message".
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

 private:
  /// The key's value, or nullptr; either way the key is known to finish().
  const json* find(std::string_view key);
  void know(std::string_view key);
  std::string child_path(std::string_view key) const;
  /// Logs the key's entry: the Doc's words where it has them, else what the read knows.
  void document(std::string_view key, const Doc& doc, std::string allowed, std::string_view unit, std::string fallback);
  std::optional<double> read_number(std::string_view key, const Range& range);
  int read_integer(std::string_view key, long min, long max);
  std::string read_text(std::string_view key);
  std::optional<std::vector<double>> read_numbers(std::string_view key, const Range& range, std::size_t min_size,
                                                  std::size_t max_size);
  SceneReader nested(std::string_view key, bool required);
  /// The index in `options` of the key's value (or of `fallback` when the key is absent).
  std::size_t choose(std::string_view key, const std::vector<std::string>& options, const std::string_view* fallback,
                     const Doc& doc);

  template <class Enum, std::size_t N>
  Enum choice_among(std::string_view key, const EnumNames<Enum, N>& names, const std::vector<Enum>& values,
                    Enum fallback, const Doc& doc) {
    const std::string_view fallback_name = name_in(names, fallback);
    return values[choose(key, names_of(names, values), &fallback_name, doc)];
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

/// A number as a reader writes it: "%g" with a short exponent (1e9, 2e-4 as 0.0002).
std::string compact_number(double v);

/// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(std::string_view a, std::string_view b);
/// The closest candidate to `word` if it is plausibly a typo, else "".
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

/// Parse scene text; syntax errors become SceneError with line and column.
json parse_scene_text(const std::string& text, const std::string& source_name);
/// Read and parse a scene file (missing, empty, unreadable, not a regular file or larger than
/// kSceneFileLimit: SceneError).
json load_scene_file(const std::string& file_path);
/// Apply one `--set key.path=value` override (value parsed as JSON, else a string;
/// `null` removes the key, so that its default applies).
void apply_override(json& scene, const std::string& assignment);

}  // namespace ffp
