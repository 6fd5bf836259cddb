#include "mesh/obj_import.h"

// tinyobj::real_t (float, or double with TINYOBJLOADER_USE_DOUBLE) must match the library linked:
// the CMake targets tinyobjloader::tinyobjloader (float) and ::tinyobjloader_double carry the right
// definition, so nothing is defined here and the code below works for either.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/mesh_check.h"
#include "scene/scene_limits.h"
#include "util/input_error.h"
#include "util/obj_faces.h"
#include "util/obj_text.h"

namespace weft {

namespace {

// Below this UV-space area (m^2, after uvScale) a triangle has no usable rest shape.
constexpr double kMinRestArea = 1e-14;

// What every error about one OBJ file needs: its name, and the scene that asked for it.
struct ObjSource {
  std::string file;
  std::string referencingFile;

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(file, field, referencingFile.empty() ? what : what + " (mesh of " + referencingFile + ")");
  }
};

// A relative path that does not exist as given is looked up beside the file that names it.
std::filesystem::path resolvePath(const std::filesystem::path& path, const std::string& referencingFile) {
  if (path.is_absolute() || referencingFile.empty() || std::filesystem::exists(path)) return path;
  const std::filesystem::path beside = std::filesystem::path(referencingFile).parent_path() / path;
  return std::filesystem::exists(beside) ? beside : path;
}

std::string readText(const std::filesystem::path& path, const ObjSource& source) {
  std::error_code error;  // a path too long for the file system is simply not found
  if (!std::filesystem::is_regular_file(path, error)) source.fail("", "mesh file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) source.fail("", "cannot open mesh file");
  std::ostringstream text;
  text << in.rdbuf();
  return withoutByteOrderMark(text.str());
}

// Renumbers the cloth vertices by their `v` line (ties, the copies of a seam vertex, keep their
// order of first use), so that ids follow the file as its author sees it. Returns the map.
ObjVertexMap renumberInObjOrder(ClothMesh& mesh, const std::vector<int>& positionOf, int positionCount) {
  const int n = mesh.vertexCount();
  std::vector<int> byFileOrder(static_cast<std::size_t>(n));  // new id -> old id
  for (int i = 0; i < n; ++i) byFileOrder[static_cast<std::size_t>(i)] = i;
  std::stable_sort(byFileOrder.begin(), byFileOrder.end(),
                   [&](int a, int b) { return positionOf[static_cast<std::size_t>(a)] < positionOf[static_cast<std::size_t>(b)]; });
  std::vector<int> newId(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) newId[static_cast<std::size_t>(byFileOrder[static_cast<std::size_t>(i)])] = i;

  ClothMesh renumbered;
  for (int i = 0; i < n; ++i) renumbered.addVertex(mesh.x[static_cast<std::size_t>(byFileOrder[static_cast<std::size_t>(i)])]);
  renumbered.tris = std::move(mesh.tris);
  for (Triangle& t : renumbered.tris) {
    for (int& v : t.v) v = newId[static_cast<std::size_t>(v)];
  }
  mesh = std::move(renumbered);

  ObjVertexMap map;
  map.clothVertices.resize(static_cast<std::size_t>(positionCount));
  for (int i = 0; i < n; ++i) {
    map.clothVertices[static_cast<std::size_t>(positionOf[static_cast<std::size_t>(byFileOrder[static_cast<std::size_t>(i)])])]
        .push_back(i);
  }
  return map;
}

double uvArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e1 = b - a;
  const Vec2 e2 = c - a;
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

}  // namespace

bool ObjVertexMap::isIdentity() const {
  for (std::size_t k = 0; k < clothVertices.size(); ++k) {
    if (clothVertices[k].size() != 1 || clothVertices[k][0] != static_cast<int>(k)) return false;
  }
  return true;
}

ClothMesh loadObjMesh(const ObjSpec& spec, const std::string& referencingFile, ObjVertexMap* outVertexMap) {
  const std::filesystem::path path = resolvePath(spec.path, referencingFile);
  const ObjSource source{path.string(), referencingFile};
  if (!std::isfinite(spec.uvScale) || spec.uvScale <= 0.0) {
    throw InputError(referencingFile.empty() ? source.file : referencingFile, "obj.uv_scale",
                     "must be a finite scale > 0 (metres per UV unit)");
  }

  const std::string text = readText(path, source);
  // Positions and UVs are the cloth's geometry: every number on a `v` or `vt` line must be one.
  if (const auto problem = findBadCoordinate(text, {"v", "vt"})) {
    source.fail("line " + std::to_string(problem->line), problem->message);
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // fan-triangulated below, so face numbers in messages match the file
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) source.fail("", "cannot parse OBJ: " + tinyobjMessage(reader.Error()));
  // tinyobjloader only warns about faces it drops or indices it cannot resolve.
  const std::string& warning = reader.Warning();
  if (warning.find("Degenerated face") != std::string::npos) source.fail("", "a face has fewer than 3 corners");
  if (warning.find("out of bounds") != std::string::npos) source.fail("", "an index is out of range: " + tinyobjMessage(warning, "out of bounds"));

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  if (attrib.texcoords.empty()) {
    source.fail("", "has no texture coordinates (vt); a cloth's rest shape comes from its UVs");
  }
  // A number that is finite as text can still overflow tinyobjloader's real_t (float by default).
  for (const auto* values : {&attrib.vertices, &attrib.texcoords}) {
    for (const tinyobj::real_t value : *values) {
      if (!std::isfinite(value)) source.fail("", "a coordinate is too large to represent");
    }
  }
  const int positionCount = static_cast<int>(attrib.vertices.size() / 3);
  const int uvCount = static_cast<int>(attrib.texcoords.size() / 2);

  ClothMesh mesh;
  // One cloth vertex per distinct (position, UV) pair: corners that share a position but not a UV
  // lie on a seam and become separate vertices. They are first numbered in order of first use,
  // then renumbered in `v` order below.
  std::unordered_map<std::uint64_t, int> clothVertexOf;
  std::vector<int> positionOf;  // first-use number -> `v` line (from 0)
  auto clothVertex = [&](const tinyobj::index_t& corner) {
    const std::uint64_t key = (static_cast<std::uint64_t>(corner.vertex_index) << 32) |
                              static_cast<std::uint32_t>(corner.texcoord_index);
    const auto [it, isNew] = clothVertexOf.try_emplace(key, mesh.vertexCount());
    if (isNew) {
      const size_t p = 3 * static_cast<size_t>(corner.vertex_index);
      mesh.addVertex(Vec3(static_cast<double>(attrib.vertices[p]), static_cast<double>(attrib.vertices[p + 1]),
                          static_cast<double>(attrib.vertices[p + 2])));
      positionOf.push_back(corner.vertex_index);
    }
    return it->second;
  };
  auto restCoordinates = [&](const tinyobj::index_t& corner) -> Vec2 {
    const size_t t = 2 * static_cast<size_t>(corner.texcoord_index);
    return Vec2(static_cast<double>(attrib.texcoords[t]) * spec.uvScale,
                static_cast<double>(attrib.texcoords[t + 1]) * spec.uvScale);
  };

  auto fail = [&](const std::string& where, const std::string& message) { source.fail(where, message); };
  forEachObjFace(reader, positionCount, fail, [&](const std::string& face, const tinyobj::index_t* corners, int cornerCount) {
    for (int c = 0; c < cornerCount; ++c) {
      if (corners[c].texcoord_index < 0) source.fail(face, "a corner has no texture coordinate (write f v/vt)");
      if (corners[c].texcoord_index >= uvCount) source.fail(face, "texture coordinate index out of range");
    }
    // Fan from the first corner; each triangle is turned counter-clockwise in UV space, the
    // orientation that material-space rest shapes use.
    for (int j = 1; j + 1 < cornerCount; ++j) {
      std::array<tinyobj::index_t, 3> tri{corners[0], corners[j], corners[j + 1]};
      std::array<Vec2, 3> rest{restCoordinates(tri[0]), restCoordinates(tri[1]), restCoordinates(tri[2])};
      const double area = uvArea(rest[0], rest[1], rest[2]);
      if (std::abs(area) < kMinRestArea) {
        source.fail(face, "zero area in texture space (degenerate UVs); the triangle would have no rest shape");
      }
      if (area < 0.0) {
        std::swap(tri[1], tri[2]);
        std::swap(rest[1], rest[2]);
      }
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        t.v[k] = clothVertex(tri[k]);
        t.rest[k] = rest[k];
      }
      mesh.tris.push_back(t);
    }
  });
  if (mesh.tris.empty()) source.fail("", "has no faces");
  if (mesh.vertexCount() > limits::kMaxClothVertices) {
    source.fail("", std::to_string(mesh.vertexCount()) + " cloth vertices; a cloth has at most " +
                        std::to_string(limits::kMaxClothVertices));
  }
  const ObjVertexMap vertexMap = renumberInObjOrder(mesh, positionOf, positionCount);
  if (outVertexMap != nullptr) *outVertexMap = vertexMap;

  buildEdges(mesh);
  // Reject what the simulator cannot handle (edges shared by three faces, UV islands folded over
  // themselves, repeated faces) here, while the file can still be named.
  const std::vector<std::string> problems = checkMesh(mesh);
  if (!problems.empty()) {
    source.fail("", "not a valid cloth mesh: " + problems.front() + " (" + std::to_string(problems.size()) +
                        " problem(s) in all; triangle ids count fan triangles in face order)");
  }
  return mesh;
}

}  // namespace weft
