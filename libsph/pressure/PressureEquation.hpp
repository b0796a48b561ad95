// The pressure Poisson equation of the projection step (eqs 5-6/9, docs/method.md 4.2):
//   interior and vicinity fluid rows:  -<lap p>_i (+ k p_i) = -b_i   (SPH(2) Laplacian weights, sign
//                                      flipped so the diagonal is positive; k: eq. 6c)
//   free-surface particles: p = 0 on the surface, delta_i outside the particle: the
//                           extrapolation row of eq. 6b (FreeSurfaceRow.hpp); with
//                           freeSurface { pressureCondition particles; } p = 0 on the particle
//   splash particles (and free ones without a normal or a deeper neighbour): p = 0
//   outlet particles: their prescribed pressure (Dirichlet, docs/boundaries.md)
//   wall particles with fluid neighbours: the Adami row (docs/method.md 11 A)
//   no Dirichlet particle at all (closed or fully periodic domain): one row pinned to p = 0,
//   unless the rows carry the compressibility term (eq. 6c), which fixes the level.
// Every particle has a row, in particle order, so the numbering of the system
// only changes when the particles are reordered (a solver may then keep a
// preconditioner across steps); particles with p = 0 (free surface, splash,
// walls away from the fluid) get the row p_i = 0 and no column elsewhere.
// The matrix is written straight into compressed row storage in parallel, then
// solved by the configured LinearSolver, warm-started from the last pressure.
// No allocation once the buffers have grown to the largest size seen.
#pragma once
#include "operators/FlowState.hpp"
#include "boundaries/WallParticles.hpp"
#include "linearSolvers/LinearSolver.hpp"
#include <algorithm>

namespace shizuku {

template <int D>
class PressureEquation {
 public:
  explicit PressureEquation(std::unique_ptr<LinearSolver> solver) : solver_(std::move(solver)) {}
  // true: p = 0 on the free surface (eq. 6b, the default); false: p = 0 on the free-surface particles.
  void setZeroPressureOnSurface(bool onSurface) { onSurface_ = onSurface; }
  bool zeroPressureOnSurface() const { return onSurface_; }
  const LinearSolver& solver() const { return *solver_; }
  // The next solve rebuilds whatever the solver keeps from earlier steps (restart exactness).
  void startAfreshAtNextSolve() { solver_->startAfreshAtNextSolve(); }
  // Whether the next solve will start afresh: the solver's own reuse cycle ends, or the
  // particles (ids in order) differ from the last assembly's (reordered, released,
  // captured or removed), which rebuilds as well.
  bool nextSolveStartsAfresh(const FlowState<D>& s) const {
    return solver_->nextSolveStartsAfresh() || numberingChanged(s.particles, s.numOwned());
  }
  // source[i] = b_i for fluid rows (rho/dt <div u*>_i plus the effects' terms); diagonal: the
  // effects' k added to every fluid row's diagonal (-<lap p>_i + k p_i = -b_i; eq. 6c).
  void assemble(const FlowState<D>& s, const std::vector<double>& source, double diagonal);
  // Solves and writes particles.pressure (p = 0 where not an unknown). correction: the
  // matrix is the last solve's with a few wall rows changed (the solver reuses its state).
  LinearSolveResult solve(FlowState<D>& s, bool correction = false);
  // Eq. 11b decided again with the pressure just solved: rewrites the wall rows and returns
  // whether any row's bound changed from the last decision (the assembly's takes the previous
  // step's pressure); the step then solves again (docs/method.md 11). Collective.
  bool redecideWallRows(const FlowState<D>& s);
  // Particles whose pressure is solved for (the other rows are p = 0).
  long numUnknowns() const { return numUnknowns_; }
  const SparseMatrixR& matrix() const { return A_; }
  const Eigen::VectorXd& rhs() const { return b_; }
  bool pinned() const { return pinned_; }
  // Rows that broke the M-matrix sign pattern and took the standard Laplacian (last assembly).
  long standardRows() const { return standardRows_; }

 private:
  // The rows' particles, this rank's own `owned` first ones (ids in order), differ from
  // those of the last assembly.
  bool numberingChanged(const ParticleSet<D>& P, std::size_t owned) const {
    return ids_.size() != owned || owned > P.id.size() || !std::equal(ids_.begin(), ids_.end(), P.id.begin());
  }
  bool countRows(const FlowState<D>& s);
  void fillRows(const FlowState<D>& s, const std::vector<double>& source, double diagonal);
  void fillSurfaceRow(const FlowState<D>& s, long i, Index pos, int* col, double* val);
  void fillWallRow(const FlowState<D>& s, long i, const AdamiRow<D>& row, int* col, double* val);
  LinearSolveResult solveDistributed(const FlowState<D>& s);
  std::unique_ptr<LinearSolver> solver_;
  bool onSurface_ = true;
  std::vector<std::uint8_t> unknown_;  // per particle: 0 = p known, 1 = solved for, 2 = eq. 6b row
  std::vector<Vec<D>> inward_;         // per particle with an eq. 6b row: -n_i
  std::vector<double> delta_;          // per particle with an eq. 6b row: delta_i
  std::vector<Index> rowStart_;        // per row: start in the CSR arrays
  std::vector<std::int64_t> ids_;      // particle ids of the last assembly (detects reordering)
  WallContacts<D> contacts_;           // wall normals of fluid particles (wall rows, eq. 11a)
  std::vector<std::uint8_t> ambient_;  // per wall row of the last assembly: eq. 11b binds, p_w = 0
  bool hasWallRows_ = false;
  SparseMatrixR A_;
  long numUnknowns_ = 0;
  Eigen::VectorXd b_, x_;
  // A distributed run: this rank's rows with global columns, and their vectors.
  std::vector<std::int64_t> globalRow_;
  SparseMatrixR Aowned_;
  Eigen::VectorXd bOwned_, xOwned_;
  bool pinned_ = false;
  long standardRows_ = 0;
};

}  // namespace shizuku
