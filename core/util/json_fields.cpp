#include "util/json_fields.h"

#include "util/echo.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>

namespace weft {

using nlohmann::json;

std::string childPointer(const std::string& parent, std::string_view key) {
  std::string escaped;
  for (char c : key) {
    if (c == '~') escaped += "~0";
    else if (c == '/') escaped += "~1";
    else escaped += c;
  }
  return parent + "/" + escaped;
}

std::string childPointer(const std::string& parent, std::size_t index) {
  return parent + "/" + std::to_string(index);
}

namespace {

// NaN and infinity cannot be written in JSON text (dump() would show them as null), but a value
// built in code or by an override can hold them; they are shown by name.
std::string asWritten(const json& value) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    const double x = value.get<double>();
    return std::isnan(x) ? "NaN" : (x > 0 ? "inf" : "-inf");
  }
  // Depth is bounded by the reader (json_text.h), so dump() cannot overflow the stack; what it
  // prints is then cut to one short line.
  if (value.is_string()) return "\"" + echo(value.get_ref<const std::string&>()) + "\"";
  return echo(value.dump(-1, ' ', false, json::error_handler_t::replace));
}

std::string kind(const json& value) {
  if (value.is_array()) return "an array of " + std::to_string(value.size());
  if (value.is_object()) return "an object";
  return std::string("a ") + value.type_name();
}

}  // namespace

std::string got(const json& value, GotStyle style) {
  if (value.is_number()) return "got " + asWritten(value);
  if (style == GotStyle::Kind) return "got " + kind(value);
  return std::string("got ") + value.type_name() + " " + asWritten(value);
}

bool satisfies(double x, Bound bound) {
  if (!std::isfinite(x)) return false;
  switch (bound) {
    case Bound::Finite: return true;
    case Bound::Positive: return x > 0.0;
    case Bound::NonNegative: return x >= 0.0;
    case Bound::UnitInterval: return x >= 0.0 && x <= 1.0;
  }
  return false;
}

std::string expectation(Bound bound) {
  switch (bound) {
    case Bound::Finite: return "must be a finite number";
    case Bound::Positive: return "must be a positive finite number (> 0)";
    case Bound::NonNegative: return "must be a finite number >= 0";
    case Bound::UnitInterval: return "must be a number in [0, 1]";
  }
  return "";
}

FieldReader::FieldReader(const json& object, std::string pointer, std::string file, GotStyle style)
    : object_(object), pointer_(std::move(pointer)), file_(std::move(file)), style_(style) {
  if (!object_.is_object()) fail(pointer_, "must be a JSON object, " + got(object_));
}

FieldReader::FieldReader(const json& object, std::string pointer, std::string file,
                         const std::vector<std::string>& allowed, GotStyle style)
    : FieldReader(object, std::move(pointer), std::move(file), style) {
  allowOnly(allowed);
}

void FieldReader::allowOnly(const std::vector<std::string>& allowed) const {
  for (const auto& item : object_.items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
      fail(pointer(item.key()), "unknown key \"" + echo(item.key()) + "\"; allowed keys here: " + joinNames(allowed));
    }
  }
}

void FieldReader::fail(const std::string& pointer, const std::string& message) const {
  throw InputError(file_, pointer, message);
}

const json& FieldReader::required(const std::string& key, const std::string& what) const {
  if (!has(key)) fail(pointer(key), "missing required field \"" + key + "\"; expected " + what);
  return at(key);
}

double FieldReader::number(const std::string& key, double fallback, Bound bound, const std::string& description) const {
  if (!has(key)) return fallback;
  return numberValue(at(key), pointer(key), bound, description);
}

double FieldReader::requiredNumber(const std::string& key, Bound bound, const std::string& description) const {
  return numberValue(required(key, description), pointer(key), bound, description);
}

double FieldReader::numberValue(const json& value, const std::string& at, Bound bound,
                                const std::string& description) const {
  if (!value.is_number() || !satisfies(value.get<double>(), bound)) {
    fail(at, lead(description) + expectation(bound) + ", " + got(value));
  }
  return value.get<double>();
}

std::string formatNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string describe(const Range& range) {
  char text[96];
  std::snprintf(text, sizeof text, "%s%g, %g]%s%s", range.loOpen ? "(" : "[", range.lo, range.hi,
                *range.unit ? " " : "", range.unit);
  return text;
}

double FieldReader::number(const std::string& key, double fallback, const Range& range,
                           const std::string& description) const {
  if (!has(key)) return fallback;
  return numberValue(at(key), pointer(key), range, description);
}

double FieldReader::numberValue(const json& value, const std::string& at, const Range& range,
                                const std::string& description) const {
  const bool inside = value.is_number() && std::isfinite(value.get<double>()) &&
                      (range.loOpen ? value.get<double>() > range.lo : value.get<double>() >= range.lo) &&
                      value.get<double>() <= range.hi;
  if (!inside) fail(at, lead(description) + "must be a number in " + describe(range) + ", " + got(value));
  return value.get<double>();
}

int FieldReader::integer(const std::string& key, int fallback, int minimum, int maximum) const {
  if (!has(key)) return fallback;
  return integerValue(at(key), pointer(key), minimum, maximum);
}

int FieldReader::integerValue(const json& value, const std::string& at, int minimum, int maximum) const {
  const std::string expected =
      "must be an integer in [" + std::to_string(minimum) + ", " + std::to_string(maximum) + "]";
  if (!value.is_number()) fail(at, expected + ", " + got(value));
  const double x = value.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || x < minimum || x > maximum) fail(at, expected + ", " + got(value));
  return static_cast<int>(x);
}

int FieldReader::integer(const std::string& key, int fallback, int minimum) const {
  if (!has(key)) return fallback;
  return integerValue(at(key), pointer(key), minimum);
}

int FieldReader::integerValue(const json& value, const std::string& at, int minimum) const {
  const std::string expected = "must be an integer >= " + std::to_string(minimum);
  if (!value.is_number()) fail(at, expected + ", " + got(value));
  const double x = value.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || x < minimum ||
      x > static_cast<double>(std::numeric_limits<int>::max())) {
    fail(at, expected + ", " + got(value));
  }
  return static_cast<int>(x);
}

bool FieldReader::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  if (!at(key).is_boolean()) fail(pointer(key), "must be true or false, " + got(at(key)));
  return at(key).get<bool>();
}

std::string FieldReader::string(const std::string& key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  return stringValue(at(key), pointer(key));
}

std::string FieldReader::stringValue(const json& value, const std::string& at) const {
  if (!value.is_string()) fail(at, "must be a string, " + got(value));
  return value.get<std::string>();
}

std::string FieldReader::requiredString(const std::string& key, const std::string& description) const {
  const json& value = required(key, description);
  if (!value.is_string() || value.get<std::string>().empty()) {
    fail(pointer(key), lead(description) + "must be a non-empty string, " + got(value));
  }
  return value.get<std::string>();
}

const json& FieldReader::array(const std::string& key) const {
  if (!at(key).is_array()) fail(pointer(key), "must be an array, " + got(at(key)));
  return at(key);
}

void FieldReader::requireExactly(const std::string& key, const json& expected) const {
  const json& value = required(key, expected.dump());
  if (value != expected) fail(pointer(key), "must be exactly " + expected.dump() + ", got " + asWritten(value));
}

}  // namespace weft
