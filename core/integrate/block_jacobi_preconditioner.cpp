#include "integrate/block_jacobi_preconditioner.h"

#include <Eigen/LU>  // computeInverseAndDetWithCheck

namespace weft {

void BlockJacobiPreconditioner::prepare(const SystemMatrix& A) {
  const int n = A.vertexCount();
  inverseBlocks_.resize(n);
  const double* values = A.matrix().valuePtr();
  for (int i = 0; i < n; ++i) {
    Mat3 block;
    for (int c = 0; c < 3; ++c) {
      const int offset = A.blockOffset(i, i, c);
      for (int r = 0; r < 3; ++r) block(r, c) = values[offset + r];
    }
    bool invertible = false;
    double determinant = 0.0;
    block.computeInverseAndDetWithCheck(inverseBlocks_[i], determinant, invertible);
    if (!invertible) inverseBlocks_[i] = Mat3::Identity();  // cannot happen for an SPD A; stay finite
  }
}

void BlockJacobiPreconditioner::apply(const Eigen::VectorXd& inR, Eigen::VectorXd& outZ) {
  outZ.resize(inR.size());
  for (size_t i = 0; i < inverseBlocks_.size(); ++i)
    outZ.segment<3>(3 * i).noalias() = inverseBlocks_[i] * inR.segment<3>(3 * i);
}

}  // namespace weft
