// Candidate PPE backend for the solver study (issue 9 item 3): hypre's ParCSR
// BiCGSTAB preconditioned by BoomerAMG (one V-cycle per application; HMIS
// coarsening, extended+i interpolation truncated to 4 entries, hybrid
// Gauss-Seidel smoothing: the settings hypre recommends for 2D/3D Poisson-like
// non-symmetric matrices). The Debian build of hypre is MPI-only (no OpenMP),
// so it runs on one core whatever the thread count. The AMG hierarchy is built
// anew each solve, or kept for `reuse` solves when the size is unchanged
// (a lagged preconditioner). Header-only; used by bench_pressure when hypre is found.
#pragma once
#include "core/Log.hpp"
#include "pressure/LinearSolver.hpp"
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>
#include <numeric>

namespace shizuku {

class HypreAMGSolver final : public LinearSolver {
 public:
  HypreAMGSolver(double tol, int maxIt, int reuse) : tol_(tol), maxIt_(maxIt), reuse_(std::max(1, reuse)) {
    static bool started = false;
    if (!started) {
      int flag = 0;
      MPI_Initialized(&flag);
      if (!flag) MPI_Init(nullptr, nullptr);
      HYPRE_Init();
      started = true;
    }
  }
  ~HypreAMGSolver() override { release(); }
  std::string name() const override { return "hypre"; }
  std::string describe() const override {
    return cat("hypre BiCGSTAB + BoomerAMG, tolerance ", tol_, reuse_ > 1 ? cat(", hierarchy kept ", reuse_, " solves") : "");
  }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    const int n = int(A.rows());
    const bool rebuild = n != n_ || sinceSetup_ >= reuse_;
    if (n != n_) { release(); create(n); }
    // A new matrix object every solve (the pattern changes); the hierarchy only on rebuild.
    HYPRE_IJMatrixDestroy(ij_);
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &ij_);
    HYPRE_IJMatrixSetObjectType(ij_, HYPRE_PARCSR);
    HYPRE_IJMatrixInitialize(ij_);
    ncols_.resize(n);
    rows_.resize(n);
    std::iota(rows_.begin(), rows_.end(), 0);
    for (int i = 0; i < n; ++i) ncols_[i] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i];
    HYPRE_IJMatrixSetValues(ij_, n, ncols_.data(), rows_.data(), const_cast<int*>(A.innerIndexPtr()),
                            const_cast<double*>(A.valuePtr()));
    HYPRE_IJMatrixAssemble(ij_);
    HYPRE_ParCSRMatrix par;
    HYPRE_IJMatrixGetObject(ij_, reinterpret_cast<void**>(&par));
    setVector(bv_, b.data(), n);
    setVector(xv_, x.data(), n);
    HYPRE_ParVector pb, px;
    HYPRE_IJVectorGetObject(bv_, reinterpret_cast<void**>(&pb));
    HYPRE_IJVectorGetObject(xv_, reinterpret_cast<void**>(&px));
    if (rebuild) {
      if (krylov_) { HYPRE_ParCSRBiCGSTABDestroy(krylov_); HYPRE_BoomerAMGDestroy(amg_); }
      HYPRE_BoomerAMGCreate(&amg_);
      HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
      HYPRE_BoomerAMGSetCoarsenType(amg_, 10);
      HYPRE_BoomerAMGSetInterpType(amg_, 6);
      HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
      HYPRE_BoomerAMGSetStrongThreshold(amg_, 0.25);
      HYPRE_BoomerAMGSetRelaxType(amg_, 3);
      HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
      HYPRE_BoomerAMGSetMaxIter(amg_, 1);
      HYPRE_BoomerAMGSetTol(amg_, 0.0);
      HYPRE_ParCSRBiCGSTABCreate(MPI_COMM_WORLD, &krylov_);
      HYPRE_ParCSRBiCGSTABSetTol(krylov_, tol_);
      HYPRE_ParCSRBiCGSTABSetMaxIter(krylov_, maxIt_);
      HYPRE_ParCSRBiCGSTABSetPrecond(krylov_, HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, amg_);
      HYPRE_ParCSRBiCGSTABSetup(krylov_, par, pb, px);
      sinceSetup_ = 0;
    }
    ++sinceSetup_;
    HYPRE_ParCSRBiCGSTABSolve(krylov_, par, pb, px);
    int its = 0;
    HYPRE_ParCSRBiCGSTABGetNumIterations(krylov_, &its);
    HYPRE_IJVectorGetValues(xv_, n, rows_.data(), x.data());
    LinearSolveResult r;
    r.iterations = its;
    r.residual = relativeResidual(A, b, x);
    r.ok = std::isfinite(r.residual) && r.residual <= std::max(10 * tol_, 1e-10);
    if (!r.ok) r.message = cat("hypre did not converge, residual ", r.residual);
    return r;
  }

 private:
  void create(int n) {
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &ij_);
    HYPRE_IJMatrixSetObjectType(ij_, HYPRE_PARCSR);
    for (auto* v : {&bv_, &xv_}) {
      HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v);
      HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
    }
    n_ = n;
  }
  void setVector(HYPRE_IJVector v, const double* data, int n) {
    HYPRE_IJVectorInitialize(v);
    HYPRE_IJVectorSetValues(v, n, rows_.data(), data);
    HYPRE_IJVectorAssemble(v);
  }
  void release() {
    if (krylov_) { HYPRE_ParCSRBiCGSTABDestroy(krylov_); HYPRE_BoomerAMGDestroy(amg_); krylov_ = nullptr; }
    if (n_ > 0) { HYPRE_IJMatrixDestroy(ij_); HYPRE_IJVectorDestroy(bv_); HYPRE_IJVectorDestroy(xv_); }
    n_ = 0;
  }
  double tol_;
  int maxIt_, reuse_;
  int n_ = 0, sinceSetup_ = 0;
  HYPRE_IJMatrix ij_{};
  HYPRE_IJVector bv_{}, xv_{};
  HYPRE_Solver amg_{}, krylov_ = nullptr;
  std::vector<int> ncols_, rows_;
};

}  // namespace shizuku
