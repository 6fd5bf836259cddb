#include "mesh/grid.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "util/input_error.h"

namespace weft {

namespace {

void requireResolution(int resolution, const char* axis) {
  if (resolution < 2) {
    throw InputError("", "grid.resolution",
                     std::string("needs at least 2 vertices along ") + axis + ", got " + std::to_string(resolution));
  }
}

void requireSize(double size, const char* field) {
  if (!std::isfinite(size) || size <= 0.0) {
    std::ostringstream got;
    got << size;
    throw InputError("", field, "must be a finite length > 0 m, got " + got.str());
  }
}

}  // namespace

ClothMesh makeGrid(const GridSpec& spec) {
  requireResolution(spec.resolutionX, "x");
  requireResolution(spec.resolutionY, "y");
  requireSize(spec.width, "grid.width");
  requireSize(spec.height, "grid.height");
  const int nx = spec.resolutionX;
  const int ny = spec.resolutionY;
  // Ids are ints: keep every triangle id (two per cell) representable.
  if (2LL * nx * ny > std::numeric_limits<int>::max()) {
    throw InputError("", "grid.resolution",
                     std::to_string(nx) + " x " + std::to_string(ny) + " vertices is more than a mesh can index");
  }

  // Computing each coordinate as size * i / (n - 1), rather than summing a step, puts the last row
  // and column exactly on width and height.
  auto materialX = [&](int ix) { return spec.width * ix / (nx - 1); };
  auto materialY = [&](int iy) { return spec.height * iy / (ny - 1); };

  ClothMesh mesh;
  const size_t vertexCount = static_cast<size_t>(nx) * ny;
  mesh.x.reserve(vertexCount);
  mesh.v.reserve(vertexCount);
  mesh.mass.reserve(vertexCount);
  mesh.pinned.reserve(vertexCount);
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) mesh.addVertex(Vec3(materialX(ix), materialY(iy), 0.0));
  }

  auto id = [nx](int ix, int iy) { return iy * nx + ix; };
  auto corner = [&](int ix, int iy) { return Vec2(materialX(ix), materialY(iy)); };
  auto addTriangle = [&](std::array<std::array<int, 2>, 3> cells) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = id(cells[k][0], cells[k][1]);
      t.rest[k] = corner(cells[k][0], cells[k][1]);
    }
    mesh.tris.push_back(t);
  };

  // Cell corners: a = (ix, iy), b = (ix+1, iy), c = (ix+1, iy+1), d = (ix, iy+1), counter-clockwise.
  // Even cells are cut along a-c, odd cells along b-d, so the diagonals alternate like a
  // checkerboard and a tear finds no preferred diagonal direction to run along.
  mesh.tris.reserve(2 * static_cast<size_t>(nx - 1) * (ny - 1));
  for (int iy = 0; iy + 1 < ny; ++iy) {
    for (int ix = 0; ix + 1 < nx; ++ix) {
      const std::array<int, 2> a{ix, iy}, b{ix + 1, iy}, c{ix + 1, iy + 1}, d{ix, iy + 1};
      if ((ix + iy) % 2 == 0) {
        addTriangle({a, b, c});
        addTriangle({a, c, d});
      } else {
        addTriangle({a, b, d});
        addTriangle({b, c, d});
      }
    }
  }

  buildEdges(mesh);
  return mesh;
}

}  // namespace weft
