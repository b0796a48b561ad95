// The pressure equation across ranks (docs/method.md 4.2, docs/parallel.md 6): PETSc's
// Krylov solvers (BiCGStab, or GMRES) on a distributed AIJ matrix, preconditioned by
// hypre's BoomerAMG through PETSc (PCHYPRE; settings below), with Jacobi as the fallback
// when BoomerAMG fails to converge; the hierarchy is kept across solves (below). Each rank hands its own rows with global column numbers (rows
// numbered rank by rank: this rank's first row is the sum of the row counts below it);
// on one rank the same matrix as the serial solvers'. The convergence test is the
// serial solvers': ||b - A x|| / ||b|| <= tolerance (right preconditioning, unpreconditioned
// norm), warm-started from x.
// PETSc is initialised on first use (after MPI when the run is distributed) and finalised
// at exit. PETSC_OPTIONS (environment) reaches KSPSetFromOptions, for experiments.
// Keys (LinearSolver::create): solver PETSc; krylov BiCGSTAB|GMRES; preconditioner
// hypreAMG|AMG|diagonal|ILU0 (AMG = BoomerAMG here; ILU0 = block Jacobi with ILU(0));
// tolerance; maxIterations; amgReuse (solves a BoomerAMG hierarchy is kept).
#include "core/Log.hpp"
#include <algorithm>
#include "linearSolvers/SolverBackends.hpp"
#include "parallel/Communicator.hpp"
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#ifdef SHIZUKU_HAVE_MPI
#include <petscksp.h>
#endif

namespace shizuku {

#ifdef SHIZUKU_HAVE_MPI

namespace {

void finalisePetsc() {
  PetscBool done = PETSC_FALSE;
  PetscFinalized(&done);
  if (!done) PetscFinalize();
}

// BoomerAMG settings for these matrices unless PETSC_OPTIONS gives its own: HMIS
// coarsening, extended+i interpolation truncated to 4 entries, one level of aggressive
// coarsening (hypre's recommendation for 2D and 3D Poisson-like problems). Measured on the
// dam break at t = 0.1 s, 2 ranks, 50 steps: the pressure solve 1.22 s with PETSc's defaults
// (10 iterations), 0.55 s with these (6), against 0.36 s for the serial own AMG (6).
void setBoomerAmgDefaults() {
  const char* defaults[][2] = {{"-pc_hypre_boomeramg_coarsen_type", "HMIS"},
                               {"-pc_hypre_boomeramg_interp_type", "ext+i"},
                               {"-pc_hypre_boomeramg_P_max", "4"},
                               {"-pc_hypre_boomeramg_agg_nl", "1"}};
  for (const auto& d : defaults) {
    PetscBool set = PETSC_FALSE;
    PetscOptionsHasName(nullptr, nullptr, d[0], &set);
    if (!set) PetscOptionsSetValue(nullptr, d[0], d[1]);
  }
}

void startPetsc() {
  PetscBool started = PETSC_FALSE;
  PetscInitialized(&started);
  if (started) return;
  // Without -parallel MPI is not started: PETSc then starts it as one process.
  PetscInitializeNoArguments();
  setBoomerAmgDefaults();
  std::atexit(finalisePetsc);
}

void check(PetscErrorCode e, const char* what) {
  if (e) throw std::runtime_error(cat("PETSc: ", what, " failed with error ", int(e)));
}

class PetscSolver final : public LinearSolver {
 public:
  explicit PetscSolver(const PetscSettings& s) : s_(s) { startPetsc(); }
  ~PetscSolver() override { release(); }
  std::string name() const override { return "PETSc"; }
  std::string describe() const override {
    return cat("PETSc ", s_.krylov, " (tolerance ", s_.tolerance, ", at most ", s_.maxIterations, " iterations), ",
               preconditionerName(s_.preconditioner),
               s_.reuse > 1 ? cat(" kept up to ", s_.reuse, " steps") : std::string(), ", on ",
               Communicator::world().size(), " rank(s)", s_.note);
  }
  bool distributed() const override { return true; }
  // The preconditioner (BoomerAMG's hierarchy) is kept while the rows stay the same
  // particles, for at most `reuse` solves, and rebuilt early when the iterations have grown
  // past 1.5x (+2) those of the solve that built it (as the serial AMG: docs/performance.md).
  // A kept hierarchy that does not converge within that many is given up for a new one, and
  // the next `reuse` solves build their own (a flow whose matrix moves on every step).
  bool nextSolveStartsAfresh() const override { return stale_ || sinceSetup_ >= s_.reuse || rebuildFor_ > 0; }
  void startAfreshAtNextSolve() override { stale_ = true; }

  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    const auto& world = Communicator::world();
    bool keep = !nextSolveStartsAfresh() && A.rows() == rows_;
    keep = !world.any(!keep);  // every rank keeps, or every rank rebuilds
    LinearSolveResult r = solveWith(A, b, x, s_.preconditioner, keep);
    int tried = 0;  // the iterations of a kept hierarchy that did not converge
    if (!r.ok && keep) {  // a kept hierarchy that no longer fits: rebuild before falling back
      tried = r.iterations;
      rebuildFor_ = s_.reuse + 1;
      keep = false;
      r = solveWith(A, b, x, s_.preconditioner, false);
    }
    rows_ = A.rows();
    if (!r.ok && s_.preconditioner != "diagonal") {
      const std::string first = r.message;
      r = solveWith(A, b, x, "diagonal", false);
      r.usedFallback = true;
      r.message = cat(first, "; Jacobi fallback: ", r.ok ? "converged" : r.message);
      stale_ = true;
      r.iterations += tried;
      return r;
    }
    if (!keep) {
      rebuildFor_ = std::max(0, rebuildFor_ - 1);
      sinceSetup_ = 1;
      setupIterations_ = r.iterations;
      stale_ = false;
    } else if (++sinceSetup_, r.iterations > staleAfter()) {
      stale_ = true;
    }
    r.iterations += tried;
    return r;
  }

 private:
  // A kept hierarchy is stale once a solve takes more iterations than this.
  double staleAfter() const { return 1.5 * setupIterations_ + 2; }
  static std::string preconditionerName(const std::string& pc) {
    if (pc == "diagonal") return "Jacobi";
    if (pc == "ILU0") return "block Jacobi with ILU(0)";
    return "hypre BoomerAMG";
  }
  void release() {
    if (ksp_) KSPDestroy(&ksp_);
    if (mat_) MatDestroy(&mat_);
  }
  // A new KSP with preconditioner pc for mat_.
  void createKsp(const std::string& pc) {
    check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
    check(KSPSetType(ksp_, s_.krylov == "GMRES" ? KSPGMRES : KSPBCGS), "KSPSetType");
    check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    check(KSPSetTolerances(ksp_, s_.tolerance, 0.0, 1e10, s_.maxIterations), "KSPSetTolerances");
    check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSPSetInitialGuessNonzero");
    PC p;
    check(KSPGetPC(ksp_, &p), "KSPGetPC");
    if (pc == "diagonal") {
      check(PCSetType(p, PCJACOBI), "PCSetType");
    } else if (pc == "ILU0") {
      check(PCSetType(p, PCBJACOBI), "PCSetType");
    } else {
      check(PCSetType(p, PCHYPRE), "PCSetType");
      check(PCHYPRESetType(p, "boomeramg"), "PCHYPRESetType");
    }
    check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  }
  // keep: this matrix has the rows of the last one (the same particles, in order), and the
  // preconditioner built for an earlier matrix is applied to it.
  LinearSolveResult solveWith(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              const std::string& pc, bool keep) {
    const auto& world = Communicator::world();
    const PetscInt m = PetscInt(A.rows());
    const long N = world.sum(long(m));
    if (!keep || !ksp_) {
      release();
    } else if (mat_) {
      MatDestroy(&mat_);
    }
    // PETSc copies the rows; columns are global already.
    check(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, m, m, PetscInt(N), PetscInt(N), A.outerIndexPtr(),
                                    A.innerIndexPtr(), A.valuePtr(), &mat_), "MatCreateMPIAIJWithArrays");
    if (!ksp_) createKsp(pc);
    check(KSPSetReusePreconditioner(ksp_, keep ? PETSC_TRUE : PETSC_FALSE), "KSPSetReusePreconditioner");
    // A kept hierarchy may stop at the iterations that mark it stale (1.5x + 2 those of the
    // solve that built it): where the matrix has moved on (the free surface's rows changed
    // class) it would otherwise take hundreds, and a new hierarchy costs a few.
    const PetscInt most = keep ? std::min<PetscInt>(s_.maxIterations, PetscInt(staleAfter()) + 1) : s_.maxIterations;
    check(KSPSetTolerances(ksp_, s_.tolerance, 0.0, 1e10, most), "KSPSetTolerances");
    check(KSPSetOperators(ksp_, mat_, mat_), "KSPSetOperators");
    ::Vec vb, vx;
    check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, m, PetscInt(N), b.data(), &vb), "VecCreateMPIWithArray");
    check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, m, PetscInt(N), x.data(), &vx), "VecCreateMPIWithArray");
    x0_ = x;
    const PetscErrorCode e = KSPSolve(ksp_, vb, vx);
    LinearSolveResult r;
    KSPConvergedReason reason;
    PetscInt its = 0;
    PetscReal rnorm = 0, bnorm = 0;
    KSPGetConvergedReason(ksp_, &reason);
    KSPGetIterationNumber(ksp_, &its);
    KSPGetResidualNorm(ksp_, &rnorm);
    VecNorm(vb, NORM_2, &bnorm);
    VecDestroy(&vb);
    VecDestroy(&vx);
    r.iterations = int(its);
    r.residual = bnorm > 0 ? rnorm / bnorm : 0;
    r.ok = e == 0 && reason > 0 && std::isfinite(r.residual);
    if (!r.ok) {
      r.message = cat("PETSc ", s_.krylov, " with ", preconditionerName(pc), keep ? " (kept)" : "",
                      " did not converge (reason ", int(reason), ", ", its, " iterations, residual ", r.residual, ")");
      x = x0_;
      release();  // the next solve builds afresh
    }
    return r;
  }

  PetscSettings s_;
  ::Mat mat_ = nullptr;
  KSP ksp_ = nullptr;
  Eigen::VectorXd x0_;
  long rows_ = -1;
  int sinceSetup_ = 0, setupIterations_ = 0, rebuildFor_ = 0;
  bool stale_ = true;
};

}  // namespace

bool petscAvailable() { return true; }
std::unique_ptr<LinearSolver> makePetscSolver(const PetscSettings& s) { return std::make_unique<PetscSolver>(s); }

#else

bool petscAvailable() { return false; }
std::unique_ptr<LinearSolver> makePetscSolver(const PetscSettings&) {
  throw std::logic_error("makePetscSolver: a build without MPI has no PETSc");
}

#endif

}  // namespace shizuku
