// Scratch: PCG on a dumped 64^2 system with Weft's preconditioners (setup and solve timed);
// with the argument `settings`, our multigrid's settings swept instead (docs/solver.md).
#include <cstring>
#include <chrono>
#include <cstdio>
#include <unsupported/Eigen/SparseExtra>
#include "integrate/amg_preconditioner.h"
#include "integrate/block_jacobi_preconditioner.h"
#include "integrate/lagged_cholesky_preconditioner.h"
#include "integrate/preconditioned_cg.h"
using namespace weft;
double now() { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
int main(int argc, char** argv) {
  SystemMatrix S;
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> A;
  Eigen::loadMarket(A, "/tmp/sys_A.mtx");
  Eigen::VectorXd b, x0;
  Eigen::loadMarketVector(b, "/tmp/sys_b.mtx");
  Eigen::loadMarketVector(x0, "/tmp/sys_x0.mtx");
  S.setPattern(A.rows() / 3, {}, {});  // bumps the pattern version
  S.matrix() = A;
  S.matrix().makeCompressed();
  if (argc > 1 && std::strcmp(argv[1], "settings") == 0) {
    for (int sweeps : {1, 2, 3})
      for (double theta : {0.0, 0.02, 0.08, 0.25})
        for (int coarsest : {48, 400}) {
          AmgPreconditioner::Settings st;
          st.smoothingSweeps = sweeps;
          st.hierarchy.strengthThreshold = theta;
          st.hierarchy.coarsestVertices = coarsest;
          double best = 1e9, setup = 0; int its = 0;
          for (int rep = 0; rep < 2; ++rep) {
            AmgPreconditioner P(st);
            PreconditionedConjugateGradient cg(1e-6, 5000);
            Eigen::VectorXd x = x0;
            P.prepare(S);  // full setup
            double t0 = now();
            P.prepare(S);  // numeric refresh only (same pattern): what a step pays
            double t1 = now();
            LinearSolveResult r = cg.solve(S, b, 0.0, P, x);
            double t2 = now();
            if (t2 - t1 < best) { best = t2 - t1; setup = t1 - t0; its = r.iterations; }
          }
          printf("sweeps %d theta %.2f coarsest %3d: refresh %6.2f ms solve %6.2f ms it %3d per it %.3f\n", sweeps, theta, coarsest,
                 setup, best, its, best / its);
        }
    return 0;
  }
  for (int which = 0; which < 3; ++which) {
    for (int rep = 0; rep < 3; ++rep) {
      std::unique_ptr<Preconditioner> P;
      const char* name = which == 0 ? "weft amg" : which == 1 ? "weft cholesky (fresh, strong couplings)" : "weft block jacobi";
      if (which == 0) P = std::make_unique<AmgPreconditioner>();
      else if (which == 1) P = std::make_unique<LaggedCholeskyPreconditioner>();
      else P = std::make_unique<BlockJacobiPreconditioner>();
      PreconditionedConjugateGradient cg(1e-6, 5000);
      Eigen::VectorXd x = x0;
      double t0 = now();
      P->prepare(S);
      double t1 = now();
      LinearSolveResult r = cg.solve(S, b, 0.0, *P, x);
      double t2 = now();
      Eigen::VectorXd res = b - A * x;
      printf("%-42s setup %7.2f ms solve %7.2f ms it %4d  |r|/|b| %.2e\n", name, t1 - t0, t2 - t1, r.iterations, res.norm() / b.norm());
    }
  }
}
