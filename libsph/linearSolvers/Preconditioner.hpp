// Preconditioners for the pressure Poisson equation (docs/method.md 4.2, "BiCGSTAB
// with ILU(0) / ILUT preconditioning"), applied by the OpenMP BiCGSTAB of
// Krylov.hpp. setup() is called once per time step with that step's matrix and
// keeps its buffers between steps (no allocation once they have their capacity):
//   diagonal  z = r / diag(A)
//   ILU0      incomplete LU with the pattern of A itself, block-Jacobi over T
//             contiguous row blocks (T = threads at setup): each thread factors
//             and solves its own diagonal block, couplings between blocks are
//             dropped. Particles (hence unknowns) are ordered by cell, so a
//             block is a compact piece of the domain and the dropped couplings
//             are few; with one thread it is the plain ILU(0).
// (AMG: HypreAMG.cpp; ILUT: Eigen's IncompleteLUT, IterativeSolver.cpp.)
// Dictionary keys (read by LinearSolver::create): preconditioner ILU0|ILUT|diagonal|AMG;
// blocks (ILU0: number of row blocks, default = threads).
#pragma once
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

using SparseMatrixR = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual std::string describe() const = 0;
  // Build from A (compressed, row-major, sorted columns, diagonal present). false: failed.
  virtual bool setup(const SparseMatrixR& A) = 0;
  // After a failed setup(): what failed, for the log.
  virtual std::string setupFailure() const { return "preconditioner setup failed"; }
  // z = M^{-1} r over all rows (called from outside a parallel region; parallel inside).
  virtual void apply(const double* r, double* z) const = 0;
  // Preconditioners kept across steps (AMG) hold state built from an earlier step's
  // matrix, which a restart cannot rebuild. nextSetupRebuilds(): the next setup()
  // builds afresh from its own matrix (a run stopped here restarts bit for bit);
  // rebuildAtNextSetup(): make it do so (the rows were renumbered, or a time directory
  // was written). solved(): the iteration count of the solve that just used it.
  virtual bool nextSetupRebuilds() const { return true; }
  virtual void rebuildAtNextSetup() {}
  virtual void solved(int iterations) {}
  // The next setup() gets the last matrix with a few rows changed, within the same step:
  // a preconditioner kept across steps keeps what it built and counts neither the setup nor
  // the solve towards its rebuild.
  virtual void nextSetupCorrects() {}
};

// inv[i] = 1 / A_ii (whenZero where A_ii = 0); false when a diagonal entry is zero or not finite.
bool invertDiagonal(const SparseMatrixR& A, double* inv, double whenZero);

class DiagonalPreconditioner final : public Preconditioner {
 public:
  std::string describe() const override { return "diagonal"; }
  bool setup(const SparseMatrixR& A) override;
  std::string setupFailure() const override { return "diagonal preconditioner: a zero or non-finite diagonal"; }
  void apply(const double* r, double* z) const override;

 private:
  std::vector<double> invDiag_;
};

class BlockILU0 final : public Preconditioner {
 public:
  // blocks <= 0: one block per OpenMP thread at setup time.
  explicit BlockILU0(int blocks = 0) : requestedBlocks_(blocks) {}
  std::string describe() const override;
  bool setup(const SparseMatrixR& A) override;
  std::string setupFailure() const override { return "ILU0 setup failed: a row without a diagonal entry"; }
  void apply(const double* r, double* z) const override;
  int blocks() const { return int(blockStart_.size()) - 1; }
  // Pivots that were zero or tiny and were replaced (last setup).
  long replacedPivots() const { return replacedPivots_; }

 private:
  int requestedBlocks_;
  int n_ = 0;
  const int* outer_ = nullptr;
  const int* col_ = nullptr;
  std::vector<double> lu_;          // factors in the pattern of A (L unit lower, U upper)
  std::vector<int> diag_;           // position of the diagonal in each row
  std::vector<int> lo_, hi_;        // per row: first and one-past-last position inside its block
  std::vector<double> invPivot_;    // 1 / U_ii
  std::vector<int> marker_;         // column -> position in the row being factored (-1: none)
  std::vector<int> blockStart_;
  long replacedPivots_ = 0;
};

}  // namespace shizuku
