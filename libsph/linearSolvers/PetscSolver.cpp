// The pressure equation across ranks (docs/method.md 4.2, docs/parallel.md 6): PETSc's
// Krylov solvers (BiCGStab, or GMRES) on a distributed AIJ matrix, preconditioned by
// hypre's BoomerAMG through PETSc (PCHYPRE), with Jacobi as the fallback when BoomerAMG
// fails to converge. Each rank hands its own rows with global column numbers (rows
// numbered rank by rank: this rank's first row is the sum of the row counts below it);
// on one rank the same matrix as the serial solvers'. The convergence test is the
// serial solvers': ||b - A x|| / ||b|| <= tolerance (right preconditioning, unpreconditioned
// norm), warm-started from x.
// PETSc is initialised on first use (after MPI when the run is distributed) and finalised
// at exit. PETSC_OPTIONS (environment) reaches KSPSetFromOptions, for experiments.
// Keys (LinearSolver::create): solver PETSc; krylov BiCGSTAB|GMRES; preconditioner
// hypreAMG|AMG|diagonal|ILU0 (AMG = BoomerAMG here; ILU0 = block Jacobi with ILU(0));
// tolerance; maxIterations.
#include "core/Log.hpp"
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

void startPetsc() {
  PetscBool started = PETSC_FALSE;
  PetscInitialized(&started);
  if (started) return;
  // Without -parallel MPI is not started: PETSc then starts it as one process.
  PetscInitializeNoArguments();
  std::atexit(finalisePetsc);
}

void check(PetscErrorCode e, const char* what) {
  if (e) throw std::runtime_error(cat("PETSc: ", what, " failed with error ", int(e)));
}

class PetscSolver final : public LinearSolver {
 public:
  PetscSolver(const PetscSettings& s) : s_(s) { startPetsc(); }
  ~PetscSolver() override { release(); }
  std::string name() const override { return "PETSc"; }
  std::string describe() const override {
    return cat("PETSc ", s_.krylov, " (tolerance ", s_.tolerance, ", at most ", s_.maxIterations, " iterations), ",
               preconditionerName(s_.preconditioner), ", on ", Communicator::world().size(), " rank(s)", s_.note);
  }
  bool distributed() const override { return true; }
  LinearSolveResult solve(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    LinearSolveResult r = solveWith(A, b, x, s_.preconditioner);
    if (!r.ok && s_.preconditioner != "diagonal") {
      const std::string first = r.message;
      r = solveWith(A, b, x, "diagonal");
      r.usedFallback = true;
      r.message = cat(first, "; Jacobi fallback: ", r.ok ? "converged" : r.message);
    }
    return r;
  }

 private:
  static std::string preconditionerName(const std::string& pc) {
    if (pc == "diagonal") return "Jacobi";
    if (pc == "ILU0") return "block Jacobi with ILU(0)";
    return "hypre BoomerAMG";
  }
  void release() {
    if (ksp_) KSPDestroy(&ksp_);
    if (mat_) MatDestroy(&mat_);
  }
  LinearSolveResult solveWith(const SparseMatrixR& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              const std::string& pc) {
    const auto& world = Communicator::world();
    const PetscInt m = PetscInt(A.rows());
    const long N = world.sum(long(m));
    release();
    // PETSc copies the rows; columns are global already.
    check(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, m, m, PetscInt(N), PetscInt(N), A.outerIndexPtr(),
                                    A.innerIndexPtr(), A.valuePtr(), &mat_), "MatCreateMPIAIJWithArrays");
    ::Vec vb, vx;
    check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, m, PetscInt(N), b.data(), &vb), "VecCreateMPIWithArray");
    check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, m, PetscInt(N), x.data(), &vx), "VecCreateMPIWithArray");
    check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
    check(KSPSetOperators(ksp_, mat_, mat_), "KSPSetOperators");
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
    const Eigen::VectorXd x0 = x;
    const PetscErrorCode e = KSPSolve(ksp_, vb, vx);
    LinearSolveResult r;
    KSPConvergedReason reason;
    PetscInt its = 0;
    PetscReal rnorm = 0;
    KSPGetConvergedReason(ksp_, &reason);
    KSPGetIterationNumber(ksp_, &its);
    KSPGetResidualNorm(ksp_, &rnorm);
    PetscReal bnorm = 0;
    VecNorm(vb, NORM_2, &bnorm);
    VecDestroy(&vb);
    VecDestroy(&vx);
    r.iterations = int(its);
    r.residual = bnorm > 0 ? rnorm / bnorm : 0;
    r.ok = e == 0 && reason > 0 && std::isfinite(r.residual);
    if (!r.ok) {
      r.message = cat("PETSc ", s_.krylov, " with ", preconditionerName(pc), " did not converge (reason ", int(reason),
                      ", ", its, " iterations, residual ", r.residual, ")");
      x = x0;
    }
    return r;
  }

  PetscSettings s_;
  ::Mat mat_ = nullptr;
  KSP ksp_ = nullptr;
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
