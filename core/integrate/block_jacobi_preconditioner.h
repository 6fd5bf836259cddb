#pragma once
// M = the 3x3 diagonal blocks of A. Cloth couples the three coordinates of a vertex strongly
// (stretch along a deformed direction), so the block version beats the plain diagonal one. Cheap
// to build and to apply, but weak on stiff fabrics: CG then needs hundreds of iterations.
#include <vector>

#include "integrate/preconditioner.h"
#include "util/types.h"

namespace weft {

class BlockJacobiPreconditioner final : public Preconditioner {
 public:
  void prepare(const SystemMatrix& A) override;
  void apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) override;

 private:
  std::vector<Mat3> inverseBlocks_;
};

}  // namespace weft
