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
  selection_.maxTearsPerStep = spec_.maxTearsPerStep;
  selection_.minSpacing = spec_.minSpacing;
  bool anyTable = false;
  for (const ClothSpec& cloth : scene.cloths) anyTable = anyTable || cloth.material.tearTable.has_value();
  runs_ = scene.stages.tearing && anyTable;
}

std::vector<TopologyChange> TearStage::run(std::vector<Cloth>& cloths, double time, StageProfile& profile) {
  std::vector<TopologyChange> changed(cloths.size());
  if (!runs_) return changed;
  StageTimer timer(profile, "tearing");
  TearGuards guards;
  guards.minEdgeLength = spec_.minEdgeLength;
  guards.minAngleDeg = spec_.minAngleDeg;
  guards.snapAngleDeg = spec_.snapAngleDeg;
  for (std::size_t c = 0; c < cloths.size(); ++c) {
    Cloth& cloth = cloths[c];
    if (!cloth.material.tearTable) continue;
    tensileStresses(cloth, stress_);
    findTearCandidates(cloth.mesh, stress_, *cloth.material.tearTable, cloth.weftAngleRad, search_, candidates_,
                       stats_.search);
    const std::vector<TearCandidate> chosen = selectTears(candidates_, cloth.mesh, selection_);
    if (chosen.empty()) continue;
    // The records are taken before any surgery: a tear appends vertices and triangles, and the
    // fans read here are those the candidates were found in.
    const std::vector<std::vector<int>> around = vertexTriangles(cloth.mesh);
    std::vector<TearRecord> records;
    for (const TearCandidate& tear : chosen) {
      TearRecord record;
      record.time = time;
      record.cloth = static_cast<int>(c);
      record.vertex = tear.vertex;
      record.position = cloth.mesh.x[tear.vertex];
      record.restPosition = restPosition(cloth.mesh, tear.vertex, around[tear.vertex]);
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
      accumulateTopologyChange(changed[c], change);
      ++stats_.tears;
      log_.push_back(records[k]);
    }
  }
  return changed;
}

}  // namespace weft
