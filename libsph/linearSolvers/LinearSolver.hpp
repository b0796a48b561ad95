// The pressure solver's interface: LinearSolver (solve A x = b) and its factory
// LinearSolver::create, which reads the `pressure` sub-dictionary of system/sphSolution
// (docs/design.md part 2, docs/method.md 4.2):
//   pressure { solver BiCGSTAB|UMFPACK|KLU|SparseLU|PETSc; krylov BiCGSTAB|GMRES (PETSc); tolerance 1e-8; maxIterations 2000;
//              preconditioner AMG|ILU0|ILUT|diagonal|hypreAMG; amgReuse 10; blocks 0;
//              dropTolerance 1e-4; fillFactor 10; reuseSymbolic yes; }
// This library (libsph/linearSolvers) owns that interface and every backend behind
// it; it depends on core only and sees the system as plain compressed rows, never
// particles or operators (libsph/pressure assembles the rows and calls solve()).
// A new backend (a 3D AMG, PETSc or hypre across MPI ranks) is added here, behind
// this interface, and built by create(); the pressure equation does not change.
// Contract of every backend:
//   - deterministic: the same matrix, right-hand side, initial guess x and reuse
//     state (a kept preconditioner or symbolic analysis, and startAfreshAtNextSolve()
//     calls) give the same x bit for bit on the same number of threads (or ranks):
//     sums in a fixed order, no dependence on timing (no dynamic schedules or
//     atomics in reductions). A restart from a time directory then continues
//     exactly as the uninterrupted run (faults.restartBitwise, docs/output.md);
//   - BiCGSTAB is warm-started from the x it is given (the last pressure);
//   - buffers are kept between calls (see the .cpp files for what each external
//     library still allocates inside).
#pragma once
#include "core/Dictionary.hpp"
#include <Eigen/Sparse>
#include <functional>
#include <memory>
#include <string>

namespace shizuku {

using SparseMatrixR = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

struct LinearSolveResult {
  bool ok = false;
  int iterations = 0;
  double residual = 0;  // ||A x - b|| / ||b|| (0 when b = 0)
  std::string message;
  bool usedFallback = false;  // an iterative solve failed and a direct LU solved instead
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  virtual std::string describe() const = 0;
  // Solve A x = b; x holds the initial guess on entry (iterative solvers). When the result
  // is not ok, x is unspecified (the last iterate of an iterative solver).
  virtual LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  // A solver across ranks: A holds this rank's rows (rows numbered rank by rank) with
  // global column numbers, b and x this rank's entries (PETSc). The others need the
  // whole matrix on one rank.
  virtual bool distributed() const { return false; }
  // State kept from earlier matrices (a lagged AMG hierarchy) cannot be rebuilt by a
  // restart. nextSolveStartsAfresh(): the next solve uses none of it, so a run stopped
  // before it restarts bit for bit; startAfreshAtNextSolve(): make the next solve
  // rebuild it (the unknowns were renumbered, or a time directory was written).
  virtual bool nextSolveStartsAfresh() const { return true; }
  virtual void startAfreshAtNextSolve() {}
  // The next solve's matrix is the last one with a few rows changed, in the same step (the
  // wall rows of eq. 11b decided again): state kept across steps is reused, not aged.
  virtual void nextSolveCorrectsTheLast() {}
  // Build from the `pressure` sub-dictionary of system/sphSolution (nullptr: defaults).
  static std::unique_ptr<LinearSolver> create(const Dictionary* dict);
  static std::vector<std::string> names();
  static std::vector<std::string> preconditionerNames();
  // Benchmarks and tests only: when set, create() returns hook(dict) instead (e.g. a
  // solver that records the systems it is given). An empty function restores the factory.
  using CreateHook = std::function<std::unique_ptr<LinearSolver>(const Dictionary*)>;
  static void setCreateHook(CreateHook hook);
  // The backends themselves (what create() returns without a hook).
  static std::unique_ptr<LinearSolver> createBuiltin(const Dictionary* dict);
};

double relativeResidual(const SparseMatrixR& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x);

}  // namespace shizuku
