// KLU factorisation of a CSR matrix (see KLUFactor.hpp).
#include "linearSolvers/KLUFactor.hpp"
#include <algorithm>

namespace shizuku {

bool PatternMemo::same(const SparseMatrixR& A) const {
  const int n = int(A.rows());
  if (n + 1 != int(outer_.size())) return false;
  const int nnz = A.outerIndexPtr()[n];
  if (nnz != int(inner_.size())) return false;
  return std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr());
}

void PatternMemo::remember(const SparseMatrixR& A) {
  const int n = int(A.rows());
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.outerIndexPtr()[n]);
}

void KLUFactor::release() {
  if (numeric_) klu_free_numeric(&numeric_, &common_);
  if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
}

const char* KLUFactor::factor(const SparseMatrixR& A, bool keepAnalysis) {
  n_ = int(A.rows());
  int* Ap = const_cast<int*>(A.outerIndexPtr());
  int* Ai = const_cast<int*>(A.innerIndexPtr());
  double* Ax = const_cast<double*>(A.valuePtr());
  if (numeric_) klu_free_numeric(&numeric_, &common_);
  if (!(keepAnalysis && symbolic_ && memo_.same(A))) {
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
    symbolic_ = klu_analyze(n_, Ap, Ai, &common_);
    if (keepAnalysis) memo_.remember(A);
  }
  if (!symbolic_) {
    memo_.forget();
    return "KLU analysis failed";
  }
  numeric_ = klu_factor(Ap, Ai, Ax, symbolic_, &common_);
  if (!numeric_) return "KLU factorisation failed (singular matrix?)";
  return "";
}

bool KLUFactor::solveInPlace(double* x) const {
  return numeric_ && klu_tsolve(symbolic_, numeric_, n_, 1, x, &common_) == 1;
}

}  // namespace shizuku
