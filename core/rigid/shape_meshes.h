#pragma once
// Procedural obstacle shapes: closed triangle meshes in their body frame, centred at the origin,
// counter-clockwise seen from outside. Each shape is made from a definition struct (dimensions in
// metres, resolutions in counts). Curved shapes put their vertices on the true surface, so the mesh
// lies inside it and its volume is slightly smaller (shape_meshes_test reports by how much).
#include "rigid/triangle_mesh.h"

namespace weft {

// An icosphere: the icosahedron with every triangle split into four `subdivisions` times, new
// vertices pushed out to the sphere. 20 * 4^s nearly equal triangles, 10 * 4^s + 2 vertices.
struct SphereShape {
  double radius = 0.1;   // m
  int subdivisions = 2;  // 0: icosahedron; 2: 320 triangles; 3: 1280 triangles
};

// An axis-aligned box. Each face is split into a grid of cells no larger than `maxCellSize`, so a
// large flat face can still meet a cloth at many vertices.
struct BoxShape {
  Vec3 halfExtents{0.1, 0.1, 0.1};  // m, along body x, y, z
  double maxCellSize = 0.0;         // m; 0 leaves each face as one cell (two triangles)
};

// A cylinder along body y with two hemispherical ends.
struct CapsuleShape {
  double radius = 0.05;     // m
  double halfLength = 0.1;  // m, half the length of the cylindrical part (0: a sphere)
  int segments = 16;        // vertices around y; each hemisphere gets segments / 4 rings of latitude
};

// A cylinder along body y with flat caps (columns, posts).
struct CylinderShape {
  double radius = 0.1;      // m
  double halfHeight = 1.0;  // m
  int segments = 32;        // vertices around y
  int heightSegments = 1;   // bands along y; more keep long sides from being one sliver per segment
};

TriangleMesh makeSphereMesh(const SphereShape& shape);
TriangleMesh makeBoxMesh(const BoxShape& shape);
TriangleMesh makeCapsuleMesh(const CapsuleShape& shape);
TriangleMesh makeCylinderMesh(const CylinderShape& shape);

}  // namespace weft
