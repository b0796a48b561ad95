// Row-parallel sparse products of the AMG setup (see SparseProducts.hpp).
#include "linearSolvers/SparseProducts.hpp"
#include <algorithm>
#include <memory>
#include <omp.h>

namespace shizuku {

namespace {

// Products over fewer rows of the fine operator are built on one thread (fork and
// barrier cost more).
constexpr int kParallelRows = 8192;

// Builds the rows x width matrix `out` whose row i sums what visit(i, emit) emits with
// emit(column, value), each sum then replaced by finish(i, column, sum). One pass counts
// each row's distinct columns (a mark per column: the last row that met it), the second
// sums into a dense row (the first value assigned, the others added, as Eigen does) and
// writes the row sorted by column straight into `out`.
// Rows are split between threads when `parallel`.
template <class Visit, class Finish>
void buildRows(int rows, int width, SparseMatrixR& out, const Visit& visit, const Finish& finish, bool parallel) {
  out.resize(rows, width);  // compressed, no entries
  int* outer = out.outerIndexPtr();
#pragma omp parallel if (parallel)
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
#pragma omp parallel if (parallel)
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

namespace {
// Rows of A P formed on demand, in the order and with the sums the product A P sums them
// (entries of A's row in column order, each times P's row; the first value assigned, the
// others added; the row sorted by column), kept until the arena is full. The rows are
// found through a direct-mapped table indexed by the row number's low bits (a thread's
// rows of R reach a narrow band of rows of A P, so its rows rarely share a slot, and a
// row displaced from its slot is formed again when needed).
struct ProductRowCache {
  static constexpr int kSlots = 1 << 15;
  const SparseMatrixR& A;
  const SparseMatrixR& P;
  std::size_t limit;
  std::vector<int> key, stamp, start, length;  // per slot: row key, arena generation `stamp`
  std::vector<int> cols;
  std::vector<double> vals;
  std::vector<int> mark;  // per column of P: the last row formed that met it
  std::vector<double> sum;
  std::vector<int> found;
  int generation = 0, formed = 0;

  ProductRowCache(const SparseMatrixR& a, const SparseMatrixR& p, std::size_t cap)
      : A(a), P(p), limit(std::max<std::size_t>(cap, 1)), key(kSlots, -1), stamp(kSlots, -1), start(kSlots),
        length(kSlots), mark(std::size_t(p.cols()), -1), sum(std::size_t(p.cols())) {}

  // Row i of A P: its columns and values.
  std::pair<const int*, const double*> row(int i, int& len) {
    const std::size_t slot = std::size_t(i) & (kSlots - 1);
    if (key[slot] != i || stamp[slot] != generation) form(i, slot);
    len = length[slot];
    const std::size_t b = std::size_t(start[slot]);
    return {cols.data() + b, vals.data() + b};
  }

  void form(int i, std::size_t slot) {
    const int* ao = A.outerIndexPtr();
    const int* ac = A.innerIndexPtr();
    const double* av = A.valuePtr();
    const int* po = P.outerIndexPtr();
    const int* pc = P.innerIndexPtr();
    const double* pv = P.valuePtr();
    const int tag = formed++;
    found.clear();
    for (int p = ao[i]; p < ao[i + 1]; ++p) {
      const int k = ac[p];
      const double x = av[p];
      for (int q = po[k]; q < po[k + 1]; ++q) {
        const int c = pc[q];
        const double v = pv[q] * x;
        if (mark[std::size_t(c)] != tag) {
          mark[std::size_t(c)] = tag;
          sum[std::size_t(c)] = v;
          found.push_back(c);
        } else {
          sum[std::size_t(c)] += v;
        }
      }
    }
    std::sort(found.begin(), found.end());
    if (!cols.empty() && cols.size() + found.size() > limit) {  // full: start a new generation
      cols.clear();
      vals.clear();
      ++generation;
    }
    key[slot] = i;
    stamp[slot] = generation;
    start[slot] = int(cols.size());
    length[slot] = int(found.size());
    for (int c : found) {
      cols.push_back(c);
      vals.push_back(sum[std::size_t(c)]);
    }
  }
};
}  // namespace

void galerkinProduct(const SparseMatrixR& R, const SparseMatrixR& A, const SparseMatrixR& P, SparseMatrixR& out,
                     std::size_t cacheEntries) {
  const int* ro = R.outerIndexPtr();
  const int* rc = R.innerIndexPtr();
  const double* rv = R.valuePtr();
  const int rows = int(R.rows());
  // The work is that of A P's rows: parallel by the fine level's size.
  const bool parallel = A.rows() > kParallelRows;
  const int threads = parallel ? omp_get_max_threads() : 1;
  std::vector<std::unique_ptr<ProductRowCache>> caches(std::size_t(std::max(threads, 1)));
  const auto visit = [&](int I, const auto& emit) {
    auto& cache = caches[std::size_t(omp_get_thread_num()) % caches.size()];
    if (!cache) cache = std::make_unique<ProductRowCache>(A, P, cacheEntries);
    for (int p = ro[I]; p < ro[I + 1]; ++p) {
      const double x = rv[p];
      int len = 0;
      const auto [c, v] = cache->row(rc[p], len);
      for (int e = 0; e < len; ++e) emit(c[e], v[e] * x);
    }
  };
  buildRows(rows, int(P.cols()), out, visit, unchanged, parallel);
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
  buildRows(int(A.rows()), numAggregates, P, visit, finish, A.rows() > kParallelRows);
}

}  // namespace shizuku
