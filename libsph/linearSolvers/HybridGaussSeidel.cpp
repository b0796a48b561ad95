// Gauss-Seidel sweeps of the AMG smoother, interior rows by block in parallel and interface
// rows after them (see HybridGaussSeidel.hpp).
#include "linearSolvers/HybridGaussSeidel.hpp"
#include <algorithm>
#include <omp.h>

namespace shizuku {
namespace hybridGaussSeidel {

namespace {

struct Rows {
  const int* outer;
  const int* col;
  const double* val;
  explicit Rows(const SparseMatrixR& A) : outer(A.outerIndexPtr()), col(A.innerIndexPtr()), val(A.valuePtr()) {}
  // Every entry of row i in [lo, hi) (columns ascend: its first and last decide).
  bool interior(int i, int lo, int hi) const {
    const int b = outer[i], e = outer[i + 1];
    return b == e || (col[b] >= lo && col[e - 1] < hi);
  }
  // x_i from every other entry of the row at x's current values.
  void solve(int i, const double* inv, const double* b, double* x) const {
    double s = b[i];
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (col[p] != i) s -= val[p] * x[col[p]];
    x[i] = s * inv[i];
  }
  // x_i from the entries before the diagonal only (the rest multiply zeros).
  void solveFromZero(int i, const double* inv, const double* b, double* x) const {
    double s = b[i];
    for (int p = outer[i]; p < outer[i + 1] && col[p] < i; ++p) s -= val[p] * x[col[p]];
    x[i] = s * inv[i];
  }
};

// Runs block(lo, hi) on each of the `threads` blocks, the blocks in parallel. The blocks are
// those the interface rows were found for even if the runtime grants fewer threads (a
// thread then takes several blocks, which share no interior row).
template <class Block>
void inBlocks(int n, int threads, Block&& block) {
#pragma omp parallel num_threads(threads)
  for (int t = omp_get_thread_num(); t < threads; t += omp_get_num_threads()) {
    int lo, hi;
    rowBlock(n, t, threads, lo, hi);
    block(lo, hi);
  }
}

}  // namespace

void interfaceRows(const SparseMatrixR& A, int threads, std::vector<int>& rows) {
  rows.clear();
  if (threads <= 1) return;
  const Rows R(A);
  const int n = int(A.rows());
  for (int t = 0; t < threads; ++t) {
    int lo, hi;
    rowBlock(n, t, threads, lo, hi);
    for (int i = lo; i < hi; ++i)
      if (!R.interior(i, lo, hi)) rows.push_back(i);
  }
}

void sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, const std::vector<int>& interface,
           int threads, bool forward) {
  const Rows R(A);
  const int n = int(A.rows());
  if (threads <= 1) {
    if (forward)
      for (int i = 0; i < n; ++i) R.solve(i, inv, b, x);
    else
      for (int i = n - 1; i >= 0; --i) R.solve(i, inv, b, x);
    return;
  }
  auto interiors = [&](int lo, int hi) {
    if (forward) {
      for (int i = lo; i < hi; ++i)
        if (R.interior(i, lo, hi)) R.solve(i, inv, b, x);
    } else {
      for (int i = hi - 1; i >= lo; --i)
        if (R.interior(i, lo, hi)) R.solve(i, inv, b, x);
    }
  };
  if (forward) {
    inBlocks(n, threads, interiors);
    for (const int i : interface) R.solve(i, inv, b, x);
  } else {
    for (auto it = interface.rbegin(); it != interface.rend(); ++it) R.solve(*it, inv, b, x);
    inBlocks(n, threads, interiors);
  }
}

// An interior row reads only its block: its entries before the diagonal are interior rows
// already solved or interface rows, which are zeroed first; the interface rows then read
// every value, the later interface rows' still zero.
void sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x,
                   const std::vector<int>& interface, int threads) {
  const Rows R(A);
  const int n = int(A.rows());
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) R.solveFromZero(i, inv, b, x);
    return;
  }
  for (const int i : interface) x[i] = 0;
  inBlocks(n, threads, [&](int lo, int hi) {
    for (int i = lo; i < hi; ++i)
      if (R.interior(i, lo, hi)) R.solveFromZero(i, inv, b, x);
  });
  for (const int i : interface) R.solve(i, inv, b, x);
}

bool interfaceOrderPays(std::size_t interfaceRows, int n, int threads) {
  return double(interfaceRows) * double(threads - 1) <= 0.2 * double(n);
}

void sweepAcrossBlocks(const SparseMatrixR& A, const double* inv, const double* b, double* x, double* old,
                       int threads, bool forward) {
  const Rows R(A);
  const int n = int(A.rows());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int i = 0; i < n; ++i) old[i] = x[i];
  inBlocks(n, threads, [&](int lo, int hi) {
    // Columns ascend: a row's entries before its block (old values), in it (current values,
    // the diagonal skipped) and after it (old values).
    auto row = [&](int i) {
      double s = b[i];
      int p = R.outer[i];
      const int e = R.outer[i + 1];
      for (; p < e && R.col[p] < lo; ++p) s -= R.val[p] * old[R.col[p]];
      for (; p < e && R.col[p] < hi; ++p)
        if (R.col[p] != i) s -= R.val[p] * x[R.col[p]];
      for (; p < e; ++p) s -= R.val[p] * old[R.col[p]];
      x[i] = s * inv[i];
    };
    if (forward)
      for (int i = lo; i < hi; ++i) row(i);
    else
      for (int i = hi - 1; i >= lo; --i) row(i);
  });
}

void sweepFromZeroAcrossBlocks(const SparseMatrixR& A, const double* inv, const double* b, double* x, int threads) {
  const Rows R(A);
  inBlocks(int(A.rows()), threads, [&](int lo, int hi) {
    for (int i = lo; i < hi; ++i) {
      double s = b[i];
      int p = R.outer[i];
      const int e = R.outer[i + 1];
      while (p < e && R.col[p] < lo) ++p;
      for (; p < e && R.col[p] < i; ++p) s -= R.val[p] * x[R.col[p]];
      x[i] = s * inv[i];
    }
  });
}

void ThreadSplit::prepare(const SparseMatrixR& A, int threads) {
  threads_ = std::max(1, threads);
  interfaceRows(A, threads_, interface_);
  acrossBlocks_ = !interfaceOrderPays(interface_.size(), int(A.rows()), threads_);
  if (acrossBlocks_) old_.resize(std::size_t(A.rows()));
  // Where each row's entries after the diagonal start, and the rows that need the whole row.
  const int n = int(A.rows());
  const Rows R(A);
  upper_.resize(std::size_t(n));
  if (acrossBlocks_) {  // every row reads values from before the sweep: the whole row
    std::fill(upper_.begin(), upper_.end(), -1);
    return;
  }
  std::vector<char>& isInterface = interfaceMask_;
  isInterface.assign(std::size_t(n), 0);
  for (const int i : interface_) isInterface[std::size_t(i)] = 1;
#pragma omp parallel for schedule(static) if (n > 2048)
  for (int i = 0; i < n; ++i) {
    int p = R.outer[i];
    const int e = R.outer[i + 1];
    bool whole = isInterface[std::size_t(i)];
    for (; p < e && R.col[p] < i; ++p) whole = whole || isInterface[std::size_t(R.col[p])];
    // A zero or missing diagonal: the sweep set x_i = 0 without solving the row.
    whole = whole || !(p < e && R.col[p] == i && R.val[p] != 0);
    upper_[std::size_t(i)] = whole ? -1 : p + 1;
  }
}

void ThreadSplit::residualAfterSweepFromZero(const SparseMatrixR& A, const double* b, const double* x, double* r,
                                             bool parallel) const {
  const Rows R(A);
  const int n = int(A.rows());
#pragma omp parallel for schedule(static) if (parallel)
  for (int i = 0; i < n; ++i) {
    const int u = upper_[std::size_t(i)];
    double s;
    if (u < 0) {
      s = b[i];
      for (int p = R.outer[i]; p < R.outer[i + 1]; ++p) s -= R.val[p] * x[R.col[p]];
    } else {
      s = 0;
      for (int p = u; p < R.outer[i + 1]; ++p) s -= R.val[p] * x[R.col[p]];
    }
    r[i] = s;
  }
}

void ThreadSplit::sweep(const SparseMatrixR& A, const double* inv, const double* b, double* x, bool forward) const {
  if (acrossBlocks_) sweepAcrossBlocks(A, inv, b, x, old_.data(), threads_, forward);
  else hybridGaussSeidel::sweep(A, inv, b, x, interface_, threads_, forward);
}

void ThreadSplit::sweepFromZero(const SparseMatrixR& A, const double* inv, const double* b, double* x) const {
  if (acrossBlocks_) sweepFromZeroAcrossBlocks(A, inv, b, x, threads_);
  else hybridGaussSeidel::sweepFromZero(A, inv, b, x, interface_, threads_);
}

}  // namespace hybridGaussSeidel
}  // namespace shizuku
