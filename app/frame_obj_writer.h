#pragma once
// `weft run --obj`: one OBJ file per cloth per frame, for viewing a run in any 3-D tool.
#include <filesystem>
#include <array>
#include <string>
#include <vector>

#include "mesh/cloth_mesh.h"

namespace weft::app {

// The mesh as OBJ text: `v` world positions, `vt` the rest (material-space) coordinates of every
// triangle corner in metres, `f` triangles. Per-corner UVs keep torn seams visible as seams.
std::string clothToObj(const ClothMesh& mesh, const std::string& comment);

// An obstacle's mesh at its current pose as OBJ text (`v` world positions, `f` triangles).
std::string obstacleToObj(const std::vector<Vec3>& worldVertices, const std::vector<std::array<int, 3>>& triangles,
                          const std::string& comment);

// frames/obstacle_<name>_0007.obj: obstacles are named apart from cloth frames.
std::filesystem::path obstacleObjPath(const std::filesystem::path& framesDir, int frame, const std::string& obstacleName);

// frames/frame_0007.obj for a single cloth, frames/frame_0007_<cloth>.obj when there are several.
std::filesystem::path frameObjPath(const std::filesystem::path& framesDir, int frame, const std::string& clothName,
                                   bool severalCloths);

// Removes frame_*.obj and obstacle_*.obj files left by an earlier run into the same folder, so that the folder
// never mixes frames of two runs.
void removeOldFrames(const std::filesystem::path& framesDir);

}  // namespace weft::app
