#include "tearing/tear_table.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "util/input_error.h"
#include "util/json_fields.h"
#include "util/json_text.h"

namespace weft {

double tableDirectionDeg(const TearTable& table, int k) { return 180.0 * k / static_cast<double>(table.strength.size()); }

double requiredStrength(const TearTable& table, double alphaDeg) {
  const int n = static_cast<int>(table.strength.size());
  // Thesis §3.1: interpolate between the measured directions; 135 deg interpolates towards
  // 180 deg, which is 0 deg again (a line has no sense).
  // fmod returns an argument already within a half turn unchanged, bit for bit: it is skipped
  // there (most calls, one per candidate line).
  double a = alphaDeg;
  if (!(a >= 0.0 && a < 180.0)) {
    a = std::fmod(a, 180.0);
    if (a < 0.0) a += 180.0;
  }
  const double position = a * n / 180.0;
  const int below = std::min(static_cast<int>(position), n - 1);
  const double f = position - below;
  const double low = table.strength[below];
  const double high = table.strength[(below + 1) % n];
  return ((1.0 - f) * low + f * high) * table.unitNPerM;
}

double weakestStrengthBetween(const TearTable& table, double fromDeg, double toDeg) {
  if (!(toDeg - fromDeg < 180.0)) return weakestStrength(table);
  double weakest = std::min(requiredStrength(table, fromDeg), requiredStrength(table, toDeg));
  const double spacing = 180.0 / static_cast<double>(table.strength.size());
  for (double direction = std::ceil(fromDeg / spacing) * spacing; direction <= toDeg; direction += spacing) {
    weakest = std::min(weakest, requiredStrength(table, direction));
  }
  return weakest;
}

double weakestStrength(const TearTable& table) {
  return *std::min_element(table.strength.begin(), table.strength.end()) * table.unitNPerM;
}

TearTable parseTearTable(const nlohmann::json& j, const std::string& file, const std::string& path) {
  const FieldReader r(j, path, file, {"name", "source", "directions_deg", "strength", "unit_n_per_m", "propagation_factor"});
  TearTable table;
  if (r.has("name")) table.name = r.requiredString("name", "the tear table's name");
  if (r.has("source")) table.source = r.requiredString("source", "where the numbers come from");
  const nlohmann::json& strength =
      r.required("strength", "the required separation strengths, an array of numbers over evenly spaced directions");
  if (!strength.is_array() || strength.empty()) {
    r.fail(r.pointer("strength"), "must be a non-empty array of required separation strengths, " + r.got(strength));
  }
  for (std::size_t k = 0; k < strength.size(); ++k) {
    table.strength.push_back(r.numberValue(strength[k], childPointer(r.pointer("strength"), k), Bound::Positive,
                                           "a required separation strength"));
  }
  table.unitNPerM = r.number("unit_n_per_m", 1.0, Bound::Positive, "the newtons per metre of one table unit");
  table.propagationFactor = r.number("propagation_factor", 1.0, Bound::UnitInterval,
                                     "the share of the table's strength a crack tip needs to run on");
  if (!(table.propagationFactor > 0.0)) {
    r.fail(r.pointer("propagation_factor"), "must be above 0 (a crack tip needs some strength to run on)");
  }
  // The directions are implied (evenly spaced from 0); when written out they must say the same.
  if (r.has("directions_deg")) {
    const nlohmann::json& directions = r.array("directions_deg");
    const std::string at = r.pointer("directions_deg");
    if (directions.size() != strength.size()) {
      r.fail(at, "must list one direction per strength (" + std::to_string(strength.size()) + "), got " +
                     std::to_string(directions.size()));
    }
    for (std::size_t k = 0; k < directions.size(); ++k) {
      const double given = r.numberValue(directions[k], childPointer(at, k), Bound::Finite);
      const double expected = tableDirectionDeg(table, static_cast<int>(k));
      if (std::abs(given - expected) > 1e-9) {
        r.fail(childPointer(at, k), "must be " + std::to_string(expected) +
                                        ": a tear table's directions are evenly spaced over [0, 180) from 0");
      }
    }
  }
  return table;
}

nlohmann::json tearTableToJson(const TearTable& table) {
  nlohmann::json out;
  if (!table.name.empty()) out["name"] = table.name;
  if (!table.source.empty()) out["source"] = table.source;
  nlohmann::json directions = nlohmann::json::array();
  for (int k = 0; k < static_cast<int>(table.strength.size()); ++k) directions.push_back(tableDirectionDeg(table, k));
  out["directions_deg"] = directions;
  out["strength"] = table.strength;
  out["unit_n_per_m"] = table.unitNPerM;
  if (table.propagationFactor != 1.0) out["propagation_factor"] = table.propagationFactor;
  return out;
}

TearTable loadTearTablePreset(const std::string& name, const std::vector<std::filesystem::path>& presetDirs,
                              const std::string& referencingFile, const std::string& referencingField,
                              std::filesystem::path* found) {
  const bool plainName = !name.empty() && name.find_first_of("/\\") == std::string::npos && name != "." && name != "..";
  std::vector<std::string> available, searched;
  for (const auto& dir : presetDirs) {
    searched.push_back(dir.string());
    const std::filesystem::path file = dir / (name + ".json");
    if (plainName && std::filesystem::is_regular_file(file)) {
      const nlohmann::json j = readJsonFile(file, "the tear table file");  // strict: util/json_text.h
      const FieldReader r(j, "", file.string());
      r.requiredString("name", "the preset's name");
      r.requiredString("source", "where the numbers come from");
      TearTable table = parseTearTable(j, file.string(), "");
      if (table.name != name) {
        throw InputError(file.string(), "/name",
                         "is '" + table.name + "' but the preset is looked up as '" + name + "'; they must match");
      }
      if (found != nullptr) *found = file;
      return table;
    }
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
      if (entry.path().extension() == ".json") available.push_back(entry.path().stem().string());
    }
  }
  std::sort(available.begin(), available.end());
  available.erase(std::unique(available.begin(), available.end()), available.end());
  throw InputError(referencingFile, referencingField,
                   "unknown tear table preset '" + name + "'; available presets: " +
                       (available.empty() ? std::string("none") : joinNames(available)) + " (searched: " +
                       joinNames(searched) + ")");
}

double angleFromWarpDeg(double angle, double weftAngleRad) {
  // Eq. 3.1-3.2 take the signed angle from the line's direction C to V = U turned by +90 degrees:
  // det(C, V) = cos(theta - w) and C . V = sin(theta - w), so alpha = w + 90 degrees - theta, which
  // Eq. 3.3 brings into [0, 180). In closed form: no trigonometry per line (the search's inner loop).
  double alpha = (weftAngleRad - angle) * (180.0 / std::numbers::pi) + 90.0;
  if (!(alpha > -180.0 && alpha < 180.0)) alpha = std::fmod(alpha, 180.0);  // fmod leaves these as they are
  if (alpha < 0.0) alpha += 180.0;
  // A line at exactly 0 may round to just below 180, which is the same line: report 0.
  return alpha < 180.0 - 1e-9 ? alpha : 0.0;
}

}  // namespace weft
