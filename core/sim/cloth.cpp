#include "sim/cloth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "mesh/grid.h"
#include "mesh/obj_import.h"
#include "util/input_error.h"

namespace weft {

Mat3 placementRotation(const Placement& placement) {
  using Eigen::AngleAxisd;
  const Vec3 r = placement.rotateDeg * (kPi / 180.0);
  // About world x, then y, then z.
  return (AngleAxisd(r.z(), Vec3::UnitZ()) * AngleAxisd(r.y(), Vec3::UnitY()) * AngleAxisd(r.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

namespace {

// Material-space position of each vertex (from the first triangle corner that names it).
std::vector<Vec2> vertexRestPositions(const ClothMesh& mesh) {
  std::vector<Vec2> rest(mesh.vertexCount(), Vec2::Zero());
  std::vector<char> seen(mesh.vertexCount(), 0);
  for (const Triangle& t : mesh.tris)
    for (int k = 0; k < 3; ++k)
      if (!seen[t.v[k]]) {
        seen[t.v[k]] = 1;
        rest[t.v[k]] = t.rest[k];
      }
  return rest;
}

// objVertices: for an OBJ cloth, where its `v` lines went; pins by id name `v` lines there.
std::vector<int> selectPinGroup(const ClothMesh& mesh, const ObjVertexMap* objVertices, const PinGroup& group,
                                const std::string& sceneFile, const std::string& field) {
  std::vector<int> selected;
  const std::vector<Vec2> rest = vertexRestPositions(mesh);
  if (!group.corners.empty()) {
    Vec2 lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    Vec2 hi = -lo;
    for (const Vec2& p : rest) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    for (const std::string& corner : group.corners) {
      Vec2 target;
      if (corner == "top_left") target = Vec2(lo.x(), hi.y());
      else if (corner == "top_right") target = hi;
      else if (corner == "bottom_left") target = lo;
      else if (corner == "bottom_right") target = Vec2(hi.x(), lo.y());
      else throw InputError(sceneFile, field + "/corners", "unknown corner '" + corner + "'");
      int best = kNone;
      double bestDistance = std::numeric_limits<double>::max();
      for (int i = 0; i < mesh.vertexCount(); ++i) {
        const double distance = (rest[i] - target).squaredNorm();
        if (distance < bestDistance) {  // strict: the lowest id wins ties (deterministic)
          bestDistance = distance;
          best = i;
        }
      }
      if (best != kNone) selected.push_back(best);
    }
  }
  if (group.restBox) {
    const auto& [lo, hi] = *group.restBox;
    for (int i = 0; i < mesh.vertexCount(); ++i)
      if ((rest[i].array() >= lo.array()).all() && (rest[i].array() <= hi.array()).all()) selected.push_back(i);
  }
  for (int id : group.vertices) {
    if (objVertices != nullptr) {
      if (id < 0 || id >= objVertices->objVertexCount() || objVertices->clothVertices[static_cast<std::size_t>(id)].empty())
        throw InputError(sceneFile, field + "/vertices",
                         "vertex id " + std::to_string(id) + " names no `v` line used by a face of the OBJ file");
      for (int v : objVertices->clothVertices[static_cast<std::size_t>(id)]) selected.push_back(v);
      continue;
    }
    if (id < 0 || id >= mesh.vertexCount())
      throw InputError(sceneFile, field + "/vertices",
                       "vertex id " + std::to_string(id) + " out of range [0, " + std::to_string(mesh.vertexCount()) + ")");
    selected.push_back(id);
  }
  std::sort(selected.begin(), selected.end());
  selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
  if (selected.empty()) throw InputError(sceneFile, field, "the pin group selects no vertex");
  return selected;
}

}  // namespace

Vec3 pinOffset(const std::vector<PinKeyframe>& script, double t) {
  if (script.empty()) return Vec3::Zero();
  if (t <= script.front().time) return script.front().offset;
  for (size_t k = 1; k < script.size(); ++k) {
    if (t <= script[k].time) {
      const PinKeyframe& a = script[k - 1];
      const PinKeyframe& b = script[k];
      const double span = b.time - a.time;
      const double s = span > 0.0 ? (t - a.time) / span : 1.0;
      return (1.0 - s) * a.offset + s * b.offset;
    }
  }
  return script.back().offset;
}

void pinTargets(const Cloth& cloth, double t, std::vector<int>& outVertices, std::vector<Vec3>& outPositions,
                StageProfile& profile) {
  outVertices.clear();
  outPositions.clear();
  if (cloth.pins.empty()) return;
  StageTimer timer(profile, "pins");
  for (const PinTrack& track : cloth.pins) {
    const Vec3 offset = pinOffset(track.script, t);
    for (size_t k = 0; k < track.vertices.size(); ++k) {
      outVertices.push_back(track.vertices[k]);
      outPositions.push_back(track.start[k] + offset);
    }
  }
}

void rebuildElements(Cloth& cloth) {
  cloth.membranes.resize(cloth.mesh.tris.size());
  for (size_t t = 0; t < cloth.mesh.tris.size(); ++t)
    cloth.membranes[t] = makeMembraneElement(cloth.mesh.tris[t], cloth.weftAngleRad);
  cloth.hinges.clear();
  if (bendingEnabled(cloth.material.bending)) cloth.hinges = buildBendingHinges(cloth.mesh, cloth.weftAngleRad);
}

CoupledVertexPairs coupledVertexPairs(const Cloth& cloth) {
  CoupledVertexPairs pairs;
  pairs.edges.reserve(cloth.mesh.edges.size());
  pairs.hingeWings.reserve(cloth.hinges.size());
  for (const Edge& e : cloth.mesh.edges) pairs.edges.emplace_back(e.v[0], e.v[1]);
  for (const BendingHinge& h : cloth.hinges) pairs.hingeWings.emplace_back(h.v[2], h.v[3]);
  return pairs;
}

CoupledVertexPairs coupledVertexPairs(const Cloth& cloth, const TopologyChange& change) {
  CoupledVertexPairs pairs;
  const std::vector<int>& edges = change.changedEdges;  // sorted
  for (int e : edges) pairs.edges.emplace_back(cloth.mesh.edges[e].v[0], cloth.mesh.edges[e].v[1]);
  // Every hinge on a changed edge was remade (cloth_topology.h). One pass over the hinges: a few
  // microseconds, and it needs no assumption on where they were put.
  for (const BendingHinge& h : cloth.hinges) {
    if (std::binary_search(edges.begin(), edges.end(), h.edge)) pairs.hingeWings.emplace_back(h.v[2], h.v[3]);
  }
  return pairs;
}

Cloth buildCloth(const ClothSpec& spec, const std::string& sceneFile, int clothIndex) {
  const std::string field = "/cloths/" + std::to_string(clothIndex);
  Cloth cloth;
  ObjVertexMap objVertices;
  cloth.name = spec.name;
  cloth.material = spec.material;
  cloth.weftAngleRad = degToRad(spec.weftAngleDeg);
  if (spec.grid) {
    try {
      cloth.mesh = makeGrid(*spec.grid);
    } catch (const InputError& e) {
      throw InputError(sceneFile, field + "/mesh/" + e.field(), e.what());
    }
  } else if (spec.obj) {
    cloth.mesh = loadObjMesh(*spec.obj, sceneFile, &objVertices);
  } else {
    throw InputError(sceneFile, field + "/mesh", "needs a grid or an obj");
  }
  const Mat3 rotation = placementRotation(spec.placement);
  for (Vec3& x : cloth.mesh.x) x = rotation * x + spec.placement.translate;

  for (size_t t = 0; t < cloth.mesh.tris.size(); ++t) {
    if (!(restArea(cloth.mesh.tris[t]) > 0.0))
      throw InputError(sceneFile, field + "/mesh",
                       "triangle " + std::to_string(t) + " has zero or negative rest area (degenerate mesh)");
  }
  assignLumpedMasses(cloth.mesh, cloth.material.areaDensity);
  rebuildElements(cloth);
  // By default a map or a region's image spans the cloth's material-space bounding box (strength_map.h).
  cloth.tearStrengthMap = spec.tearStrengthMap;
  if (cloth.tearStrengthMap) prepareStrengthMapFor(*cloth.tearStrengthMap, cloth.mesh);
  cloth.tearRegion = spec.tearRegion;
  if (cloth.tearRegion) prepareStrengthMapFor(cloth.tearRegion->outside, cloth.mesh);

  for (size_t g = 0; g < spec.pins.size(); ++g) {
    PinTrack track;
    track.vertices = selectPinGroup(cloth.mesh, spec.obj ? &objVertices : nullptr, spec.pins[g], sceneFile, field + "/pins/" + std::to_string(g));
    for (int v : track.vertices) {
      track.start.push_back(cloth.mesh.x[v]);
      cloth.mesh.pinned[v] = 1;
    }
    track.script = spec.pins[g].script;
    cloth.pins.push_back(std::move(track));
  }
  return cloth;
}

}  // namespace weft
