#include "drivers/scene/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace ffp {

namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string type_name(const json& v) {
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  if (v.is_null()) return "null";
  return "an unknown type";
}

std::string join_quoted(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ", ";
    out += w;
  }
  return out;
}

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (min_open ? !(v > min) : !(v >= min)) return false;
  if (max_open ? !(v < max) : !(v <= max)) return false;
  return true;
}

std::string Range::describe() const {
  const double lowest = -std::numeric_limits<double>::max();
  const double highest = std::numeric_limits<double>::max();
  std::string out;
  if (min > lowest) out += (min_open ? "> " : "≥ ") + format_number(min);
  if (max < highest) {
    if (!out.empty()) out += " and ";
    out += (max_open ? "< " : "≤ ") + format_number(max);
  }
  if (out.empty()) out = "a finite number";
  if (!unit.empty()) out += " " + std::string(unit);
  if (!note.empty()) out += " (" + std::string(note) + ")";
  return out;
}

std::string Range::interval() const {
  const bool low = min > -std::numeric_limits<double>::max();
  const bool high = max < std::numeric_limits<double>::max();
  std::string out;
  if (low && high) {
    out = std::string(min_open ? "(" : "[") + compact_number(min) + ", " + compact_number(max) + (max_open ? ")" : "]");
  } else if (low) {
    out = (min_open ? "> " : "≥ ") + compact_number(min);
  } else if (high) {
    out = (max_open ? "< " : "≤ ") + compact_number(max);
  } else {
    out = "any number";
  }
  if (!note.empty()) out += " (" + std::string(note) + ")";
  return out;
}

std::string compact_number(double v) {
  // Powers of ten and their multiples from 1e4 on as a reader writes them (1e4, 3e4, 1e9);
  // other numbers with %g's six digits (1488.28, 0.04375, 1e-10).
  const double magnitude = std::abs(v);
  if (magnitude >= 1e4 && magnitude < 1e300) {
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    const double mantissa = v / std::pow(10.0, exponent);
    if (std::abs(mantissa - std::round(mantissa)) < 1e-12)
      return std::to_string(static_cast<long>(std::round(mantissa))) + "e" + std::to_string(exponent);
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  std::string out = buffer;
  const auto e = out.find('e');  // 1e-05 → 1e-5
  if (e == std::string::npos) return out;
  std::string mantissa = out.substr(0, e), exponent = out.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

void KeyLog::note(const std::string& path, KeyEntry entry) {
  const auto [at, added] = entries.try_emplace(path, entry);
  if (added) {
    order.push_back(path);
  } else if (!(at->second == entry)) {
    conflicts.push_back(path);
  }
}

void KeyLog::drop(const std::string& path) {
  entries.erase(path);
  order.erase(std::remove(order.begin(), order.end(), path), order.end());
}

SceneReader::SceneReader(const json& object, std::string path, json& echo, KeyLog* log)
    : object_(&object), path_(std::move(path)), echo_(&echo), log_(log) {
  if (!object_->is_object()) {
    throw SceneError((path_.empty() ? std::string("scene") : path_) + ": must be a JSON object, got " +
                     type_name(*object_));
  }
  if (!echo_->is_object()) *echo_ = json::object();
}

std::string SceneReader::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void SceneReader::fail(std::string_view key, const std::string& message) const {
  throw SceneError(child_path(key) + ": " + message);
}

bool SceneReader::has(std::string_view key) const { return object_->contains(std::string(key)); }

void SceneReader::know(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

const json* SceneReader::find(std::string_view key) {
  know(key);
  auto it = object_->find(std::string(key));
  return it == object_->end() ? nullptr : &*it;
}

void SceneReader::document(std::string_view key, const Doc& doc, std::string allowed, std::string_view unit,
                           std::string fallback) {
  if (log_ == nullptr) return;
  log_->note(child_path(key), KeyEntry{doc.meaning, std::string(unit), doc.fallback.empty() ? fallback : doc.fallback,
                                       doc.range.empty() ? allowed : doc.range, doc.condition});
}

void SceneReader::allow(std::string_view key, const Doc& doc) {
  know(key);
  document(key, doc, "", "", "none");
}

std::optional<double> SceneReader::read_number(std::string_view key, const Range& range) {
  const json* v = find(key);
  if (v == nullptr) return std::nullopt;
  if (!v->is_number()) fail(key, "must be a number (" + range.describe() + "), got " + type_name(*v));
  const double x = v->get<double>();
  if (!std::isfinite(x)) fail(key, "must be a finite number (" + range.describe() + ")");
  if (!range.contains(x)) fail(key, "= " + format_number(x) + " is out of range: must be " + range.describe());
  (*echo_)[std::string(key)] = x;
  return x;
}

std::optional<double> SceneReader::optional_number(std::string_view key, const Range& range, const Doc& doc) {
  document(key, doc, range.interval(), range.unit, "none");
  return read_number(key, range);
}

double SceneReader::number(std::string_view key, const Range& range, const Doc& doc) {
  document(key, doc, range.interval(), range.unit, "required");
  auto v = read_number(key, range);
  if (!v) fail(key, "is required (" + range.describe() + ")");
  return *v;
}

double SceneReader::number(std::string_view key, const Range& range, double fallback, const Doc& doc) {
  document(key, doc, range.interval(), range.unit, compact_number(fallback));
  auto v = read_number(key, range);
  if (v) return *v;
  (*echo_)[std::string(key)] = fallback;
  return fallback;
}

int SceneReader::read_integer(std::string_view key, long min, long max) {
  const json* v = find(key);
  const std::string allowed = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (v == nullptr) fail(key, "is required (" + allowed + ")");
  if (!v->is_number()) fail(key, "must be " + allowed + ", got " + type_name(*v));
  const double x = v->get<double>();
  if (!std::isfinite(x) || x != std::floor(x)) fail(key, "must be " + allowed + ", got " + format_number(x));
  if (x < static_cast<double>(min) || x > static_cast<double>(max))
    fail(key, "= " + format_number(x) + " is out of range: must be " + allowed);
  (*echo_)[std::string(key)] = static_cast<long>(x);
  return static_cast<int>(x);
}

namespace {

std::string integer_interval(long min, long max) {
  return "integer in [" + compact_number(static_cast<double>(min)) + ", " + compact_number(static_cast<double>(max)) +
         "]";
}

}  // namespace

int SceneReader::integer(std::string_view key, long min, long max, const Doc& doc) {
  document(key, doc, integer_interval(min, max), "", "required");
  return read_integer(key, min, max);
}

int SceneReader::integer(std::string_view key, long min, long max, long fallback, const Doc& doc) {
  document(key, doc, integer_interval(min, max), "", compact_number(static_cast<double>(fallback)));
  if (!has(key)) {
    know(key);
    (*echo_)[std::string(key)] = fallback;
    return static_cast<int>(fallback);
  }
  return read_integer(key, min, max);
}

bool SceneReader::boolean(std::string_view key, bool fallback, const Doc& doc) {
  document(key, doc, "`true`, `false`", "", fallback ? "`true`" : "`false`");
  const json* v = find(key);
  if (v == nullptr) {
    (*echo_)[std::string(key)] = fallback;
    return fallback;
  }
  if (!v->is_boolean()) fail(key, "must be true or false, got " + type_name(*v));
  (*echo_)[std::string(key)] = v->get<bool>();
  return v->get<bool>();
}

std::optional<bool> SceneReader::optional_boolean(std::string_view key, const Doc& doc) {
  document(key, doc, "`true`, `false`", "", "none");
  const json* v = find(key);
  if (v == nullptr) return std::nullopt;
  if (!v->is_boolean()) fail(key, "must be true or false, got " + type_name(*v));
  (*echo_)[std::string(key)] = v->get<bool>();
  return v->get<bool>();
}

std::string SceneReader::read_text(std::string_view key) {
  const json* v = find(key);
  if (v == nullptr) fail(key, "is required (a string)");
  if (!v->is_string()) fail(key, "must be a string, got " + type_name(*v));
  (*echo_)[std::string(key)] = *v;
  return v->get<std::string>();
}

std::string SceneReader::text(std::string_view key, const Doc& doc) {
  document(key, doc, "text", "", "required");
  return read_text(key);
}

std::string SceneReader::text(std::string_view key, std::string_view fallback, const Doc& doc) {
  document(key, doc, "text", "", "`" + std::string(fallback) + "`");
  if (!has(key)) {
    know(key);
    (*echo_)[std::string(key)] = std::string(fallback);
    return std::string(fallback);
  }
  return read_text(key);
}

namespace {

std::string names_in_backticks(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "`" : ", `") + n + "`";
  return out;
}

}  // namespace

std::size_t SceneReader::choose(std::string_view key, const std::vector<std::string>& options,
                                const std::string_view* fallback, const Doc& doc) {
  document(key, doc, names_in_backticks(options), "",
           fallback == nullptr ? "required" : "`" + std::string(*fallback) + "`");
  if (fallback != nullptr && !has(key)) {
    know(key);
    (*echo_)[std::string(key)] = std::string(*fallback);
    return static_cast<std::size_t>(std::find(options.begin(), options.end(), *fallback) - options.begin());
  }
  const json* v = find(key);
  if (v == nullptr) fail(key, "is required (one of: " + join_quoted(options) + ")");
  if (!v->is_string()) fail(key, "must be one of: " + join_quoted(options) + "; got " + type_name(*v));
  const std::string value = v->get<std::string>();
  const auto match = std::find(options.begin(), options.end(), value);
  if (match == options.end()) {
    const std::string guess = nearest(value, options);
    fail(key, "'" + value + "' is not allowed: must be one of: " + join_quoted(options) +
                  (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  (*echo_)[std::string(key)] = value;
  return static_cast<std::size_t>(match - options.begin());
}

std::string SceneReader::choice(std::string_view key, std::initializer_list<std::string_view> allowed, const Doc& doc) {
  const std::vector<std::string> options(allowed.begin(), allowed.end());
  return options[choose(key, options, nullptr, doc)];
}

std::string SceneReader::choice(std::string_view key, std::initializer_list<std::string_view> allowed,
                                std::string_view fallback, const Doc& doc) {
  const std::vector<std::string> options(allowed.begin(), allowed.end());
  // The fallback need not be one of `allowed` (it never was checked): it is returned as given.
  if (!has(key)) {
    document(key, doc, names_in_backticks(options), "", "`" + std::string(fallback) + "`");
    know(key);
    (*echo_)[std::string(key)] = std::string(fallback);
    return std::string(fallback);
  }
  return options[choose(key, options, &fallback, doc)];
}

std::filesystem::path SceneReader::file(std::string_view key, const std::filesystem::path& scene_dir, const Doc& doc) {
  document(key, doc, "a file (relative to the scene's folder)", "", "required");
  const std::filesystem::path named = read_text(key);
  return (named.is_absolute() ? named : scene_dir / named).lexically_normal();
}

std::filesystem::path SceneReader::existing_file(std::string_view key, const std::filesystem::path& scene_dir,
                                                 const InputFileLimit& limit, const Doc& doc) {
  std::filesystem::path resolved = file(key, scene_dir, doc);
  const std::string problem = input_file_problem(resolved, limit);
  if (!problem.empty())
    fail(key, "'" + resolved.string() + "' " + problem + " (paths are relative to the scene's folder)");
  return resolved;
}

namespace {

std::string list_shape(std::size_t min_size, std::size_t max_size, const std::string& what) {
  return std::to_string(min_size) + (min_size == max_size ? "" : " to " + std::to_string(max_size)) + " " + what;
}

}  // namespace

std::optional<std::vector<double>> SceneReader::read_numbers(std::string_view key, const Range& range,
                                                             std::size_t min_size, std::size_t max_size) {
  const json* v = find(key);
  if (v == nullptr) return std::nullopt;
  const std::string shape = "a list of " + std::to_string(min_size) +
                            (min_size == max_size ? "" : " to " + std::to_string(max_size)) + " numbers, each " +
                            range.describe();
  if (!v->is_array()) fail(key, "must be " + shape + ", got " + type_name(*v));
  if (v->size() < min_size || v->size() > max_size)
    fail(key, "has " + std::to_string(v->size()) + " entries: must be " + shape);
  std::vector<double> out;
  out.reserve(v->size());
  for (std::size_t i = 0; i < v->size(); ++i) {
    const json& e = (*v)[i];
    const std::string element = std::string(key) + "[" + std::to_string(i) + "]";
    if (!e.is_number()) fail(element, "must be a number (" + range.describe() + "), got " + type_name(e));
    const double x = e.get<double>();
    if (!range.contains(x)) fail(element, "= " + format_number(x) + " is out of range: must be " + range.describe());
    out.push_back(x);
  }
  (*echo_)[std::string(key)] = out;
  return out;
}

std::optional<std::vector<double>> SceneReader::optional_numbers(std::string_view key, const Range& range,
                                                                 std::size_t min_size, std::size_t max_size,
                                                                 const Doc& doc) {
  document(key, doc, list_shape(min_size, max_size, "numbers, each " + range.interval()), range.unit, "none");
  return read_numbers(key, range, min_size, max_size);
}

std::vector<double> SceneReader::numbers(std::string_view key, const Range& range, std::size_t min_size,
                                         std::size_t max_size, const Doc& doc) {
  document(key, doc, list_shape(min_size, max_size, "numbers, each " + range.interval()), range.unit, "required");
  auto v = read_numbers(key, range, min_size, max_size);
  if (!v) fail(key, "is required (a list of numbers, each " + range.describe() + ")");
  return *v;
}

SceneReader SceneReader::nested(std::string_view key, bool required) {
  static const json empty = json::object();
  const json* v = find(key);
  if (v == nullptr && required) fail(key, "is required (an object)");
  if (v != nullptr && !v->is_object()) fail(key, "must be an object, got " + type_name(*v));
  json& child_echo = (*echo_)[std::string(key)];
  if (!child_echo.is_object()) child_echo = json::object();
  return SceneReader(v != nullptr ? *v : empty, child_path(key), child_echo, log_);
}

SceneReader SceneReader::object(std::string_view key, const Doc& doc) {
  document(key, doc, "object", "", "{}");
  return nested(key, false);
}

SceneReader SceneReader::required_object(std::string_view key, const Doc& doc) {
  document(key, doc, "object", "", "required");
  return nested(key, true);
}

std::vector<SceneReader> SceneReader::objects(std::string_view key, std::size_t min_size, std::size_t max_size,
                                              const Doc& doc) {
  document(key, doc, list_shape(min_size, max_size, "objects"), "", min_size > 0 ? "required" : "[]");
  const json* v = find(key);
  std::vector<SceneReader> out;
  const std::string shape = "a list of " + std::to_string(min_size) + " to " + std::to_string(max_size) + " objects";
  if (v == nullptr) {
    if (min_size > 0) fail(key, "is required (" + shape + ")");
    (*echo_)[std::string(key)] = json::array();
    return out;
  }
  if (!v->is_array()) fail(key, "must be " + shape + ", got " + type_name(*v));
  if (v->size() < min_size || v->size() > max_size)
    fail(key, "has " + std::to_string(v->size()) + " entries: must be " + shape);
  json& arr = (*echo_)[std::string(key)];
  arr = json::array();
  for (std::size_t i = 0; i < v->size(); ++i) arr.push_back(json::object());
  for (std::size_t i = 0; i < v->size(); ++i)
    out.emplace_back((*v)[i], child_path(key) + "[" + std::to_string(i) + "]", arr[i], log_);
  return out;
}

std::optional<json> SceneReader::raw(std::string_view key, const Doc& doc) {
  document(key, doc, "JSON", "", "none");
  const json* v = find(key);
  if (v == nullptr) return std::nullopt;
  (*echo_)[std::string(key)] = *v;
  return *v;
}

void SceneReader::refuse(std::string_view key, const std::string& reason) {
  if (has(key)) fail(key, reason);
  if (log_ != nullptr) log_->drop(child_path(key));
}

void SceneReader::finish(std::string_view context) {
  for (const auto& [key, value] : object_->items()) {
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    const std::string guess = nearest(key, known_);
    std::string message = "unknown key";
    if (!context.empty()) message += " for " + std::string(context);
    if (!guess.empty()) {
      message += " (did you mean '" + guess + "'?)";
    } else {
      std::vector<std::string> sorted = known_;
      std::sort(sorted.begin(), sorted.end());
      message += "; allowed keys: " + join_quoted(sorted);
    }
    fail(key, message);
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  // A typo changes a few characters; a word sharing a long prefix is also a good guess.
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  if (best_distance <= limit) return best;
  for (const auto& c : candidates) {
    const std::size_t n = std::min(word.size(), c.size());
    if (n >= 4 && std::string_view(c).substr(0, 4) == word.substr(0, 4)) return c;
  }
  return "";
}

json parse_scene_text(const std::string& text, const std::string& source_name) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw SceneError(source_name + ": file is empty (expected a JSON scene object)");
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // Translate the byte offset into line and column for the message.
    const std::size_t offset = e.byte == 0 ? 0 : std::min<std::size_t>(e.byte - 1, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto colon = what.rfind(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw SceneError(source_name + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": invalid JSON: " + what);
  } catch (const json::out_of_range& e) {
    // A literal beyond double range (1e400): name it, where it is and its key.
    const std::string what = e.what();
    const auto open = what.find('\'');
    const auto close = what.rfind('\'');
    const std::string literal =
        open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
    if (at == std::string::npos) throw SceneError(source_name + ": a number is out of range: " + what);
    std::size_t line =
        1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    const std::size_t line_start = text.rfind('\n', at);
    const std::size_t column = at - (line_start == std::string::npos ? 0 : line_start + 1) + 1;
    std::string key = "a value";
    const std::size_t colon = text.rfind(':', at);
    if (colon != std::string::npos) {
      const std::size_t key_end = text.rfind('"', colon);
      const std::size_t key_start = key_end == std::string::npos ? std::string::npos : text.rfind('"', key_end - 1);
      if (key_start != std::string::npos) key = text.substr(key_start + 1, key_end - key_start - 1);
    }
    throw SceneError(source_name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + key + ": " +
                     literal + " is beyond the range of a number (must be a finite number)");
  }
}

json load_scene_file(const std::string& file_path) {
  json scene = parse_scene_text(read_input_file(file_path, kSceneFileLimit), file_path);
  if (!scene.is_object()) throw SceneError(file_path + ": the scene must be a JSON object ({...})");
  return scene;
}

void apply_override(json& scene, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError("--set " + assignment + ": expected key.path=value");
  const std::string key_path = assignment.substr(0, eq);
  const std::string value_text = assignment.substr(eq + 1);
  json value;
  try {
    value = json::parse(value_text);
  } catch (const json::parse_error&) {
    value = value_text;                  // bare words are strings: --set material.model=ssmc
  } catch (const json::out_of_range&) {  // found by fuzzing: 1e400 overflows a double
    throw SceneError("--set " + key_path + ": '" + value_text + "' is beyond the range of a number (±1.8e308)");
  }
  json* node = &scene;
  std::string walked;
  std::size_t start = 0;
  while (true) {
    const auto dot = key_path.find('.', start);
    const std::string part = key_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw SceneError("--set " + key_path + ": empty component in the key path");
    walked += (walked.empty() ? "" : ".") + part;
    if (node->is_array()) {
      std::size_t index = 0;
      try {
        index = std::stoul(part);
      } catch (...) {
        throw SceneError("--set " + key_path + ": " + walked + " indexes a list and must be a number");
      }
      if (index >= node->size())
        throw SceneError("--set " + key_path + ": index " + part + " is past the end of a list of " +
                         std::to_string(node->size()));
      node = &(*node)[index];
    } else if (node->is_object()) {
      if (dot == std::string::npos && value.is_null()) {  // --set key=null: the key is dropped, its default applies
        node->erase(part);
        return;
      }
      if (dot != std::string::npos && !node->contains(part)) (*node)[part] = json::object();
      node = &(*node)[part];
    } else {
      throw SceneError("--set " + key_path + ": " + walked + " is inside a value that is not an object");
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  *node = value;
}

}  // namespace ffp
