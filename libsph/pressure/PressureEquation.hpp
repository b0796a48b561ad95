// The pressure Poisson equation of the projection step (eqs 5-6/9, methods.md 4.2):
//   interior and vicinity fluid rows:  -<lap p>_i = -b_i   (SPH(2) Laplacian weights, sign flipped so
//                                      the diagonal is positive)
//   free-surface and splash particles: p = 0 (Dirichlet, eliminated)
//   wall particles with fluid neighbours: the Adami row (methods.md 11 A)
//   no Dirichlet particle at all (closed or fully periodic domain): one row pinned to p = 0.
// The matrix is written straight into compressed row storage in parallel, then
// solved by the configured LinearSolver, warm-started from the last pressure.
#pragma once
#include "operators/FlowState.hpp"
#include "pressure/LinearSolver.hpp"

namespace shizuku {

template <int D>
class PressureEquation {
 public:
  explicit PressureEquation(std::unique_ptr<LinearSolver> solver) : solver_(std::move(solver)) {}
  const LinearSolver& solver() const { return *solver_; }
  // source[i] = b_i for fluid rows (rho/dt <div u*>_i plus stabilization terms).
  void assemble(const FlowState<D>& s, const std::vector<double>& source);
  // Solves and writes particles.pressure (p = 0 where not an unknown).
  LinearSolveResult solve(FlowState<D>& s);
  long numUnknowns() const { return long(A_.rows()); }
  const SparseMatrixR& matrix() const { return A_; }
  const Eigen::VectorXd& rhs() const { return b_; }
  bool pinned() const { return pinned_; }
  // Rows that broke the M-matrix sign pattern and took the standard Laplacian (last assembly).
  long standardRows() const { return standardRows_; }

 private:
  std::unique_ptr<LinearSolver> solver_;
  std::vector<Index> unknown_;     // per particle: row index, or -1 (p = 0)
  std::vector<Index> rowStart_;    // per unknown: start in the CSR arrays
  std::vector<Index> rowParticle_; // per unknown: the particle
  SparseMatrixR A_;
  Eigen::VectorXd b_, x_;
  bool pinned_ = false;
  long standardRows_ = 0;
};

}  // namespace shizuku
