#include "tearing/tear_stage.h"

#include <cmath>
#include <numbers>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "tearing/tear_mesh.h"
#include "tearing/tensile_stress.h"

namespace weft {

TearStage::TearStage(const Scene& scene) : spec_(scene.tearing) {
  search_.lines = spec_.denseLines ? CandidateLines::Dense : CandidateLines::Thesis;
  search_.denseDirections = spec_.denseDirections;
  search_.skipByBound = spec_.skipByBound;
  search_.onlyTheBest = spec_.maxTearsPerStep == 1;
  selection_.maxTearsPerStep = spec_.maxTearsPerStep;
  selection_.minSpacing = spec_.minSpacing;
  bool anyTable = false;
  for (const ClothSpec& cloth : scene.cloths) anyTable = anyTable || cloth.material.tearTable.has_value();
  runs_ = scene.stages.tearing && anyTable;
}

std::vector<char> TearStage::run(std::vector<Cloth>& cloths, double time, StageProfile& profile) {
  std::vector<char> changed(cloths.size(), 0);
  if (!runs_) return changed;
  TearGuards guards;
  guards.minEdgeLength = spec_.minEdgeLength;
  guards.minAngleDeg = spec_.minAngleDeg;
  guards.snapAngleDeg = spec_.snapAngleDeg;
  for (std::size_t c = 0; c < cloths.size(); ++c) {
    Cloth& cloth = cloths[c];
    if (!cloth.material.tearTable) continue;
    if (corners_.size() != cloths.size()) corners_.resize(cloths.size());
    std::vector<TriangleCorners>& corners = corners_[c];
    if (corners.size() != cloth.mesh.tris.size()) corners = triangleCorners(cloth.mesh);
    {
      StageTimer timer(profile, "tear_stress");
      tensileStresses(cloth, stress_);
    }
    std::vector<TearCandidate> chosen;
    {
      StageTimer timer(profile, "tear_search");
      findTearCandidates(cloth.mesh, corners, stress_, *cloth.material.tearTable, cloth.weftAngleRad, search_,
                         candidates_, stats_.search);
      chosen = selectTears(candidates_, selection_);
    }
    if (chosen.empty()) continue;
    StageTimer timer(profile, "tear_surgery");
    // The records are taken before any surgery: a tear appends vertices and triangles, and the
    // fans read here are those the candidates were found in.
    std::vector<TearRecord> records;
    for (const TearCandidate& tear : chosen) {
      TearRecord record;
      record.time = time;
      record.cloth = static_cast<int>(c);
      record.vertex = tear.vertex;
      record.position = cloth.mesh.x[tear.vertex];
      record.restPosition = tear.restPosition;
      record.angleDeg = tear.angle * 180.0 / std::numbers::pi;
      record.alphaDeg = tear.alphaDeg;
      record.ray = tear.ray;
      record.separation = tear.separation;
      record.required = tear.required;
      record.ratio = tear.ratio;
      records.push_back(record);
    }
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      TopologyChange change;
      const Vec2 direction(std::cos(chosen[k].angle), std::sin(chosen[k].angle));
      if (!tearThroughVertex(cloth.mesh, chosen[k].vertex, direction, guards, cloth.material.areaDensity, change)) {
        ++stats_.refused;
        continue;
      }
      applyTopologyChange(cloth, change);
      updateTriangleCorners(cloth.mesh, change.changedTriangles, corners);
      changed[c] = 1;
      ++stats_.tears;
      log_.push_back(records[k]);
    }
  }
  return changed;
}

}  // namespace weft
