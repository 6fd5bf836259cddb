#pragma once
// The tearing part of a scene: how candidates are searched and chosen, and the guards of the mesh
// surgery. Which cloths can tear is the material's business (Material::tearTable); a cloth
// without a tear table never tears. Read by scene/tearing_json.cpp.
namespace weft {


struct TearingSpec {
  bool denseLines = false;       // false: the thesis' three lines per incident triangle; true: the whole fan
  int denseDirections = 180;     // dense: samples per half turn (per fan for a border vertex)
  bool skipByBound = true;       // skip vertices whose separation-strength bound cannot reach the table
  int maxTearsPerStep = 1;       // per cloth; the thesis tears one line per step
  double minSpacing = 0.1;       // m (material space): several tears in one step keep this apart
  // The guards of the mesh surgery (tearing/tear_guards.h says why these values).
  double minEdgeLength = 0.001;  // m (material space): no tear creates a shorter edge
  double minAngleDeg = 15.0;     // no tear creates a triangle with a smaller angle
  double snapAngleDeg = 5.0;     // a line this close to an existing edge follows the edge

  friend bool operator==(const TearingSpec&, const TearingSpec&) = default;
};

}  // namespace weft
