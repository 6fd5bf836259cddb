#pragma once
// The one exception type for bad user input (scene, preset, mesh file). It names the file and
// the field so the message can be acted on; the simulation step itself never throws.
#include <stdexcept>
#include <string>

#include "util/echo.h"

namespace weft {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string field, const std::string& what)
      : std::runtime_error(format(file, field, what)),
        file_(std::move(file)),
        field_(std::move(field)),
        message_(what) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  // The problem alone, without the file and field in front.
  const std::string& message() const { return message_; }

 private:
  // File and field come from the user (a path, a key of any length) and are shown as one short
  // line each; the problem is written by us, with every echoed value already shortened, and is
  // only cut as a last guard so that one message never floods a terminal.
  static std::string format(const std::string& file, const std::string& field, const std::string& what) {
    std::string out = file.empty() ? std::string("<input>") : echo(file, 200);
    if (!field.empty()) out += ": " + echo(field, 200);
    return out + ": " + echo(what, 1000);
  }
  std::string file_;
  std::string field_;
  std::string message_;
};

}  // namespace weft
