// A KLU factorisation (SuiteSparse, through its C interface) of a compressed row-major
// matrix, for the direct KLU backend (DirectSolvers.cpp) and the AMG's coarsest level
// (docs/method.md 4.2). The row-major (CSR) arrays, read as compressed columns, are A^T,
// which KLU factors; the transposed solve then gives A x = b with no copy. The symbolic
// analysis (fill-reducing ordering) can be kept while the sparsity pattern equals the last
// one. A solve allocates nothing (KLU's workspace lives in the numeric factor).
// Reads no dictionary keys.
#pragma once
#include "linearSolvers/Preconditioner.hpp"
#include <klu.h>
#include <vector>

namespace shizuku {

// Remembers the pattern of the last matrix; same() compares without allocating once the
// buffers have their capacity.
class PatternMemo {
 public:
  bool same(const SparseMatrixR& A) const;
  void remember(const SparseMatrixR& A);
  void forget() {
    outer_.clear();
    inner_.clear();
  }

 private:
  std::vector<int> outer_, inner_;
};

class KLUFactor {
 public:
  KLUFactor() { klu_defaults(&common_); }
  ~KLUFactor() { release(); }
  KLUFactor(const KLUFactor&) = delete;
  KLUFactor& operator=(const KLUFactor&) = delete;

  // Factor A (square, compressed). keepAnalysis: reuse the last symbolic analysis while the
  // pattern is unchanged. Returns an empty string on success, else what failed.
  const char* factor(const SparseMatrixR& A, bool keepAnalysis);
  // x <- A^-1 x (after a successful factor). Returns false if KLU reports a failure.
  bool solveInPlace(double* x) const;

 private:
  void release();
  int n_ = 0;
  mutable klu_common common_;  // KLU records each call's status in it
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  PatternMemo memo_;
};

}  // namespace shizuku
