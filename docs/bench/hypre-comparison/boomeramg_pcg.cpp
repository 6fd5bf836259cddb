// Scratch: hypre BoomerAMG as the PCG preconditioner on the same dumped system (serial, 1 MPI rank).
#include <chrono>
#include <cstdio>
#include <vector>
#include <cstdlib>
#include <mpi.h>
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>
#include <HYPRE_krylov.h>
#include <unsupported/Eigen/SparseExtra>
double now() { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  HYPRE_Init();
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> A;
  Eigen::loadMarket(A, "/tmp/sys_A.mtx");
  A.makeCompressed();
  Eigen::VectorXd b, x0;
  Eigen::loadMarketVector(b, "/tmp/sys_b.mtx");
  Eigen::loadMarketVector(x0, "/tmp/sys_x0.mtx");
  const int n = A.rows();
  struct Config { const char* name; int nodal; int coarsen; int aggLevels; double strong; int interp; int relax; };
  Config configs[] = {
    {"boomeramg default (HMIS, ext+i, l1-GS), systems 3", 0, 10, 0, 0.25, 6, 8},
    {"boomeramg nodal 4 (block norms), systems 3", 4, 10, 0, 0.25, 6, 8},
    {"boomeramg nodal 1 (Frobenius), strong 0.5", 1, 10, 0, 0.5, 6, 8},
    {"boomeramg aggressive 1 level, strong 0.5", 0, 10, 1, 0.5, 6, 8},
    {"boomeramg PMIS, strong 0.5, hybrid sym GS", 0, 8, 0, 0.5, 6, 6},
  };
  for (const Config& c : configs) {
    for (int rep = 0; rep < 2; ++rep) {
      HYPRE_IJMatrix ij; HYPRE_ParCSRMatrix par;
      HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &ij);
      HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR);
      HYPRE_IJMatrixInitialize(ij);
      std::vector<int> rows(n), ncols(n);
      for (int i = 0; i < n; ++i) { rows[i] = i; ncols[i] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i]; }
      HYPRE_IJMatrixSetValues(ij, n, ncols.data(), rows.data(), A.innerIndexPtr(), A.valuePtr());
      HYPRE_IJMatrixAssemble(ij);
      HYPRE_IJMatrixGetObject(ij, (void**)&par);
      HYPRE_IJVector bv, xv; HYPRE_ParVector bp, xp;
      for (HYPRE_IJVector* v : {&bv, &xv}) {
        HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v);
        HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
        HYPRE_IJVectorInitialize(*v);
      }
      HYPRE_IJVectorSetValues(bv, n, rows.data(), b.data());
      HYPRE_IJVectorSetValues(xv, n, rows.data(), x0.data());
      HYPRE_IJVectorAssemble(bv); HYPRE_IJVectorAssemble(xv);
      HYPRE_IJVectorGetObject(bv, (void**)&bp); HYPRE_IJVectorGetObject(xv, (void**)&xp);
      HYPRE_Solver pcg, amg;
      HYPRE_ParCSRPCGCreate(MPI_COMM_WORLD, &pcg);
      HYPRE_PCGSetTol(pcg, 1e-6); HYPRE_PCGSetMaxIter(pcg, 2000); HYPRE_PCGSetTwoNorm(pcg, 1);
      HYPRE_BoomerAMGCreate(&amg);
      HYPRE_BoomerAMGSetNumFunctions(amg, 3);
      if (c.nodal) HYPRE_BoomerAMGSetNodal(amg, c.nodal);
      HYPRE_BoomerAMGSetCoarsenType(amg, c.coarsen);
      HYPRE_BoomerAMGSetAggNumLevels(amg, c.aggLevels);
      HYPRE_BoomerAMGSetStrongThreshold(amg, c.strong);
      HYPRE_BoomerAMGSetInterpType(amg, c.interp);
      HYPRE_BoomerAMGSetRelaxType(amg, c.relax);
      HYPRE_BoomerAMGSetMaxIter(amg, 1); HYPRE_BoomerAMGSetTol(amg, 0.0);
      HYPRE_BoomerAMGSetPrintLevel(amg, getenv("PL") ? 1 : 0);
      HYPRE_PCGSetPrecond(pcg, (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSolve, (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSetup, amg);
      double t0 = now();
      HYPRE_ParCSRPCGSetup(pcg, par, bp, xp);
      double t1 = now();
      HYPRE_ParCSRPCGSolve(pcg, par, bp, xp);
      double t2 = now();
      int it = 0; double rel = 0;
      HYPRE_PCGGetNumIterations(pcg, &it);
      HYPRE_PCGGetFinalRelativeResidualNorm(pcg, &rel);
      Eigen::VectorXd x(n);
      HYPRE_IJVectorGetValues(xv, n, rows.data(), x.data());
      Eigen::SparseMatrix<double> Ac = A;
      double res = (b - Ac * x).norm() / b.norm();
      printf("%-52s setup %7.2f ms solve %7.2f ms it %4d |r|/|b| %.2e\n", c.name, t1 - t0, t2 - t1, it, res);
      HYPRE_BoomerAMGDestroy(amg); HYPRE_ParCSRPCGDestroy(pcg);
      HYPRE_IJMatrixDestroy(ij); HYPRE_IJVectorDestroy(bv); HYPRE_IJVectorDestroy(xv);
    }
  }
  HYPRE_Finalize();
  MPI_Finalize();
}
