// The linear-solver factory: reads the `pressure` sub-dictionary of
// system/sphSolution (design.md part 2, methods.md 4.2) and builds a backend:
//   solver          BiCGSTAB | UMFPACK | KLU | SparseLU        (default BiCGSTAB)
//   preconditioner  AMG | ILU0 | ILUT | diagonal | hypreAMG    (BiCGSTAB; default AMG, the own
//                                                              smoothed aggregation; hypreAMG only
//                                                              in builds with -DSHIZUKU_HYPRE=ON)
//   amgReuse 10                                                (AMG, hypreAMG: steps a hierarchy is kept)
//   tolerance 1e-8; maxIterations 2000;                        (BiCGSTAB)
//   blocks N                                                   (ILU0; default: one per thread)
//   dropTolerance 1e-4; fillFactor 10;                         (ILUT)
//   reuseSymbolic yes                                          (KLU, UMFPACK)
// The default was chosen by measurement: docs/performance.md.
#include "linearSolvers/LinearSolver.hpp"
#include "linearSolvers/AggregationAMG.hpp"
#include "linearSolvers/Krylov.hpp"
#include "linearSolvers/SolverBackends.hpp"

namespace shizuku {

double relativeResidual(const SparseMatrixR& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  return relativeResidual(A, b.data(), x.data());
}

std::vector<std::string> LinearSolver::names() { return {"BiCGSTAB", "UMFPACK", "KLU", "SparseLU"}; }

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

std::unique_ptr<LinearSolver> LinearSolver::createBuiltin(const Dictionary* d) {
  const std::string type = d ? d->getOptionOr("solver", names(), "BiCGSTAB") : "BiCGSTAB";
  const bool iterative = type == "BiCGSTAB";
  if (d) {
    // Settings of the other family do not apply: accepted and ignored.
    const std::vector<const char*> iterKeys = {"tolerance", "maxIterations", "preconditioner", "blocks",
                                               "dropTolerance", "fillFactor", "amgReuse"};
    if (!iterative) for (const char* k : iterKeys) d->markRead(k);
    else d->markRead("reuseSymbolic");
  }
  if (!iterative) {
    const bool reuse = d ? d->getSwitchOr("reuseSymbolic", true) : true;
    if (type == "UMFPACK") return makeUMFPACK(reuse);
    if (type == "KLU") return makeKLU(reuse);
    return makeSparseLU();
  }
  IterativeSettings s;
  s.tolerance = d ? d->getScalarOr("tolerance", 1e-8, dim::none) : 1e-8;
  s.maxIterations = d ? d->getIntOr("maxIterations", 2000) : 2000;
  if (d && !(s.tolerance > 0)) d->error("tolerance", "must be > 0");
  if (d && s.maxIterations <= 0) d->error("maxIterations", "must be > 0");
  const std::string def = "AMG";
  const std::string pc = d ? d->getOptionOr("preconditioner", preconditionerNames(), def) : def;
  // Keys of the other preconditioners are accepted and ignored.
  if (d)
    for (const char* k : {"blocks", "dropTolerance", "fillFactor", "amgReuse"}) d->markRead(k);
  std::unique_ptr<Preconditioner> p;
  if (pc == "ILUT") {
    const double drop = d ? d->getScalarOr("dropTolerance", 1e-4, dim::none) : 1e-4;
    const int fill = d ? d->getIntOr("fillFactor", 10) : 10;
    if (d && !(drop >= 0)) d->error("dropTolerance", "must be >= 0");
    if (d && fill <= 0) d->error("fillFactor", "must be > 0");
    p = makeILUT(drop, fill);
  } else if (pc == "diagonal") {
    p = std::make_unique<DiagonalPreconditioner>();
  } else if (pc == "AMG" || pc == "hypreAMG") {
    const int reuse = d ? d->getIntOr("amgReuse", 10) : 10;
    if (d && reuse < 1) d->error("amgReuse", "must be >= 1 (1: a new hierarchy every step)");
    if (pc == "AMG") {
      p = std::make_unique<AggregationAMG>(reuse);
    } else {
      if (!hypreAvailable())
        d->error("preconditioner", "hypreAMG needs a build with hypre: install the Debian package libhypre-dev and "
                                   "configure with -DSHIZUKU_HYPRE=ON (or use AMG)");
      p = makeHypreAMG(reuse);
    }
  } else {
    const int blocks = d ? d->getIntOr("blocks", 0) : 0;
    if (d && blocks < 0) d->error("blocks", "must be >= 0 (0: one block per thread)");
    p = std::make_unique<BlockILU0>(blocks);
  }
  return makeBiCGSTAB(s, std::move(p));
}

}  // namespace shizuku
