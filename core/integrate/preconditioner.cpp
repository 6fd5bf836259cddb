#include "integrate/preconditioner.h"

namespace weft {

// Out of line, in the core's own translation unit: the pragma needs the core's OpenMP flags (a
// file built without them would compile it as apply on every thread at once).
void Preconditioner::applyInTeam(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) {
#pragma omp single
  apply(inR, outZ);
}

}  // namespace weft
