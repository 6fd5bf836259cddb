#include "util/json_text.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "util/echo.h"
#include "util/input_error.h"
#include "util/json_fields.h"

namespace weft {
namespace {

using nlohmann::json;

// Builds the value as nlohmann's own DOM parser would, one SAX event at a time, keeping the JSON
// pointer of every open container so that a rejection can name where it happened. Errors are
// recorded and parsing stopped by returning false (never thrown through the parser).
class StrictBuilder : public nlohmann::json_sax<json> {
 public:
  explicit StrictBuilder(json& out) : root_(out) {}

  const std::optional<std::pair<std::string, std::string>>& error() const { return error_; }

  bool null() override { return put(json(nullptr)); }
  bool boolean(bool value) override { return put(json(value)); }
  bool number_integer(number_integer_t value) override { return put(json(value)); }
  bool number_unsigned(number_unsigned_t value) override { return put(json(value)); }
  bool number_float(number_float_t value, const string_t& text) override {
    // The lexer turns 1e400 into infinity; nlohmann's DOM parser refuses it, and so do we.
    if (!std::isfinite(value)) return fail(valuePointer(), "the number " + echo(text) + " is too large for a double");
    return put(json(value));
  }
  bool string(string_t& value) override {
    if (value.find('\0') != std::string::npos) return fail(valuePointer(), "a string may not contain \\u0000");
    return put(json(std::move(value)));
  }
  bool binary(binary_t& value) override { return put(json(json::binary_t(std::move(value)))); }

  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    Frame& frame = stack_.back();
    if (name.find('\0') != std::string::npos) return fail(frame.pointer, "a key may not contain \\u0000");
    if (frame.container->contains(name)) {
      return fail(childPointer(frame.pointer, name),
                  "duplicate key \"" + echo(name) + "\"; a key may appear only once in an object");
    }
    frame.key = std::move(name);
    return true;
  }

  bool parse_error(std::size_t, const std::string& lastToken, const nlohmann::detail::exception& e) override {
    // The parser reports a number beyond a double (1e999) as an error of its own (out_of_range 406).
    if (e.id == 406) return fail(valuePointer(), "the number " + echo(lastToken) + " is too large for a double");
    // nlohmann's message quotes the last token read, which can be a whole long string.
    return fail("", std::string("not valid JSON: ") + echo(e.what(), 240));
  }

 private:
  struct Frame {
    json* container;
    std::string pointer;
    std::string key;  // the key whose value comes next (objects only)
  };

  std::string valuePointer() const {
    if (stack_.empty()) return "";
    const Frame& frame = stack_.back();
    if (frame.container->is_object()) return childPointer(frame.pointer, frame.key);
    return childPointer(frame.pointer, frame.container->size());
  }

  json* put(json&& value) {
    if (stack_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& frame = stack_.back();
    if (frame.container->is_object()) return &((*frame.container)[frame.key] = std::move(value));
    frame.container->push_back(std::move(value));
    return &frame.container->back();
  }

  bool open(json&& empty) {
    const std::string pointer = valuePointer();
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
      return fail(pointer, "nested deeper than " + std::to_string(kMaxJsonDepth) +
                               " levels of arrays and objects; no Weft file needs that many");
    }
    json* container = put(std::move(empty));
    stack_.push_back(Frame{container, pointer, {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  bool fail(std::string pointer, std::string message) {
    if (!error_) error_ = std::make_pair(std::move(pointer), std::move(message));
    return false;
  }

  json& root_;
  std::vector<Frame> stack_;
  std::optional<std::pair<std::string, std::string>> error_;
};

}  // namespace

json parseJsonText(std::string_view text, const std::string& file, JsonTextOptions options) {
  json value;
  StrictBuilder builder(value);
  bool ok = false;
  try {
    ok = json::sax_parse(text, &builder, json::input_format_t::json, /*strict=*/true, options.allowComments);
  } catch (const json::exception& e) {  // defensive: the SAX interface reports through parse_error
    throw InputError(file, "", std::string("not valid JSON: ") + echo(e.what(), 240));
  }
  if (!ok) {
    if (const auto& error = builder.error()) throw InputError(file, error->first, error->second);
    throw InputError(file, "", "not valid JSON");
  }
  return value;
}

json readJsonFile(const std::filesystem::path& file, const std::string& what, JsonTextOptions options) {
  std::error_code error;
  if (std::filesystem::is_directory(file, error)) throw InputError(file.string(), "", "cannot open " + what + " (it is a folder)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "", "cannot open " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return parseJsonText(text.str(), file.string(), options);
}

}  // namespace weft
