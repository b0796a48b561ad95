// Right-preconditioned BiCGSTAB (van der Vorst 1992) for the pressure Poisson
// equation (docs/method.md 4.2), OpenMP-parallel in every matrix-vector product,
// dot product and vector update, with the products fused with the reductions
// that follow them. The work vectors live in a KrylovWorkspace that keeps its
// capacity between time steps: a solve allocates nothing once it has run at the
// largest size. Convergence: ||b - A x|| <= tolerance ||b|| on the recursively
// updated residual; the caller checks the true residual.
#pragma once
#include "linearSolvers/Preconditioner.hpp"

namespace shizuku {

struct KrylovWorkspace {
  std::vector<double> r, r0, p, v, t, y, z;  // s lives in r
  void resize(int n);
};

struct KrylovResult {
  bool converged = false;
  bool breakdown = false;
  int iterations = 0;
  double residual = 0;  // recursive ||r|| / ||b||
};

// x holds the initial guess on entry. b, x have A.rows() entries.
KrylovResult bicgstab(const SparseMatrixR& A, const double* b, double* x, const Preconditioner& M,
                      double tolerance, int maxIterations, KrylovWorkspace& w);

// y = A x (parallel over rows).
void multiply(const SparseMatrixR& A, const double* x, double* y);
// ||A x - b|| / ||b|| (||A x - b|| when b = 0), parallel, no allocation.
double relativeResidual(const SparseMatrixR& A, const double* b, const double* x);

}  // namespace shizuku
