#include "sim/finite_state.h"

#include "sim/world.h"

namespace weft {

bool stateIsFinite(const World& world) {
  for (int i = 0; i < world.clothCount(); ++i) {
    const ClothMesh& mesh = world.cloth(i);
    for (std::size_t k = 0; k < mesh.x.size(); ++k) {
      if (!mesh.x[k].allFinite() || !mesh.v[k].allFinite()) return false;
    }
  }
  return true;
}

}  // namespace weft
