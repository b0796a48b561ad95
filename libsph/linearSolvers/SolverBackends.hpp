// Constructors of the LinearSolver backends (internal to libsph/linearSolvers; the
// factory LinearSolver::create in LinearSolver.cpp reads the dictionary and calls these).
//   iterative: OpenMP BiCGSTAB (Krylov.hpp) with a Preconditioner, warm start,
//              direct SparseLU fallback when it fails (IterativeSolver.cpp)
//   direct:    KLU and UMFPACK through their C interfaces, reading the row-major
//              matrix as the column-major storage of A^T and solving with the
//              transposed system (no copy); the symbolic analysis is kept while
//              the sparsity pattern is unchanged; Eigen SparseLU (DirectSolvers.cpp)
#pragma once
#include "linearSolvers/LinearSolver.hpp"
#include "linearSolvers/Preconditioner.hpp"

namespace shizuku {

struct IterativeSettings {
  double tolerance = 1e-8;
  int maxIterations = 2000;
};

std::unique_ptr<LinearSolver> makeBiCGSTAB(const IterativeSettings& s, std::unique_ptr<Preconditioner> pc);
std::unique_ptr<LinearSolver> makeKLU(bool reuseSymbolic);
std::unique_ptr<LinearSolver> makeUMFPACK(bool reuseSymbolic);
std::unique_ptr<LinearSolver> makeSparseLU();

// Eigen's IncompleteLUT (dual threshold ILU) as a Preconditioner.
std::unique_ptr<Preconditioner> makeILUT(double dropTolerance, int fillFactor);

// hypre BoomerAMG (HypreAMG.cpp): available when built with libhypre-dev.
bool hypreAvailable();

// PETSc across ranks (PetscSolver.cpp).
struct PetscSettings {
  std::string krylov = "BiCGSTAB";        // or GMRES
  std::string preconditioner = "hypreAMG";  // hypreAMG (AMG), diagonal, ILU0
  double tolerance = 1e-8;
  int maxIterations = 2000;
  int reuse = 10;                          // solves a preconditioner is kept (amgReuse)
  std::string note;                        // appended to describe()
};
bool petscAvailable();
std::unique_ptr<LinearSolver> makePetscSolver(const PetscSettings& s);
std::unique_ptr<Preconditioner> makeHypreAMG(int reuse);

}  // namespace shizuku
