// Direct sparse LU backends for the PPE (docs/method.md 4.2: "a direct SparseLU or
// UMFPACK is also cheap and the most robust" at 2D test sizes).
// KLU (KLUFactor.hpp) and UMFPACK are called through their C interfaces: the row-major
// (CSR) matrix A is, read as compressed columns, the matrix A^T, which they factor;
// the transposed solve (klu_tsolve, UMFPACK_At) then gives A x = b with no copy.
// The symbolic analysis (fill-reducing ordering) is kept while the sparsity
// pattern equals the last one (checked entry by entry; particles that gain or
// lose a neighbour change it, so in a flowing case it is redone most steps).
// SparseLU (Eigen, COLAMD ordering) works on a column-major copy.
#include "core/Log.hpp"
#include "linearSolvers/KLUFactor.hpp"
#include "linearSolvers/Krylov.hpp"
#include "linearSolvers/SolverBackends.hpp"
#include <Eigen/SparseLU>
#include <algorithm>
#include <umfpack.h>

namespace shizuku {

namespace {

LinearSolveResult finish(const std::string& name, const SparseMatrixR& A, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& x, bool solved) {
  LinearSolveResult r;
  r.iterations = 1;
  r.residual = relativeResidual(A, b.data(), x.data());
  r.ok = solved && std::isfinite(r.residual) && r.residual < 1e-6;
  if (!r.ok) r.message = cat(name, " solve failed, residual ", r.residual);
  return r;
}

class KLUSolver final : public LinearSolver {
 public:
  explicit KLUSolver(bool reuse) : reuse_(reuse) {}
  std::string name() const override { return "KLU"; }
  std::string describe() const override {
    return cat("KLU (direct sparse LU", reuse_ ? ", symbolic analysis kept while the pattern is unchanged" : "", ")");
  }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    LinearSolveResult r;
    r.message = lu_.factor(A, reuse_);
    if (!r.message.empty()) return r;
    x = b;
    return finish("KLU", A, b, x, lu_.solveInPlace(x.data()));
  }

 private:
  bool reuse_;
  KLUFactor lu_;
};

class UMFPACKSolver final : public LinearSolver {
 public:
  explicit UMFPACKSolver(bool reuse) : reuse_(reuse) { umfpack_di_defaults(control_); }
  ~UMFPACKSolver() override {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  }
  std::string name() const override { return "UMFPACK"; }
  std::string describe() const override {
    return cat("UMFPACK (direct sparse LU", reuse_ ? ", symbolic analysis kept while the pattern is unchanged" : "",
               ")");
  }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    const int n = int(A.rows());
    const int* Ap = A.outerIndexPtr();
    const int* Ai = A.innerIndexPtr();
    const double* Ax = A.valuePtr();
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    LinearSolveResult r;
    if (!(reuse_ && symbolic_ && memo_.same(A))) {
      if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
      if (umfpack_di_symbolic(n, n, Ap, Ai, Ax, &symbolic_, control_, info_) != UMFPACK_OK) {
        symbolic_ = nullptr;
        memo_.forget();
        r.message = "UMFPACK analysis failed";
        return r;
      }
      if (reuse_) memo_.remember(A);
    }
    if (umfpack_di_numeric(Ap, Ai, Ax, symbolic_, &numeric_, control_, info_) != UMFPACK_OK) {
      if (numeric_) umfpack_di_free_numeric(&numeric_);
      r.message = "UMFPACK factorisation failed (singular matrix?)";
      return r;
    }
    x.resize(n);
    const bool ok = umfpack_di_solve(UMFPACK_At, Ap, Ai, Ax, x.data(), b.data(), numeric_, control_, info_) == UMFPACK_OK;
    return finish("UMFPACK", A, b, x, ok);
  }

 private:
  bool reuse_;
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  PatternMemo memo_;
};

class SparseLUSolver final : public LinearSolver {
 public:
  std::string name() const override { return "SparseLU"; }
  std::string describe() const override { return "SparseLU (Eigen direct sparse LU, COLAMD ordering)"; }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    colMajor_ = A;
    colMajor_.makeCompressed();
    lu_.compute(colMajor_);
    if (lu_.info() != Eigen::Success) {
      LinearSolveResult r;
      r.message = "SparseLU factorisation failed (singular matrix?)";
      return r;
    }
    x = lu_.solve(b);
    return finish("SparseLU", A, b, x, lu_.info() == Eigen::Success);
  }

 private:
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> colMajor_;
  Eigen::SparseLU<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeKLU(bool reuseSymbolic) { return std::make_unique<KLUSolver>(reuseSymbolic); }
std::unique_ptr<LinearSolver> makeUMFPACK(bool reuseSymbolic) { return std::make_unique<UMFPACKSolver>(reuseSymbolic); }
std::unique_ptr<LinearSolver> makeSparseLU() { return std::make_unique<SparseLUSolver>(); }

}  // namespace shizuku
