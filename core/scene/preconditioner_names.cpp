#include "scene/preconditioner_names.h"

namespace weft {

const char* preconditionerName(PreconditionerKind kind) {
  switch (kind) {
    case PreconditionerKind::Amg: return "amg";
    case PreconditionerKind::LaggedCholesky: return "lagged_cholesky";
    case PreconditionerKind::LaggedExactCholesky: return "lagged_exact_cholesky";
    case PreconditionerKind::BlockJacobi: return "block_jacobi";
  }
  return "unknown";
}

}  // namespace weft
