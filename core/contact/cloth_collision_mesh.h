#pragma once
// A cloth's collision topology (collision_mesh.h), mirroring its ClothMesh id for id: triangle t
// and edge e of the collision mesh are triangle t and edge e of the cloth. So after a tear the
// TopologyChange names exactly what to edit, and an edited mesh equals one built afresh from the
// torn cloth.
#include "collision/collision_mesh.h"
#include "mesh/cloth_mesh.h"
#include "mesh/topology_change.h"

namespace weft {

// From scratch (first use, or a change the contact stage was not told about).
CollisionMesh makeClothCollisionMesh(const ClothMesh& mesh);

// Brings `topology`, built for the cloth before `change`, in step with `mesh` after it: edits the
// changed and new triangles and edges only (and the triangles whose edge ids changed).
CollisionMeshChange updateClothCollisionMesh(CollisionMesh& topology, const ClothMesh& mesh,
                                             const TopologyChange& change);

}  // namespace weft
