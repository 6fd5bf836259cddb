#include "rigid/closed_obj_import.h"

// Linked against tinyobjloader::tinyobjloader_double (core/CMakeLists.txt), so tinyobj::real_t is
// double; nothing here depends on which.
#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "rigid/closed_surface_check.h"
#include "rigid/mass_properties.h"
#include "util/input_error.h"
#include "util/json_fields.h"
#include "util/obj_faces.h"
#include "util/obj_text.h"

namespace weft {

namespace {

std::string readText(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path.string(), "", "mesh file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open mesh file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every coordinate within ±kMaxToolCoordinate and the mesh at least kMinToolExtent across (in
// the file's units), so its areas, volume and inertia are finite and not flushed to zero.
void requireToolSize(const TriangleMesh& mesh, const std::string& file) {
  if (mesh.vertices.empty()) return;  // "has no faces" says more
  Vec3 low = mesh.vertices.front(), high = low;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& p = mesh.vertices[v];
    if (p.cwiseAbs().maxCoeff() > kMaxToolCoordinate) {
      throw InputError(file, "", "`v` line " + std::to_string(v) + " has a coordinate of " +
                                     formatNumber(p.cwiseAbs().maxCoeff()) + "; at most " +
                                     formatNumber(kMaxToolCoordinate) + " in magnitude (set the scene's scale instead)");
    }
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = (high - low).maxCoeff();
  if (extent < kMinToolExtent) {
    throw InputError(file, "", "spans " + formatNumber(extent) + " along its longest axis; at least " +
                                   formatNumber(kMinToolExtent) + " (set the scene's scale instead)");
  }
}

}  // namespace

TriangleMesh loadClosedObj(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = readText(path);
  if (const auto problem = findBadCoordinate(text, {"v"})) {
    throw InputError(file, "line " + std::to_string(problem->line), problem->message);
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // fanned below, so face numbers in messages match the file's `f` lines
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) throw InputError(file, "", "cannot parse OBJ: " + tinyobjMessage(reader.Error()));
  // tinyobjloader only warns about faces it drops or indices it cannot resolve.
  const std::string& warning = reader.Warning();
  if (warning.find("Degenerated face") != std::string::npos)
    throw InputError(file, "", "a face has fewer than 3 corners");
  if (warning.find("out of bounds") != std::string::npos)
    throw InputError(file, "", "an index is out of range: " + tinyobjMessage(warning, "out of bounds"));

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  TriangleMesh mesh;
  // attrib.vertices holds the `v` lines in file order: vertex i of the mesh is `v` line i.
  for (size_t p = 0; p + 2 < attrib.vertices.size(); p += 3) {
    const Vec3 position(static_cast<double>(attrib.vertices[p]), static_cast<double>(attrib.vertices[p + 1]),
                        static_cast<double>(attrib.vertices[p + 2]));
    if (!position.allFinite()) throw InputError(file, "", "a coordinate is too large to represent");
    mesh.vertices.push_back(position);
  }
  const int vertexCount = static_cast<int>(mesh.vertices.size());
  requireToolSize(mesh, file);

  forEachObjFace(
      reader, vertexCount,
      [&](const std::string& where, const std::string& message) { throw InputError(file, where, message); },
      [&](const std::string&, const tinyobj::index_t* corners, int cornerCount) {
        for (int j = 1; j + 1 < cornerCount; ++j) {
          mesh.triangles.push_back({corners[0].vertex_index, corners[j].vertex_index, corners[j + 1].vertex_index});
        }
      });
  if (mesh.triangles.empty()) throw InputError(file, "", "has no faces");

  const std::vector<std::string> problems = closedSurfaceProblems(mesh);
  if (!problems.empty()) {
    throw InputError(file, "",
                     "not the closed surface of a solid: " + problems.front() + " (" + std::to_string(problems.size()) +
                         " problem(s) in all; vertex ids count `v` lines from 0, triangle ids count fan "
                         "triangles in face order)");
  }
  const double volume = signedVolume(mesh);
  if (!(volume > 0.0)) {
    std::ostringstream what;
    what << "encloses a volume of " << volume
         << " m^3: its faces are turned inward (clockwise seen from outside); reverse every face's vertex order";
    throw InputError(file, "", what.str());
  }
  return mesh;
}

}  // namespace weft
