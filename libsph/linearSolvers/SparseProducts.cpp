// Row-parallel sparse products of the AMG setup (see SparseProducts.hpp).
#include "linearSolvers/SparseProducts.hpp"
#include <algorithm>
#include <omp.h>

namespace shizuku {

namespace {

// Results with fewer rows are built on one thread (fork and barrier cost more).
constexpr int kParallelRows = 8192;

// Builds the rows x width matrix `out` whose row i sums what visit(i, emit) emits with
// emit(column, value), each sum then replaced by finish(i, column, sum). One pass counts
// each row's distinct columns (a mark per column: the last row that met it), the second
// sums into a dense row (the first value assigned, the others added, as Eigen does) and
// writes the row sorted by column straight into `out`.
template <class Visit, class Finish>
void buildRows(int rows, int width, SparseMatrixR& out, const Visit& visit, const Finish& finish) {
  out.resize(rows, width);  // compressed, no entries
  int* outer = out.outerIndexPtr();
#pragma omp parallel if (rows > kParallelRows)
  {
    std::vector<int> mark(std::size_t(width), -1);
#pragma omp for schedule(static)
    for (int i = 0; i < rows; ++i) {
      int count = 0;
      visit(i, [&](int c, double) {
        if (mark[std::size_t(c)] != i) {
          mark[std::size_t(c)] = i;
          ++count;
        }
      });
      outer[i + 1] = count;
    }
  }
  outer[0] = 0;
  for (int i = 0; i < rows; ++i) outer[i + 1] += outer[i];
  out.resizeNonZeros(outer[rows]);
  int* col = out.innerIndexPtr();
  double* val = out.valuePtr();
#pragma omp parallel if (rows > kParallelRows)
  {
    std::vector<int> mark(std::size_t(width), -1);
    std::vector<double> sum(static_cast<std::size_t>(width));
#pragma omp for schedule(static)
    for (int i = 0; i < rows; ++i) {
      int* c = col + outer[i];
      int len = 0;
      visit(i, [&](int k, double v) {
        if (mark[std::size_t(k)] != i) {
          mark[std::size_t(k)] = i;
          sum[std::size_t(k)] = v;
          c[len++] = k;
        } else {
          sum[std::size_t(k)] += v;
        }
      });
      std::sort(c, c + len);
      for (int e = 0; e < len; ++e) val[outer[i] + e] = finish(i, c[e], sum[std::size_t(c[e])]);
    }
  }
}

const auto unchanged = [](int, int, double v) { return v; };

}  // namespace

void multiplySparse(const SparseMatrixR& X, const SparseMatrixR& Y, SparseMatrixR& out) {
  const int* xo = X.outerIndexPtr();
  const int* xc = X.innerIndexPtr();
  const double* xv = X.valuePtr();
  const int* yo = Y.outerIndexPtr();
  const int* yc = Y.innerIndexPtr();
  const double* yv = Y.valuePtr();
  const auto visit = [&](int i, const auto& emit) {
    for (int p = xo[i]; p < xo[i + 1]; ++p) {
      const int k = xc[p];
      const double x = xv[p];
      for (int q = yo[k]; q < yo[k + 1]; ++q) emit(yc[q], yv[q] * x);
    }
  };
  buildRows(int(X.rows()), int(Y.cols()), out, visit, unchanged);
}

void transposeSparse(const SparseMatrixR& X, SparseMatrixR& out) {
  const int rows = int(X.rows()), cols = int(X.cols());
  const int* xo = X.outerIndexPtr();
  const int* xc = X.innerIndexPtr();
  const double* xv = X.valuePtr();
  out.resize(cols, rows);
  int* outer = out.outerIndexPtr();
  for (int p = 0; p < xo[rows]; ++p) ++outer[xc[p] + 1];
  for (int c = 0; c < cols; ++c) outer[c + 1] += outer[c];
  out.resizeNonZeros(outer[cols]);
  std::vector<int> next(outer, outer + cols);
  int* col = out.innerIndexPtr();
  double* val = out.valuePtr();
  for (int i = 0; i < rows; ++i)
    for (int p = xo[i]; p < xo[i + 1]; ++p) {
      const int q = next[std::size_t(xc[p])]++;
      col[q] = i;
      val[q] = xv[p];
    }
}

void smoothedProlongator(const SparseMatrixR& A, const std::vector<double>& invDiag, const std::vector<int>& agg,
                         int numAggregates, double omega, SparseMatrixR& P) {
  const int* ao = A.outerIndexPtr();
  const int* ac = A.innerIndexPtr();
  const double* av = A.valuePtr();
  const double* inv = invDiag.data();
  // Row i: (A P0)_iK = sum of a_ij over j in aggregate K, times -omega/a_ii, plus P0's 1
  // in the row's own aggregate (added after the product, as Eigen's P0 + (A P0) adds it;
  // the +0 emitted for it changes no sum but makes the entry exist). An exact zero
  // stays an entry, as in Eigen's sum: the AMG prunes P.
  const auto visit = [&](int i, const auto& emit) {
    for (int p = ao[i]; p < ao[i + 1]; ++p) {
      const int K = agg[std::size_t(ac[p])];
      if (K >= 0) emit(K, av[p]);
    }
    if (agg[std::size_t(i)] >= 0) emit(agg[std::size_t(i)], 0.0);
  };
  const auto finish = [&](int i, int K, double v) {
    const double scale = -omega * inv[i];
    return K == agg[std::size_t(i)] ? 1.0 + v * scale : v * scale;
  };
  buildRows(int(A.rows()), numAggregates, P, visit, finish);
}

}  // namespace shizuku
