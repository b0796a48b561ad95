// Sparse linear solvers for the pressure Poisson equation behind one
// interface (design.md part 2), chosen in system/sphSolution:
//   pressure { solver BiCGSTAB|UMFPACK|KLU|SparseLU; tolerance 1e-8; maxIterations 2000;
//              preconditioner ILUT|diagonal; dropTolerance 1e-4; fillFactor 10; }
// BiCGSTAB is warm-started from the x it is given (the last pressure).
#pragma once
#include "core/Dictionary.hpp"
#include <Eigen/Sparse>
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
  // Solve A x = b; x holds the initial guess on entry (iterative solvers).
  virtual LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  // Build from the `pressure` sub-dictionary of system/sphSolution (nullptr: defaults).
  static std::unique_ptr<LinearSolver> create(const Dictionary* dict);
  static std::vector<std::string> names();
};

double relativeResidual(const SparseMatrixR& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x);

}  // namespace shizuku
