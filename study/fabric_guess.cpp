#include "fabric_guess.h"

#include <fstream>

#include "util/echo.h"
#include "util/input_error.h"

namespace weft::study {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::vector<FabricGuess> readFabricGuesses(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot open the file");
  std::vector<FabricGuess> guesses;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const std::string content = trimmed(text);
    if (content.empty() || content.front() == '#') continue;
    const std::string where = "line " + std::to_string(line);
    const auto comma = content.find(',');
    const std::string fabricText = trimmed(content.substr(0, comma));
    const std::string groupText = comma == std::string::npos ? "" : trimmed(content.substr(comma + 1));
    const auto fabric = parseFabric(fabricText);
    if (!fabric)
      throw InputError(file, where,
                       "unknown fabric '" + echo(fabricText, 60) + "' (expected denim, t-shirt, pants or swimsuit)");
    FabricGuess guess{*fabric, groupOf(*fabric)};
    if (!groupText.empty()) {
      const auto group = parseGroup(groupText);
      if (!group)
        throw InputError(file, where,
                         "unknown elasticity group '" + echo(groupText, 60) + "' (expected stiff or stretchy)");
      guess.group = *group;
    }
    guesses.push_back(guess);
  }
  return guesses;
}

}  // namespace weft::study
