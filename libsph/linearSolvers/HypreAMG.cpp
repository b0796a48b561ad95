// Algebraic multigrid preconditioner for the PPE (docs/method.md 4.2):
// one BoomerAMG V-cycle of hypre (Debian libhypre-dev) per application, inside
// the OpenMP BiCGSTAB of Krylov.cpp. Settings are hypre's recommendations for
// Poisson-like non-symmetric 2D/3D matrices: HMIS coarsening, extended+i
// interpolation truncated to 4 entries, strong threshold 0.25 (2D) / 0.5 (3D
// not distinguished here: 0.25), one hybrid Gauss-Seidel sweep down and up.
// The hierarchy is kept ("lagged") while the numbering of the rows is unchanged,
// for at most `reuse` solves, and rebuilt early when the iteration count has
// grown past 1.5x (+2) the count of the solve that built it: the matrix of the
// next steps differs little, and an older hierarchy is still a good
// preconditioner (measured in docs/performance.md).
// The Debian hypre is an MPI build without OpenMP: the V-cycle runs on one core;
// MPI is initialised (as a single process) on first use and finalised at exit.
// Keys (LinearSolver::create): preconditioner hypreAMG; amgReuse 10.
#include "core/Log.hpp"
#include "linearSolvers/SolverBackends.hpp"
#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

#ifdef SHIZUKU_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>
#endif

namespace shizuku {

#ifdef SHIZUKU_HAVE_HYPRE

namespace {

void finaliseHypre() {
  HYPRE_Finalize();
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

void startHypre() {
  static bool started = false;
  if (started) return;
  int flag = 0;
  MPI_Initialized(&flag);
  if (!flag) {
    MPI_Init(nullptr, nullptr);
    std::atexit(finaliseHypre);
  }
  HYPRE_Init();
  started = true;
}

class HypreBoomerAMG final : public Preconditioner {
 public:
  explicit HypreBoomerAMG(int reuse) : reuse_(std::max(1, reuse)) { startHypre(); }
  ~HypreBoomerAMG() override { release(); }
  std::string describe() const override {
    return cat("AMG (hypre BoomerAMG V-cycle, one core", reuse_ > 1 ? cat(", hierarchy kept up to ", reuse_, " steps") : "",
               ")");
  }
  bool nextSetupRebuilds() const override { return stale_ || sinceSetup_ >= reuse_; }
  void rebuildAtNextSetup() override { stale_ = true; }
  void solved(int iterations) override {
    if (sinceSetup_ == 1) setupIterations_ = iterations;
    else if (iterations > 1.5 * setupIterations_ + 2) stale_ = true;
  }
  bool setup(const SparseMatrixR& A) override {
    const int n = int(A.rows());
    if (!(stale_ || n != n_ || sinceSetup_ >= reuse_)) { ++sinceSetup_; return true; }
    release();
    n_ = n;
    rows_.resize(n);
    ncols_.resize(n);
    std::iota(rows_.begin(), rows_.end(), 0);
    for (int i = 0; i < n; ++i) ncols_[i] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i];
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &ij_);
    HYPRE_IJMatrixSetObjectType(ij_, HYPRE_PARCSR);
    HYPRE_IJMatrixInitialize(ij_);
    HYPRE_IJMatrixSetValues(ij_, n, ncols_.data(), rows_.data(), const_cast<int*>(A.innerIndexPtr()),
                            const_cast<double*>(A.valuePtr()));
    HYPRE_IJMatrixAssemble(ij_);
    HYPRE_IJMatrixGetObject(ij_, reinterpret_cast<void**>(&par_));
    for (auto* v : {&rv_, &zv_}) {
      HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v);
      HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
      HYPRE_IJVectorInitialize(*v);
      HYPRE_IJVectorAssemble(*v);
    }
    HYPRE_IJVectorGetObject(rv_, reinterpret_cast<void**>(&pr_));
    HYPRE_IJVectorGetObject(zv_, reinterpret_cast<void**>(&pz_));
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
    const int err = HYPRE_BoomerAMGSetup(amg_, par_, pr_, pz_);
    built_ = true;
    stale_ = false;
    sinceSetup_ = 1;
    ++setups_;
    return err == 0;
  }
  void apply(const double* r, double* z) const override {
    HYPRE_IJVectorSetValues(rv_, n_, rows_.data(), r);
    std::fill(z, z + n_, 0.0);
    HYPRE_IJVectorSetValues(zv_, n_, rows_.data(), z);
    HYPRE_BoomerAMGSolve(amg_, par_, pr_, pz_);
    HYPRE_IJVectorGetValues(zv_, n_, rows_.data(), z);
  }

 private:
  void release() {
    if (!built_) return;
    HYPRE_BoomerAMGDestroy(amg_);
    HYPRE_IJMatrixDestroy(ij_);
    HYPRE_IJVectorDestroy(rv_);
    HYPRE_IJVectorDestroy(zv_);
    built_ = false;
  }
  int reuse_;
  bool built_ = false, stale_ = true;
  int n_ = 0, sinceSetup_ = 0, setupIterations_ = 0;
  long setups_ = 0;
  std::vector<int> rows_, ncols_;
  HYPRE_IJMatrix ij_{};
  HYPRE_ParCSRMatrix par_{};
  HYPRE_IJVector rv_{}, zv_{};
  HYPRE_ParVector pr_{}, pz_{};
  HYPRE_Solver amg_{};
};

}  // namespace

bool hypreAvailable() { return true; }
std::unique_ptr<Preconditioner> makeHypreAMG(int reuse) { return std::make_unique<HypreBoomerAMG>(reuse); }

#else

bool hypreAvailable() { return false; }
std::unique_ptr<Preconditioner> makeHypreAMG(int) {
  throw std::runtime_error("this build has no hypre: install the Debian package libhypre-dev and rebuild");
}

#endif

}  // namespace shizuku
