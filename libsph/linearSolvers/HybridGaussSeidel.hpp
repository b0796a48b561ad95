// The AMG's smoother (docs/method.md 4.2): hybrid Gauss-Seidel over the rows of a sparse
// matrix, Gauss-Seidel inside each OpenMP thread's contiguous row block [lo, hi) and Jacobi
// across blocks (entries of other blocks read the values from before the sweep). With one
// thread, or `parallel` false, it is plain Gauss-Seidel. Matrices are compressed row-major
// with ascending columns; inv holds 1 / a_ii (0 where a_ii = 0: the row keeps x_i = 0).
// No allocation; reads no dictionary keys.
#pragma once
#include "linearSolvers/Preconditioner.hpp"

namespace shizuku {
namespace hybridGaussSeidel {

// Thread t's row block of n rows split among T threads.
inline void rowBlock(int n, int t, int T, int& lo, int& hi) {
  lo = int(long(n) * t / T);
  hi = int(long(n) * (t + 1) / T);
}

// One sweep (forward or backward) on x; old (n entries) is scratch for the values before it.
void sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, double* old, bool forward,
           bool parallel);

// The forward sweep from x = 0, writing x (its values on entry are not read): the same values
// as sweep(forward) on x = 0, with each row stopping at its diagonal.
void sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x, bool parallel);

}  // namespace hybridGaussSeidel
}  // namespace shizuku
