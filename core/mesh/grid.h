#pragma once
#include "mesh/cloth_mesh.h"
#include "scene/scene.h"

namespace weft {

// A rectangular sheet of resolutionX x resolutionY vertices over [0,width] x [0,height] in material
// space, lying in the world x-y plane (z = 0). Cells are split along alternating diagonals in a
// checkerboard ("union jack") so that the triangulation has no preferred diagonal direction.
// Vertex id = iy * resolutionX + ix. Throws InputError for a resolution below 2 or a size <= 0.
ClothMesh makeGrid(const GridSpec& spec);

}  // namespace weft
