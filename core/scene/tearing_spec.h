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
  double minEdgeLength = 0.002;  // m (material space): no tear creates a shorter edge
  double minAngleDeg = 12.0;     // no tear creates a triangle with a smaller angle
  double snapAngleDeg = 8.0;     // a line this close to an existing edge follows the edge
};

}  // namespace weft
