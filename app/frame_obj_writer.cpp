#include "frame_obj_writer.h"

#include <cstdio>
#include <utility>
#include <vector>

#include "frame_files.h"

namespace weft::app {

namespace {
template <typename... Args>
void appendLine(std::string& out, const char* format, Args... args) {
  char line[160];
  const int n = std::snprintf(line, sizeof line, format, args...);
  out.append(line, static_cast<std::size_t>(n));
}
}  // namespace

std::string clothToObj(const ClothMesh& mesh, const std::string& comment) {
  std::string out = "# " + comment + "\n";
  out.reserve(out.size() + static_cast<std::size_t>(mesh.vertexCount()) * 40 +
              static_cast<std::size_t>(mesh.triangleCount()) * 120);
  for (const Vec3& p : mesh.x) appendLine(out, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
  for (const Triangle& t : mesh.tris) {
    for (const Vec2& uv : t.rest) appendLine(out, "vt %.9g %.9g\n", uv.x(), uv.y());
  }
  int corner = 1;  // OBJ indices start at 1
  for (const Triangle& t : mesh.tris) {
    appendLine(out, "f %d/%d %d/%d %d/%d\n", t.v[0] + 1, corner, t.v[1] + 1, corner + 1, t.v[2] + 1, corner + 2);
    corner += 3;
  }
  // Torn and cut edges as line elements in their own groups, so a viewer can draw them in red
  // and green (thesis Figures 4.1-4.2).
  for (const auto& [group, wanted] : {std::pair{"torn", true}, std::pair{"cut", false}}) {
    bool opened = false;
    for (const Edge& e : mesh.edges) {
      if (!(wanted ? e.torn : e.cut)) continue;
      if (!opened) appendLine(out, "g %s\n", group);
      opened = true;
      appendLine(out, "l %d %d\n", e.v[0] + 1, e.v[1] + 1);
    }
  }
  return out;
}

std::filesystem::path frameObjPath(const std::filesystem::path& framesDir, int frame, const std::string& clothName,
                                   bool severalCloths) {
  char number[32];
  std::snprintf(number, sizeof number, "%04d", frame);
  std::string name = std::string("frame_") + number;
  if (severalCloths) name += "_" + clothName;
  return framesDir / (name + ".obj");
}

std::string obstacleToObj(const std::vector<Vec3>& worldVertices, const std::vector<std::array<int, 3>>& triangles,
                          const std::string& comment) {
  std::string out = "# " + comment + "\n";
  char line[128];
  for (const Vec3& p : worldVertices) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    out += line;
  }
  for (const auto& t : triangles) {
    std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += line;
  }
  return out;
}

std::filesystem::path obstacleObjPath(const std::filesystem::path& framesDir, int frame, const std::string& obstacleName) {
  char number[32];
  std::snprintf(number, sizeof number, "%04d", frame);
  return framesDir / ("obstacle_" + obstacleName + "_" + number + ".obj");
}

void removeOldFrames(const std::filesystem::path& framesDir) {
  removeFrameFiles(framesDir, ".obj", {"frame_", "obstacle_"});
}

}  // namespace weft::app
