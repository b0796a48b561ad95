// Diagonal and block-Jacobi ILU(0) preconditioners (see Preconditioner.hpp).
// ILU(0), row by row (IKJ form), restricted to the diagonal block of the row:
//   for k in row i, k < i:  l_ik = a_ik / u_kk;  a_ij -= l_ik u_kj for j > k in both patterns.
#include "linearSolvers/Preconditioner.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <cmath>
#include <omp.h>

namespace shizuku {

bool invertDiagonal(const SparseMatrixR& A, double* inv, double whenZero) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
  bool ok = true;
#pragma omp parallel for schedule(static) reduction(&& : ok)
  for (int i = 0; i < n; ++i) {
    double d = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (col[p] == i) d = val[p];
    ok = ok && d != 0 && std::isfinite(d);
    inv[i] = d != 0 ? 1.0 / d : whenZero;
  }
  return ok;
}

bool DiagonalPreconditioner::setup(const SparseMatrixR& A) {
  invDiag_.resize(A.rows());
  return invertDiagonal(A, invDiag_.data(), 1.0);
}

void DiagonalPreconditioner::apply(const double* r, double* z) const {
  const int n = int(invDiag_.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) z[i] = r[i] * invDiag_[i];
}

std::string BlockILU0::describe() const {
  return requestedBlocks_ > 0 ? cat("ILU0 (", requestedBlocks_, " blocks)") : std::string("ILU0 (one block per thread)");
}

bool BlockILU0::setup(const SparseMatrixR& A) {
  n_ = int(A.rows());
  outer_ = A.outerIndexPtr();
  col_ = A.innerIndexPtr();
  const double* val = A.valuePtr();
  const int nnz = outer_[n_];
  const int T = requestedBlocks_ > 0 ? requestedBlocks_ : omp_get_max_threads();
  const int B = std::max(1, std::min(T, n_ / 64 + 1));
  blockStart_.resize(B + 1);
  for (int b = 0; b <= B; ++b) blockStart_[b] = int((long(n_) * b) / B);
  lu_.resize(nnz);
  diag_.resize(n_);
  lo_.resize(n_);
  hi_.resize(n_);
  invPivot_.resize(n_);
  marker_.resize(n_);
  long replaced = 0;
  bool ok = true;
#pragma omp parallel for schedule(static, 1) reduction(+ : replaced) reduction(&& : ok)
  for (int b = 0; b < B; ++b) {
    const int r0 = blockStart_[b], r1 = blockStart_[b + 1];
    for (int i = r0; i < r1; ++i) {
      const int pb = outer_[i], pe = outer_[i + 1];
      int lo = pb, hi = pe, d = -1;
      for (int p = pb; p < pe; ++p) {
        const int c = col_[p];
        if (c < r0) lo = p + 1;
        if (c < r1) hi = p + 1;
        if (c == i) d = p;
        lu_[p] = val[p];
      }
      lo_[i] = lo;
      hi_[i] = hi;
      diag_[i] = d;
      marker_[i] = -1;
      if (d < 0) ok = false;
    }
    if (!ok) continue;
    for (int i = r0; i < r1; ++i) {
      const int lo = lo_[i], hi = hi_[i], d = diag_[i];
      for (int p = lo; p < hi; ++p) marker_[col_[p]] = p;
      for (int p = lo; p < d; ++p) {
        const int k = col_[p];
        const double l = lu_[p] * invPivot_[k];
        lu_[p] = l;
        for (int q = diag_[k] + 1; q < hi_[k]; ++q) {
          const int m = marker_[col_[q]];
          if (m >= 0) lu_[m] -= l * lu_[q];
        }
      }
      for (int p = lo; p < hi; ++p) marker_[col_[p]] = -1;
      double piv = lu_[d];
      // A vanishing or non-finite pivot (not seen on the M-matrix rows of the PPE,
      // kept as a guard) takes the original diagonal.
      if (!(std::abs(piv) > 1e-12 * std::abs(val[d])) || !std::isfinite(piv)) {
        piv = val[d] != 0 ? val[d] : 1.0;
        lu_[d] = piv;
        ++replaced;
      }
      invPivot_[i] = 1.0 / piv;
    }
  }
  replacedPivots_ = replaced;
  return ok;
}

void BlockILU0::apply(const double* r, double* z) const {
  const int B = blocks();
#pragma omp parallel for schedule(static, 1)
  for (int b = 0; b < B; ++b) {
    const int r0 = blockStart_[b], r1 = blockStart_[b + 1];
    // L y = r (unit lower), written into z.
    for (int i = r0; i < r1; ++i) {
      double s = r[i];
      for (int p = lo_[i]; p < diag_[i]; ++p) s -= lu_[p] * z[col_[p]];
      z[i] = s;
    }
    // U z = y.
    for (int i = r1 - 1; i >= r0; --i) {
      double s = z[i];
      for (int p = diag_[i] + 1; p < hi_[i]; ++p) s -= lu_[p] * z[col_[p]];
      z[i] = s * invPivot_[i];
    }
  }
}

}  // namespace shizuku
