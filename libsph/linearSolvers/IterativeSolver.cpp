// The BiCGSTAB backend (docs/method.md 4.2): warm-started OpenMP BiCGSTAB (Krylov.cpp)
// with a configurable preconditioner; converged when the true relative residual
// meets the tolerance (or the ~1e-10 round-off floor of these matrices when a
// tighter one was asked for). When the recursive residual converged but the true
// one did not, it restarts from the current x (at most twice); when it still
// fails, one direct SparseLU solve rescues the step and says so. A solve that still
// fails leaves its last iterate in x (the caller stops the run and restores its last
// good state).
// Keys: tolerance, maxIterations, preconditioner, blocks, dropTolerance, fillFactor.
#include "core/Log.hpp"
#include "linearSolvers/Krylov.hpp"
#include "linearSolvers/SolverBackends.hpp"
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>
#include <cmath>

namespace shizuku {

namespace {

class EigenILUT final : public Preconditioner {
 public:
  EigenILUT(double drop, int fill) : drop_(drop), fill_(fill) {
    ilut_.setDroptol(drop);
    ilut_.setFillfactor(fill);
  }
  std::string describe() const override { return cat("ILUT (Eigen, drop ", drop_, ", fill ", fill_, ")"); }
  bool setup(const SparseMatrixR& A) override {
    n_ = int(A.rows());
    ilut_.compute(A);
    return ilut_.info() == Eigen::Success;
  }
  std::string setupFailure() const override { return "ILUT setup failed (Eigen IncompleteLUT)"; }
  void apply(const double* r, double* z) const override {
    Eigen::Map<const Eigen::VectorXd> rm(r, n_);
    Eigen::Map<Eigen::VectorXd> zm(z, n_);
    zm = ilut_.solve(rm);
  }

 private:
  double drop_;
  int fill_;
  int n_ = 0;
  Eigen::IncompleteLUT<double> ilut_;
};

class BiCGSTABSolver final : public LinearSolver {
 public:
  BiCGSTABSolver(const IterativeSettings& s, std::unique_ptr<Preconditioner> pc) : set_(s), pc_(std::move(pc)) {}
  std::string name() const override { return "BiCGSTAB"; }
  std::string describe() const override {
    return cat("BiCGSTAB (OpenMP), preconditioner ", pc_->describe(), ", tolerance ", set_.tolerance,
               ", maxIterations ", set_.maxIterations, ", warm start");
  }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    LinearSolveResult r;
    if (!pc_->setup(A)) {
      r.message = pc_->setupFailure();
    } else {
      int budget = set_.maxIterations;
      for (int attempt = 0; attempt < 3 && budget > 0; ++attempt) {
        const KrylovResult k = bicgstab(A, b.data(), x.data(), *pc_, set_.tolerance, budget, work_);
        r.iterations += k.iterations;
        budget -= std::max(k.iterations, 1);
        r.residual = relativeResidual(A, b.data(), x.data());
        r.ok = std::isfinite(r.residual) && r.residual <= std::max(10 * set_.tolerance, 1e-10);
        if (r.ok || !k.converged) break;  // only a drifted recursive residual is worth a restart
      }
      if (!r.ok)
        r.message = cat("BiCGSTAB did not converge: ", r.iterations, " iterations, residual ", r.residual);
    }
    pc_->solved(r.iterations);
    if (!r.ok) fallback(A, b, x, r);
    return r;
  }
  bool nextSolveStartsAfresh() const override { return pc_->nextSetupRebuilds(); }
  void startAfreshAtNextSolve() override { pc_->rebuildAtNextSetup(); }
  void nextSolveCorrectsTheLast() override { pc_->nextSetupCorrects(); }

 private:
  // BiCGSTAB can stagnate or break down; a direct LU solves this step rather
  // than stopping the run, and the result says so.
  void fallback(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x, LinearSolveResult& r) {
    const std::string failed = r.message;
    colMajor_ = A;
    colMajor_.makeCompressed();
    lu_.compute(colMajor_);
    if (lu_.info() == Eigen::Success) {
      x = lu_.solve(b);
      r.residual = relativeResidual(A, b.data(), x.data());
      r.ok = std::isfinite(r.residual) && r.residual < 1e-6;
      r.message = cat(failed, "; solved by the direct fallback (SparseLU), residual ", r.residual);
      r.usedFallback = true;
    }
  }

  IterativeSettings set_;
  std::unique_ptr<Preconditioner> pc_;
  KrylovWorkspace work_;
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> colMajor_;
  Eigen::SparseLU<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace

std::unique_ptr<Preconditioner> makeILUT(double dropTolerance, int fillFactor) {
  return std::make_unique<EigenILUT>(dropTolerance, fillFactor);
}

std::unique_ptr<LinearSolver> makeBiCGSTAB(const IterativeSettings& s, std::unique_ptr<Preconditioner> pc) {
  return std::make_unique<BiCGSTABSolver>(s, std::move(pc));
}

}  // namespace shizuku
