#include "roofline.h"

#include <algorithm>
#include <chrono>

#include <Eigen/Core>

#include "integrate/preconditioned_cg.h"
#include "integrate/system_matrix.h"
#include "sim/cloth.h"

namespace weft::app {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double measureTriadBandwidth(long doubles, int repeats) {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(doubles), b = Eigen::VectorXd::Constant(doubles, 1.0),
                  c = Eigen::VectorXd::Constant(doubles, 2.0);
  const double scalar = 3.0;
  double best = 1e30;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    a.noalias() = b + scalar * c;
    best = std::min(best, secondsSince(start));
  }
  const double bytes = 3.0 * 8.0 * static_cast<double>(doubles);
  return bytes / best * 1e-9 + 0.0 * a[0];
}

ProductBandwidth measureProductBandwidth(const Scene& scene, const std::filesystem::path& sceneFile) {
  const Cloth cloth = buildCloth(scene.cloths.at(0), sceneFile.string(), 0);
  const CoupledVertexPairs pairs = coupledVertexPairs(cloth);
  SystemMatrix matrix;
  matrix.setPattern(cloth.mesh.vertexCount(), pairs.edges, pairs.hingeWings);
  const SystemMatrix::Sparse& A = matrix.matrix();
  Eigen::Map<Eigen::VectorXd>(matrix.matrix().valuePtr(), A.nonZeros()).setConstant(1e-3);
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(A.cols(), 1.0);
  Eigen::VectorXd y(A.rows());

  // The CG's own product (preconditioned_cg.h): A's columns read as 3x3 blocks, each value once
  // and one row index per block column's run of three rows (nnz / 9 of them).
  PreconditionedConjugateGradient cg(1e-6, 1);
  ProductBandwidth result;
  result.megabytes = 1e-6 * (8.0 * static_cast<double>(A.nonZeros()) + 4.0 * static_cast<double>(A.nonZeros()) / 9.0 +
                             4.0 * static_cast<double>(A.cols() + 1) + 16.0 * static_cast<double>(A.rows()));
  // Enough products for ~20 ms per repeat, best of five repeats (a shared machine's noise is one-sided).
  const auto probe = std::chrono::steady_clock::now();
  cg.multiply(matrix, x, y);
  const int products = std::clamp(static_cast<int>(0.02 / std::max(secondsSince(probe), 1e-7)), 1, 100000);
  double best = 1e30;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < products; ++k) cg.multiply(matrix, x, y);
    best = std::min(best, secondsSince(start) / products);
  }
  result.ms = 1e3 * best + 0.0 * y[0];
  return result;
}

}  // namespace weft::app
