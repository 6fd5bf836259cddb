#include "tearing/tear_stage.h"

#include <cmath>
#include <numbers>

#include "sim/cloth.h"
#include "sim/cloth_topology.h"
#include "tearing/tear_mesh.h"
#include "tearing/tensile_stress.h"

namespace weft {

namespace {

// How far each copy of a separated vertex moves into its own side (m). The copies start at one
// point, so the two lips of a fresh tear touch exactly: self-collision could not tell which side
// is which and would treat the seam as a collision in every step (ARCSim nudges its copies apart
// too). A micrometre is far below any contact thickness: the proximity pass then sees two lips
// in contact with a well-defined normal, as it would after any fold.
constexpr double kCopySeparation = 1e-6;

// Moves each copy of a separated vertex (and its original) towards the middle of its own
// triangles, so the lips of the tear no longer coincide. Velocities are not touched (momentum is
// kept); the masses do not move by more than a micrometre.
void nudgeCopiesApart(ClothMesh& mesh, const TopologyChange& change) {
  if (change.vertexCopies.empty()) return;
  std::vector<int> moved;
  for (const auto& [original, copy] : change.vertexCopies) {
    moved.push_back(original);
    moved.push_back(copy);
  }
  std::vector<Vec3> towards(moved.size(), Vec3::Zero());
  for (const Triangle& t : mesh.tris) {
    const Vec3 centroid = (mesh.x[t.v[0]] + mesh.x[t.v[1]] + mesh.x[t.v[2]]) / 3.0;
    for (std::size_t k = 0; k < moved.size(); ++k) {
      if (t.v[0] == moved[k] || t.v[1] == moved[k] || t.v[2] == moved[k]) towards[k] += centroid - mesh.x[moved[k]];
    }
  }
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const double length = towards[k].norm();
    if (length > 0.0 && std::isfinite(length)) mesh.x[moved[k]] += (kCopySeparation / length) * towards[k];
  }
}

}  // namespace

TearStage::TearStage(const Scene& scene) : spec_(scene.tearing) {
  search_.lines = spec_.denseLines ? CandidateLines::Dense : CandidateLines::Thesis;
  search_.denseDirections = spec_.denseDirections;
  search_.skipByBound = spec_.skipByBound;
  search_.onlyTheBest = spec_.maxTearsPerStep == 1;
  selection_.maxTearsPerStep = spec_.maxTearsPerStep;
  selection_.minSpacing = spec_.minSpacing;
  materialsChanged(scene);
}

void TearStage::materialsChanged(const Scene& scene) {
  bool anyTable = false;
  for (const ClothSpec& cloth : scene.cloths) anyTable = anyTable || cloth.material.tearTable.has_value();
  runs_ = scene.stages.tearing && anyTable;
}

std::vector<TopologyChange> TearStage::run(std::vector<Cloth>& cloths, double time, StageProfile& profile) {
  std::vector<TopologyChange> changed(cloths.size());
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
      nudgeCopiesApart(cloth.mesh, change);
      accumulateTopologyChange(changed[c], change);
      ++stats_.tears;
      log_.push_back(records[k]);
    }
  }
  return changed;
}

}  // namespace weft
