// Hybrid Gauss-Seidel sweeps of the AMG smoother (see HybridGaussSeidel.hpp).
#include "linearSolvers/HybridGaussSeidel.hpp"
#include <omp.h>

namespace shizuku {
namespace hybridGaussSeidel {

namespace {
// Runs block(lo, hi) on every thread's row block (one block of all rows unless parallel);
// block may hold barriers.
template <class Block>
void inBlocks(int n, bool parallel, Block&& block) {
#pragma omp parallel if (parallel)
  {
    int lo, hi;
    rowBlock(n, omp_get_thread_num(), omp_get_num_threads(), lo, hi);
    block(lo, hi);
  }
}
}  // namespace

void sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, double* old, bool forward,
           bool parallel) {
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
  inBlocks(int(A.rows()), parallel, [&](int lo, int hi) {
    for (int i = lo; i < hi; ++i) old[i] = x[i];
#pragma omp barrier
    // Columns ascend, so a row's entries are those before the block (old values),
    // in it (current values, the diagonal skipped) and after it (old values): three
    // runs summed in column order, without a test of each column against the block.
    auto row = [&](int i) {
      double s = b[i];
      int p = outer[i];
      const int e = outer[i + 1];
      for (; p < e && col[p] < lo; ++p) s -= val[p] * old[col[p]];
      for (; p < e && col[p] < hi; ++p)
        if (col[p] != i) s -= val[p] * x[col[p]];
      for (; p < e; ++p) s -= val[p] * old[col[p]];
      x[i] = s * inv[i];
    };
    if (forward)
      for (int i = lo; i < hi; ++i) row(i);
    else
      for (int i = hi - 1; i >= lo; --i) row(i);
  });
}

// Every term with a column at or after the diagonal, or outside the thread's block,
// multiplies a zero, so each row stops at its diagonal and neither the zeroing of x nor
// the copy of the old values is needed.
void sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x, bool parallel) {
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
  inBlocks(int(A.rows()), parallel, [&](int lo, int hi) {
    for (int i = lo; i < hi; ++i) {
      double s = b[i];
      int p = outer[i];
      const int e = outer[i + 1];
      while (p < e && col[p] < lo) ++p;
      for (; p < e && col[p] < i; ++p) s -= val[p] * x[col[p]];
      x[i] = s * inv[i];
    }
  });
}

}  // namespace hybridGaussSeidel
}  // namespace shizuku
