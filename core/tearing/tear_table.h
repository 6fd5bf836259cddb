#pragma once
// A tear table (thesis §3.1, Table 3.1 and 4.1): the separation strength a line in the cloth needs
// before it tears, measured in a few evenly spaced directions and interpolated in between.
//
// Directions are angles alpha of the line from the warp direction V in material space (thesis
// Eq. 3.1-3.3), over [0, 180): a line has no sense, so 180 is 0 again and the table is periodic.
// N values sit at alpha = 0, 180/N, 2*180/N, ... (the thesis' 0, 45, 90, 135 for N = 4).
//
// Unit: the required strength is a traction, N/m: a straight line through a uniformly stressed
// sheet tears when the traction across it (stress times the line's normal, per metre of line)
// exceeds the table's value for its direction (separation_strength.h computes that traction). The thesis'
// numbers (5-35) carry no unit; a table stores them as written with `unitNPerM`, the newtons per
// metre of one table unit, so the source's numbers stay recognisable.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace weft {

struct TearTable {
  std::string name;               // preset name, e.g. "karaoz2015-table4.1-cloth2" (may be empty inline)
  std::string source;             // where the numbers come from
  std::vector<double> strength;   // table units, at alpha = k * 180 / N degrees; all > 0
  double unitNPerM = 1.0;         // N/m per table unit
  // Initiation against propagation: a crack tip (a vertex on a torn or cut edge) needs only this
  // share of the table's strength to run on. Woven fabrics start a tear at their tensile strength
  // but propagate it at their much lower tear strength (the gap between a grab test, ASTM D5034,
  // and a tongue tear test, ASTM D2261): a notch runs where an intact sheet holds. In (0, 1];
  // 1 (the default) tears tips and intact cloth alike, as the thesis does.
  double propagationFactor = 1.0;

  friend bool operator==(const TearTable&, const TearTable&) = default;
};

// The required separation strength (N/m) of a line at alpha degrees from V: linear interpolation
// between the two neighbouring table directions, periodic over 180 degrees (thesis §3.1).
double requiredStrength(const TearTable& table, double alphaDeg);

// The smallest required strength over all directions (N/m): with linear interpolation, the
// smallest table entry. A vertex whose separation strength cannot reach it cannot tear.
double weakestStrength(const TearTable& table);

// The smallest required strength (N/m) over the directions [fromDeg, toDeg] (fromDeg <= toDeg,
// any real numbers: periodic over 180): the ends and every table direction between them, as the
// interpolation is linear in between.
double weakestStrengthBetween(const TearTable& table, double fromDeg, double toDeg);

// alpha of a line at `angle` (rad, material space) from the warp direction V of a cloth whose weft
// U is at weftAngleRad from material x: Eq. 3.1-3.3 as printed (degrees, in [0, 180)).
double angleFromWarpDeg(double angle, double weftAngleRad);

// The direction of table entry k, degrees from V.
double tableDirectionDeg(const TearTable& table, int k);

// Strict parsing: `file` and `path` name the object in error messages. Throws InputError.
TearTable parseTearTable(const nlohmann::json& j, const std::string& file, const std::string& path);
nlohmann::json tearTableToJson(const TearTable& table);
// Loads presets/tear_tables/<name>.json from the first of `presetDirs` that has it; `found`, when
// given, is set to the file read.
TearTable loadTearTablePreset(const std::string& name, const std::vector<std::filesystem::path>& presetDirs,
                              const std::string& referencingFile, const std::string& referencingField,
                              std::filesystem::path* found = nullptr);

}  // namespace weft
