// The linear-solver backends: Eigen BiCGSTAB (ILUT or diagonal preconditioner),
// SuiteSparse UMFPACK and KLU, Eigen SparseLU.
#include "pressure/LinearSolver.hpp"
#include "core/Log.hpp"
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>

namespace shizuku {

double relativeResidual(const SparseMatrixR& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  const double nb = b.norm();
  const double nr = (A * x - b).norm();
  return nb > 0 ? nr / nb : nr;
}

namespace {

class BiCGSTABSolver final : public LinearSolver {
 public:
  BiCGSTABSolver(double tol, int maxIt, bool ilut, double dropTol, int fill)
      : tol_(tol), maxIt_(maxIt), ilut_(ilut), dropTol_(dropTol), fill_(fill) {}
  std::string name() const override { return "BiCGSTAB"; }
  std::string describe() const override {
    return cat("BiCGSTAB, preconditioner ", ilut_ ? cat("ILUT(drop ", dropTol_, ", fill ", fill_, ")") : "diagonal",
               ", tolerance ", tol_, ", maxIterations ", maxIt_, ", warm start");
  }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    LinearSolveResult r;
    if (b.norm() == 0) { x.setZero(); r.ok = true; return r; }
    const Eigen::VectorXd guess = x;
    if (ilut_) r = run(ilutSolver_, A, b, x); else r = run(diagSolver_, A, b, x);
    if (!r.ok) {
      // BiCGSTAB can stagnate or break down; fall back to a direct LU for this
      // solve rather than stop the run, and say so.
      const LinearSolveResult failed = r;
      colMajor_ = A;
      colMajor_.makeCompressed();
      lu_.compute(colMajor_);
      if (lu_.info() == Eigen::Success) {
        x = lu_.solve(b);
        r.residual = relativeResidual(A, b, x);
        r.ok = std::isfinite(r.residual) && r.residual < 1e-6;
        r.message = cat(failed.message, "; solved by the direct fallback (SparseLU), residual ", r.residual);
        r.usedFallback = true;
      }
      if (!r.ok) x = guess;
    }
    return r;
  }

 private:
  template <class S>
  LinearSolveResult run(S& s, const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    LinearSolveResult r;
    s.setTolerance(tol_);
    s.setMaxIterations(maxIt_);
    s.compute(A);
    if (s.info() != Eigen::Success) { r.message = "preconditioner setup failed"; return r; }
    Eigen::VectorXd x0 = x;
    x = s.solveWithGuess(b, x0);
    r.iterations = int(s.iterations());
    r.residual = relativeResidual(A, b, x);
    // Converged when the true residual meets the tolerance, or sits at the
    // round-off floor of these matrices (~1e-11) when a tighter one was asked for.
    r.ok = std::isfinite(r.residual) && r.residual <= std::max(10 * tol_, 1e-10);
    if (!r.ok) r.message = cat("BiCGSTAB did not converge: ", r.iterations, " iterations, residual ", r.residual);
    return r;
  }
  double tol_;
  int maxIt_;
  bool ilut_;
  double dropTol_;
  int fill_;
  Eigen::BiCGSTAB<SparseMatrixR, Eigen::IncompleteLUT<double>> ilutSolver_;
  Eigen::BiCGSTAB<SparseMatrixR, Eigen::DiagonalPreconditioner<double>> diagSolver_;
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> colMajor_;
  Eigen::SparseLU<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::COLAMDOrdering<int>> lu_;

 public:
  void setup() { ilutSolver_.preconditioner().setDroptol(dropTol_); ilutSolver_.preconditioner().setFillfactor(fill_); }
};

// Direct solvers work on a column-major copy.
template <class Direct>
class DirectSolver final : public LinearSolver {
 public:
  explicit DirectSolver(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  std::string describe() const override { return name_ + " (direct sparse LU)"; }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    LinearSolveResult r;
    colMajor_ = A;
    colMajor_.makeCompressed();
    solver_.compute(colMajor_);
    if (solver_.info() != Eigen::Success) { r.message = name_ + " factorisation failed (singular matrix?)"; return r; }
    x = solver_.solve(b);
    r.iterations = 1;
    r.residual = relativeResidual(A, b, x);
    r.ok = solver_.info() == Eigen::Success && std::isfinite(r.residual) && r.residual < 1e-6;
    if (!r.ok) r.message = cat(name_, " solve failed, residual ", r.residual);
    return r;
  }

 private:
  std::string name_;
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> colMajor_;
  Direct solver_;
};

}  // namespace

std::vector<std::string> LinearSolver::names() { return {"BiCGSTAB", "UMFPACK", "KLU", "SparseLU"}; }

std::unique_ptr<LinearSolver> LinearSolver::create(const Dictionary* d) {
  const std::string type = d ? d->getOptionOr("solver", names(), "BiCGSTAB") : "BiCGSTAB";
  using CM = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  if (d && type != "BiCGSTAB")  // iterative settings do not apply to direct solvers
    for (const char* k : {"tolerance", "maxIterations", "preconditioner", "dropTolerance", "fillFactor"})
      d->markRead(k);
  if (type == "UMFPACK") return std::make_unique<DirectSolver<Eigen::UmfPackLU<CM>>>("UMFPACK");
  if (type == "KLU") return std::make_unique<DirectSolver<Eigen::KLU<CM>>>("KLU");
  if (type == "SparseLU")
    return std::make_unique<DirectSolver<Eigen::SparseLU<CM, Eigen::COLAMDOrdering<int>>>>("SparseLU");
  const double tol = d ? d->getScalarOr("tolerance", 1e-8, dim::none) : 1e-8;
  const int maxIt = d ? d->getIntOr("maxIterations", 2000) : 2000;
  const std::string pc = d ? d->getOptionOr("preconditioner", {"ILUT", "diagonal"}, "ILUT") : "ILUT";
  const double drop = d ? d->getScalarOr("dropTolerance", 1e-4, dim::none) : 1e-4;
  const int fill = d ? d->getIntOr("fillFactor", 10) : 10;
  if (d && tol <= 0) d->error("tolerance", "must be > 0");
  if (d && maxIt <= 0) d->error("maxIterations", "must be > 0");
  auto s = std::make_unique<BiCGSTABSolver>(tol, maxIt, pc == "ILUT", drop, fill);
  s->setup();
  return s;
}

}  // namespace shizuku
