#pragma once
// The one exception type for bad user input (scene, preset, mesh file). It names the file and
// the field so the message can be acted on; the simulation step itself never throws.
#include <stdexcept>
#include <string>

namespace weft {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string field, const std::string& what)
      : std::runtime_error(format(file, field, what)), file_(std::move(file)), field_(std::move(field)) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  static std::string format(const std::string& file, const std::string& field, const std::string& what) {
    std::string out = file.empty() ? std::string("<input>") : file;
    if (!field.empty()) out += ": " + field;
    return out + ": " + what;
  }
  std::string file_;
  std::string field_;
};

}  // namespace weft
