#pragma once
// A contact body (contact/contact_body.h) over a mesh's topology and position arrays that the
// test owns, with its swept mesh pointing at the same arrays, as ContactStage::refreshBodies
// makes them.
#include <vector>

#include "contact/contact_body.h"

namespace weft::test {

inline ContactBody contactBody(const CollisionMesh& mesh, const std::vector<Vec3>& x0, std::vector<Vec3>& x1,
                               std::vector<Vec3>* v = nullptr) {
  ContactBody body;
  body.topology = &mesh;
  body.x0 = &x0;
  body.x1 = &x1;
  body.v = v;
  body.swept.mesh = &mesh;
  body.swept.x0 = &x0;
  body.swept.x1 = &x1;
  return body;
}

}  // namespace weft::test
