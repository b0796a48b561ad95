// The linear-solver factory: reads the `pressure` sub-dictionary of
// system/sphSolution (docs/design.md part 2, docs/method.md 4.2) and builds a backend:
// solver BiCGSTAB|UMFPACK|KLU|SparseLU|PETSc; BiCGSTAB and PETSc: tolerance, maxIterations,
// preconditioner AMG|ILU0|ILUT|diagonal|hypreAMG with amgReuse (AMG, hypreAMG),
// blocks (ILU0), dropTolerance and fillFactor (ILUT); reuseSymbolic (KLU, UMFPACK).
// Defaults and ranges are declared once below; the default was chosen by
// measurement (docs/performance.md). On several ranks a solver that needs the whole
// matrix is replaced by PETSc with the same tolerance, iteration limit and preconditioner
// family (docs/parallel.md 6), so a case runs unchanged in serial and in parallel.
#include "linearSolvers/LinearSolver.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include "linearSolvers/AggregationAMG.hpp"
#include "linearSolvers/Krylov.hpp"
#include "linearSolvers/SolverBackends.hpp"
#include "parallel/Communicator.hpp"

namespace shizuku {

double relativeResidual(const SparseMatrixR& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  return relativeResidual(A, b.data(), x.data());
}

std::vector<std::string> LinearSolver::names() { return {"BiCGSTAB", "UMFPACK", "KLU", "SparseLU", "PETSc"}; }

std::vector<std::string> LinearSolver::preconditionerNames() { return {"AMG", "ILU0", "ILUT", "diagonal", "hypreAMG"}; }

namespace {
LinearSolver::CreateHook& createHook() {
  static LinearSolver::CreateHook hook;
  return hook;
}
}  // namespace

void LinearSolver::setCreateHook(CreateHook hook) { createHook() = std::move(hook); }

std::unique_ptr<LinearSolver> LinearSolver::create(const Dictionary* d) {
  return createHook() ? createHook()(d) : createBuiltin(d);
}

namespace {

namespace key {

const ParameterGroup pressure("system/sphSolution: pressure", "Pressure Poisson equation solver (docs/method.md 4.2).");
const OptionParameter solver = pressure.option("solver", LinearSolver::names(),
    "BiCGSTAB (warm-started, falls back to LU), a direct LU, or PETSc (across ranks; chosen on several ranks)")
    .def("BiCGSTAB");
const OptionParameter krylov = pressure.option("krylov", {"BiCGSTAB", "GMRES"}, "PETSc: the Krylov method")
    .def("BiCGSTAB");
const ScalarParameter tolerance = pressure.scalar("tolerance", dim::none,
    "BiCGSTAB: relative residual to reach").def(1e-8).above(0).below(1);
const IntParameter maxIterations = pressure.integer("maxIterations", "BiCGSTAB: iteration limit").def(2000).min(1);
const OptionParameter preconditioner = pressure.option("preconditioner", LinearSolver::preconditionerNames(),
    "BiCGSTAB preconditioner (hypreAMG: builds with -DSHIZUKU_HYPRE=ON)").def("AMG");
const IntParameter amgReuse = pressure.integer("amgReuse",
    "AMG, hypreAMG: steps a hierarchy is kept (1: rebuilt every step)").def(10).min(1);
const IntParameter blocks = pressure.integer("blocks", "ILU0: diagonal blocks (0: one per thread)").def(0).min(0);
const ScalarParameter dropTolerance = pressure.scalar("dropTolerance", dim::none, "ILUT: drop tolerance")
    .def(1e-4).min(0).below(1);
const IntParameter fillFactor = pressure.integer("fillFactor", "ILUT: fill factor").def(10).min(1);
const SwitchParameter reuseSymbolic = pressure.onOff("reuseSymbolic",
    "KLU, UMFPACK: reuse the symbolic factorization while the pattern holds").def(true);


}  // namespace key
}  // namespace

namespace {

// PETSc with the case's settings; `note` says why it replaced the case's solver.
std::unique_ptr<LinearSolver> createPetsc(const Dictionary* d, const std::string& type) {
  if (!petscAvailable())
    d->error("solver", "PETSc needs a build with MPI (configure without -DSHIZUKU_MPI=OFF)");
  PetscSettings s;
  s.krylov = key::krylov.read(d);
  s.tolerance = key::tolerance.read(d);
  s.maxIterations = key::maxIterations.read(d);
  const std::string pc = key::preconditioner.read(d);
  if (pc == "ILUT") d->error("preconditioner", "ILUT is not available with PETSc: use AMG, diagonal or ILU0");
  s.preconditioner = pc == "AMG" ? "hypreAMG" : pc;
  s.reuse = s.preconditioner == "hypreAMG" ? key::amgReuse.read(d) : 1;
  if (type != "PETSc") s.note = cat("; the case's ", type, " needs the whole matrix on one rank");
  if (d)
    for (const char* k : {"blocks", "dropTolerance", "fillFactor", "amgReuse", "reuseSymbolic"}) d->markRead(k);
  return makePetscSolver(s);
}

}  // namespace

std::unique_ptr<LinearSolver> LinearSolver::createBuiltin(const Dictionary* d) {
  const std::string type = key::solver.read(d);
  if (type == "PETSc" || Communicator::world().isParallel()) return createPetsc(d, type);
  if (d) d->markRead("krylov");
  const bool iterative = type == "BiCGSTAB";
  if (d) {
    // Settings of the other family do not apply: accepted and ignored.
    const std::vector<const char*> iterKeys = {"tolerance", "maxIterations", "preconditioner", "blocks",
                                               "dropTolerance", "fillFactor", "amgReuse"};
    if (!iterative) for (const char* k : iterKeys) d->markRead(k);
    else d->markRead("reuseSymbolic");
  }
  if (!iterative) {
    const bool reuse = key::reuseSymbolic.read(d);
    if (type == "UMFPACK") return makeUMFPACK(reuse);
    if (type == "KLU") return makeKLU(reuse);
    return makeSparseLU();
  }
  IterativeSettings s;
  s.tolerance = key::tolerance.read(d);
  s.maxIterations = key::maxIterations.read(d);
  const std::string pc = key::preconditioner.read(d);
  // Keys of the other preconditioners are accepted and ignored.
  if (d)
    for (const char* k : {"blocks", "dropTolerance", "fillFactor", "amgReuse"}) d->markRead(k);
  std::unique_ptr<Preconditioner> p;
  if (pc == "ILUT") {
    p = makeILUT(key::dropTolerance.read(d), key::fillFactor.read(d));
  } else if (pc == "diagonal") {
    p = std::make_unique<DiagonalPreconditioner>();
  } else if (pc == "AMG" || pc == "hypreAMG") {
    const int reuse = key::amgReuse.read(d);
    if (pc == "AMG") {
      p = std::make_unique<AggregationAMG>(reuse);
    } else {
      if (!hypreAvailable())
        d->error("preconditioner", "hypreAMG needs a build with hypre: install the Debian package libhypre-dev and "
                                   "configure with -DSHIZUKU_HYPRE=ON (or use AMG)");
      p = makeHypreAMG(reuse);
    }
  } else {
    p = std::make_unique<BlockILU0>(key::blocks.read(d));
  }
  return makeBiCGSTAB(s, std::move(p));
}

}  // namespace shizuku
