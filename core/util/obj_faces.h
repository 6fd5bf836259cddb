#pragma once
// Walking the faces of an OBJ read by tinyobjloader, in file order, with the checks it does not
// make. Shared by the cloth loader (mesh/obj_import) and the obstacle loader
// (rigid/closed_obj_import), which differ only in what they build from each face.
#include <cstddef>
#include <string>

#include <tiny_obj_loader.h>

namespace weft {

// For every face: fail(where, message) if it is malformed (fail must throw), else
// visit(where, corners, cornerCount), `where` being "face N" counting `f` lines from 1.
// Malformed: a corner count tinyobjloader misread (more than 255 corners), fewer than 3 corners,
// a position index outside [0, positionCount).
template <typename Fail, typename Visit>
void forEachObjFace(const tinyobj::ObjReader& reader, int positionCount, Fail&& fail, Visit&& visit) {
  int faceNumber = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    // tinyobjloader stores corner counts as bytes; a larger polygon would be misread.
    std::size_t cornerTotal = 0;
    for (const unsigned char cornerCount : shape.mesh.num_face_vertices) cornerTotal += cornerCount;
    if (cornerTotal != shape.mesh.indices.size()) fail(std::string(), std::string("a face has more than 255 corners"));

    std::size_t firstCorner = 0;
    for (const unsigned char cornerCount : shape.mesh.num_face_vertices) {
      const std::string where = "face " + std::to_string(++faceNumber);
      const tinyobj::index_t* corners = &shape.mesh.indices[firstCorner];
      firstCorner += cornerCount;
      if (cornerCount < 3) fail(where, std::string("has fewer than 3 corners"));
      for (int c = 0; c < cornerCount; ++c) {
        if (corners[c].vertex_index < 0 || corners[c].vertex_index >= positionCount) {
          fail(where, std::string("position index out of range"));
        }
      }
      visit(where, corners, static_cast<int>(cornerCount));
    }
  }
}

}  // namespace weft
