#pragma once
// Strict reading of one JSON object: the shared mechanism behind the scene and material formats.
// A FieldReader knows the file and the JSON pointer (RFC 6901) of the object it reads, so every
// rejection is an InputError naming the exact field and what was expected instead. Which keys a
// format has, their bounds and defaults stay with the format (scene_json.cpp, material.cpp).
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/input_error.h"

namespace weft {

// The pointer of `key` (or element `index`) inside the value at `parent`; '~' and '/' in a key are
// escaped as "~0" and "~1" so the pointer can be followed back to the field.
std::string childPointer(const std::string& parent, std::string_view key);
std::string childPointer(const std::string& parent, std::size_t index);

// "a, b, c": lists allowed keys, known names or searched folders in a message.
template <typename Names>
std::string joinNames(const Names& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

// How a value of the wrong type is shown after "got". Both wordings are pinned by existing tests
// (the scene's `got string "fast"`, the material's `got a string`), so a reader says which it uses.
enum class GotStyle {
  AsWritten,  // the type and the value as written: got string "fast", got array [0,-9.81]
  Kind,       // the kind of value only: got a string, got an array of 4
};

// "got -1", "got string \"NaN\"", "got a null". Numbers are always shown as written; longer values
// are shortened so that a whole object pasted in the wrong place does not flood the terminal.
std::string got(const nlohmann::json& value, GotStyle style = GotStyle::AsWritten);

enum class Bound {
  Finite,        // any finite number
  Positive,      // > 0
  NonNegative,   // >= 0
  UnitInterval,  // in [0, 1]
};

bool satisfies(double x, Bound bound);
std::string expectation(Bound bound);  // "must be a finite number >= 0"

// The values that make physical (or practical) sense for a field: anything outside is refused at
// load time with the range in the message, before it can cost hours or overflow a count.
struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool loOpen = false;  // true: lo itself is excluded, (lo, hi]
  const char* unit = "";  // "m", "s", "m/s" (shown after the range)
};
std::string describe(const Range& range);  // "(0, 0.1] m"
std::string formatNumber(double x);        // "%g": 1e-12, 0.005, 3e+151 (never 320 digits)

class FieldReader {
 public:
  // Rejects a non-object. Use allowOnly() once the allowed keys are known (they may depend on a
  // field such as "model").
  FieldReader(const nlohmann::json& object, std::string pointer, std::string file, GotStyle style = GotStyle::AsWritten);
  // Rejects a non-object and any key outside `allowed`.
  FieldReader(const nlohmann::json& object, std::string pointer, std::string file, const std::vector<std::string>& allowed,
              GotStyle style = GotStyle::AsWritten);

  // The reader refers to the object rather than copying it, so a temporary cannot be read.
  FieldReader(nlohmann::json&&, std::string, std::string, GotStyle = GotStyle::AsWritten) = delete;
  FieldReader(nlohmann::json&&, std::string, std::string, const std::vector<std::string>&,
              GotStyle = GotStyle::AsWritten) = delete;

  // Rejects the first key outside `allowed`, naming it and listing the allowed ones.
  void allowOnly(const std::vector<std::string>& allowed) const;

  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  std::string pointer(const std::string& key) const { return childPointer(pointer_, key); }
  bool has(const std::string& key) const { return object_.contains(key); }
  const nlohmann::json& at(const std::string& key) const { return object_.at(key); }
  std::string got(const nlohmann::json& value) const { return weft::got(value, style_); }

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;

  // `what` says what the field should hold, e.g. "an array of at least one cloth".
  const nlohmann::json& required(const std::string& key, const std::string& what) const;

  // Numbers. `description` names the quantity ("area density in kg/m^2") and leads the message.
  double number(const std::string& key, double fallback, Bound bound, const std::string& description = "") const;
  double requiredNumber(const std::string& key, Bound bound, const std::string& description) const;
  double numberValue(const nlohmann::json& value, const std::string& at, Bound bound,
                     const std::string& description = "") const;

  // A finite number inside `range`.
  double number(const std::string& key, double fallback, const Range& range, const std::string& description = "") const;
  double numberValue(const nlohmann::json& value, const std::string& at, const Range& range,
                     const std::string& description = "") const;

  // 32.0 is accepted as 32: some tools write every number as a float.
  int integer(const std::string& key, int fallback, int minimum) const;
  int integerValue(const nlohmann::json& value, const std::string& at, int minimum) const;
  // An integer in [minimum, maximum].
  int integer(const std::string& key, int fallback, int minimum, int maximum) const;
  int integerValue(const nlohmann::json& value, const std::string& at, int minimum, int maximum) const;

  bool boolean(const std::string& key, bool fallback) const;

  std::string string(const std::string& key, const std::string& fallback) const;
  std::string stringValue(const nlohmann::json& value, const std::string& at) const;
  // A required, non-empty string (names, sources: an empty one is as good as missing).
  std::string requiredString(const std::string& key, const std::string& description) const;

  const nlohmann::json& array(const std::string& key) const;

  // A label that must repeat `expected` exactly (units, coefficient names, sample axes), so a file
  // written for another layout cannot be read by accident.
  void requireExactly(const std::string& key, const nlohmann::json& expected) const;

  // Exactly N finite numbers.
  template <std::size_t N>
  std::array<double, N> numberRow(const nlohmann::json& value, const std::string& at,
                                  const std::string& description = "") const {
    if (!value.is_array() || value.size() != N) {
      fail(at, lead(description) + "must be an array of " + std::to_string(N) + " numbers, all " + std::to_string(N) +
                   " finite, " + got(value));
    }
    std::array<double, N> row{};
    for (std::size_t i = 0; i < N; ++i) row[i] = numberValue(value[i], childPointer(at, i), Bound::Finite);
    return row;
  }

  // Exactly Rows rows of exactly Cols finite numbers.
  template <std::size_t Rows, std::size_t Cols>
  std::array<std::array<double, Cols>, Rows> numberTable(const nlohmann::json& value, const std::string& at,
                                                         const std::string& description = "") const {
    if (!value.is_array() || value.size() != Rows) {
      fail(at, lead(description) + "must be an array of " + std::to_string(Rows) + " rows of " + std::to_string(Cols) +
                   " numbers, " + got(value));
    }
    std::array<std::array<double, Cols>, Rows> table{};
    for (std::size_t i = 0; i < Rows; ++i) {
      table[i] = numberRow<Cols>(value[i], childPointer(at, i),
                                 description.empty() ? "" : "row " + std::to_string(i) + " of " + description);
    }
    return table;
  }

 private:
  static std::string lead(const std::string& description) { return description.empty() ? "" : description + " "; }

  const nlohmann::json& object_;
  std::string pointer_;
  std::string file_;
  GotStyle style_;
};

}  // namespace weft
