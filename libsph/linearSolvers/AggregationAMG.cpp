// Smoothed-aggregation AMG preconditioner (see AggregationAMG.hpp for the method).
#include "linearSolvers/AggregationAMG.hpp"
#include "linearSolvers/HybridGaussSeidel.hpp"
#include "linearSolvers/SparseProducts.hpp"
#include "core/Log.hpp"
#include "core/types.hpp"
#include <string>
#include <cmath>
#include <omp.h>

namespace shizuku {

namespace {

// Strength of connection, row by row (scale-free: wall rows are O(1), fluid rows
// O(1/h^2)): j is a strong neighbour of i when |a_ij| >= kStrength max_k |a_ik|. A
// row whose off-diagonal mass is below kDominance |a_ii| is solved by the smoother
// alone and has no strong neighbour. Measured on 3D tanks (15k and 80k unknowns,
// about 36 entries per row; BiCGSTAB to 1e-8, one thread) and 2D dam breaks
// (6k, 21k): the symmetric test |a_ij| >= 0.08 sqrt(a_ii a_jj) never finds a wall
// row's couplings strong, and 3D aggregation then stalls (80k: 80148 -> 3592 ->
// ... 2053 rows, 4.2 s per solve); row-wise 0.25 coarsens 80148 -> 3592 -> 319.
// On the K&O 20k systems (2D, 23k unknowns, 18 entries a row; 2 threads, omega 2/3)
// 0.15 and 0.35 solve as fast: 8.4 and 8.7 against 8.6 ms, 6 iterations each.
constexpr double kStrength = 0.25;
constexpr double kDominance = 0.1;
// The smoothed prolongator keeps, in each row, the entries of at least kTruncation
// times the row's largest, rescaled to the row's old sum (constants stay exact).
// Untruncated, a 3D stencil of ~60 neighbours makes A_c = R A P dense (15k: operator
// complexity 5.2, coarse rows of 770 entries); truncated 1.2 (15k: 345 -> 40 ms per
// solve; 80k: 4.2 s -> 0.44 s, 7 iterations). 0.3 gives 9 iterations at 80k. In 2D
// (K&O 20k, 2 threads) 0.1 and 0.3 solve as fast, none doubles the iterations; the
// symmetric strength test with the untruncated prolongator, which 2D used before,
// made the second level 3861 rows of 38 entries (operator complexity 1.40 against
// 1.13) and a solve 1.4-1.6 times slower for one iteration fewer.
constexpr double kTruncation = 0.2;
// Prolongation smoothing, 4/3 / rho(D^-1 A): the textbook rho ~ 2 gives 2/3, but these
// PPEs have rho nearer 1.5-1.8. Measured (BiCGSTAB to 1e-8, iterations and ms per solve):
// K&O 20k from rest 6 -> 5 (2 threads 8.5-9.2 -> 7.4-7.8 ms), the flowing dam break at
// maxCo 0.2 9.05 -> 8.5 (20.8 -> 16.8 ms), 3D-100k 8 -> 5.75 (three passes: 11.1 -> 6,
// one thread 241 -> 179 ms);
// 0.9 takes 12 on the flowing dam break, and omega from a power-iteration estimate of rho
// per level (0.90, 0.74) 6 from rest.
constexpr double kOmega = 0.8;
constexpr int kSweeps = 1;            // Gauss-Seidel sweeps before and after
// Levels smaller than this run on one thread: a parallel region's fork and barrier
// cost more than the work, and on a shared machine every barrier can wait for a
// descheduled thread. Measured on the K&O 20k systems (2 threads, levels 23018 -> 2600
// -> 310 rows; bench_pressure, three alternating runs): 8192 rows and 65536 entries
// (the second level on one thread) 7.5-7.7 ms a solve, 2048 and 32768 6.6-6.9, 1024 and
// 16384 6.6-7.0, 256 and 4096 6.7-7.0; the iterations are the same (5).
constexpr int kParallelRows = 2048;
// Row-wise products (residual, restriction, prolongation) go parallel by their
// entries instead: their rows are independent, so the result is the same on any
// number of threads, and a coarse level's restriction holds several times more
// entries per row than the finest level's matrix.
constexpr long kParallelEntries = 32768;
constexpr int kCoarsest = 400;    // dense LU at or below this size
constexpr int kMaxLevels = 12;

void diagonal(const SparseMatrixR& A, std::vector<double>& d) {
  const int n = int(A.rows());
  d.assign(std::size_t(n), 0.0);
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (int i = 0; i < n; ++i)
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (col[p] == i) d[i] = val[p];
}

// Aggregates of the strong-coupling graph; -1 for rows left out (no strong coupling).
// threshold and first are scratch (kept by the caller between setups).
int aggregate(const SparseMatrixR& A, const std::vector<double>& d, std::vector<int>& agg,
              std::vector<double>& threshold, std::vector<int>& first) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* col = A.innerIndexPtr();
  const double* val = A.valuePtr();
  threshold.resize(n);  // |a_ij| at or above is strong
  for (int i = 0; i < n; ++i) {
    double largest = 0, mass = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (col[p] != i) {
        largest = std::max(largest, std::abs(val[p]));
        mass += std::abs(val[p]);
      }
    threshold[i] = mass < kDominance * std::abs(d[i]) ? HUGE_VAL : kStrength * largest;
  }
  auto strong = [&](int i, int p) { return col[p] != i && std::abs(val[p]) >= threshold[i]; };
  // -2: not yet aggregated, -1: isolated (never on a coarse grid).
  agg.assign(n, -2);
  for (int i = 0; i < n; ++i) {
    bool any = false;  // any off-diagonal entry at all (p = 0 rows have none)
    for (int p = outer[i]; p < outer[i + 1] && !any; ++p) any = col[p] != i && val[p] != 0;
    if (!any) agg[i] = -1;
  }
  int nc = 0;
  // 1. Roots whose strong neighbours are all free take them.
  for (int i = 0; i < n; ++i) {
    if (agg[i] != -2) continue;
    bool free = true;
    for (int p = outer[i]; p < outer[i + 1] && free; ++p)
      if (strong(i, p) && agg[col[p]] >= 0) free = false;
    if (!free) continue;
    agg[i] = nc;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (strong(i, p) && agg[col[p]] == -2) agg[col[p]] = nc;
    ++nc;
  }
  // 2. Leftovers join the aggregate of their strongest aggregated neighbour.
  first = agg;
  for (int i = 0; i < n; ++i) {
    if (agg[i] != -2) continue;
    double best = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (col[p] != i && first[col[p]] >= 0 && std::abs(val[p]) > best) {
        best = std::abs(val[p]);
        agg[i] = first[col[p]];
      }
  }
  // 3. Whatever is left forms aggregates of its own.
  for (int i = 0; i < n; ++i) {
    if (agg[i] != -2) continue;
    agg[i] = nc;
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (strong(i, p) && agg[col[p]] == -2) agg[col[p]] = nc;
    ++nc;
  }
  return nc;
}

// Drops the entries of each row of P below kTruncation of the row's largest and
// rescales the rest to the row's old sum. A row keeps the entry of its own aggregate
// whatever its size (unless it is exactly zero). In a coarse level's rows, whose
// off-diagonal entries have both signs, the smoothing can move most of a row's weight to
// neighbouring aggregates; dropping the own entry in every member row emptied that
// aggregate's column of P, and A_c = R A P had a zero row and column (measured: the noShift
// dam break at H/60, the coarsest KLU failing in 5 steps of 4176, each solved by the direct
// fallback).
void truncate(SparseMatrixR& P, const std::vector<int>& agg) {
  for (int i = 0; i < int(P.rows()); ++i) {
    double largest = 0, sum = 0, kept = 0;
    for (SparseMatrixR::InnerIterator it(P, i); it; ++it) {
      largest = std::max(largest, std::abs(it.value()));
      sum += it.value();
    }
    for (SparseMatrixR::InnerIterator it(P, i); it; ++it) {
      if (it.col() != agg[i] && std::abs(it.value()) < kTruncation * largest) it.valueRef() = 0;
      else kept += it.value();
    }
    if (kept != 0)
      for (SparseMatrixR::InnerIterator it(P, i); it; ++it) it.valueRef() *= sum / kept;
  }
}

// y = M x over all rows (parallel).
void spmv(const SparseMatrixR& M, const double* x, double* y) {
  const int n = int(M.rows());
  const int* outer = M.outerIndexPtr();
  const int* col = M.innerIndexPtr();
  const double* val = M.valuePtr();
#pragma omp parallel for schedule(static) if (M.nonZeros() > kParallelEntries)
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int p = outer[i]; p < outer[i + 1]; ++p) s += val[p] * x[col[p]];
    y[i] = s;
  }
}

}  // namespace

std::string AggregationAMG::describe() const {
  return cat("AMG (smoothed aggregation, Gauss-Seidel V-cycle", reuse_ > 1 ? cat(", hierarchy kept up to ", reuse_, " steps") : "",
             ")");
}

void AggregationAMG::solved(int iterations) {
  if (correcting_) {
    correcting_ = false;
    return;
  }
  if (sinceSetup_ == 1) setupIterations_ = iterations;
  else if (iterations > 1.5 * setupIterations_ + 2) stale_ = true;
}

double AggregationAMG::operatorComplexity() const {
  if (levels_.empty() || !fine_) return 1;
  double nnz = double(fine_->nonZeros());
  for (std::size_t l = 1; l < levels_.size(); ++l) nnz += double(levels_[l].A.nonZeros());
  return nnz / double(fine_->nonZeros());
}

bool AggregationAMG::setup(const SparseMatrixR& A) {
  fine_ = &A;
  failure_.clear();
  const int n = int(A.rows());
  if (correcting_ && !stale_ && n == n_ && !levels_.empty()) {
    // the hierarchy of this step's first solve serves its correction as it is
  } else if (stale_ || n != n_ || sinceSetup_ >= reuse_ || levels_.empty()) {
    const bool built = build(A);
    correcting_ = false;  // a rebuilt hierarchy counts its solve as any other
    n_ = n;
    stale_ = !built;  // a failed coarsest factorisation: rebuild at the next setup
    sinceSetup_ = 1;
    ++setups_;
  } else {
    ++sinceSetup_;
  }
  // The finest level smooths with this step's matrix; every level finds its split between
  // this solve's threads.
  Level& L0 = levels_[0];
  const bool diagonalOk = invertDiagonal(A, L0.invDiag.data(), 0.0);
  if (!diagonalOk) failure_ = "AMG setup failed: a zero or non-finite diagonal in the matrix";
  const bool ok = diagonalOk && !stale_;
  const int threads = omp_get_max_threads();
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    const SparseMatrixR& M = l == 0 ? A : levels_[l].A;
    levels_[l].split.prepare(M, M.rows() > kParallelRows ? threads : 1);
  }
  return ok;
}

// The levels are rebuilt in place: each keeps the storage of its matrices and vectors
// from the last setup (reallocated only where a level grew), so a setup does not free
// and reallocate the hierarchy and the heap does not fragment from one setup to the next.
bool AggregationAMG::build(const SparseMatrixR& A) {
  levels_.reserve(kMaxLevels + 1);  // references to levels stay valid while they are added
  if (levels_.empty()) levels_.emplace_back();
  const SparseMatrixR* cur = &A;
  for (int l = 0;; ++l) {
    Level& L = levels_[std::size_t(l)];
    const int n = int(cur->rows());
    diagonal(*cur, diag_);
    L.invDiag.resize(n);
    for (int i = 0; i < n; ++i) L.invDiag[i] = diag_[i] != 0 ? 1.0 / diag_[i] : 0.0;
    // Level 0's right-hand side and solution are the caller's vectors (apply).
    for (auto* v : {&L.x, &L.b}) v->assign(l == 0 ? 0 : n, 0.0);
    L.r.assign(n, 0.0);
    const int nc = (n <= kCoarsest || l + 1 >= kMaxLevels) ? 0 : aggregate(*cur, diag_, agg_, threshold_, firstAgg_);
    if (nc == 0 || nc > 0.9 * n) {
      // Coarsest level, solved exactly (rows left out of aggregation are identity-like
      // and solved here too).
      L.P = SparseMatrixR();
      L.R = SparseMatrixR();
      levels_.resize(std::size_t(l) + 1);
      coarsestRows_ = n;
      coarsestStalled_ = n > kCoarsest;
      const char* klu = coarse_.factor(*cur, false);
      if (*klu != '\0') failure_ = cat("AMG setup failed: level ", l, " of ", n, " rows: ", klu);
      return *klu == '\0';
    }
    smoothedProlongator(*cur, L.invDiag, agg_, nc, kOmega, L.P);
    truncate(L.P, agg_);
    L.P.prune(0.0);
    transposeSparse(L.P, L.R);
    if (levels_.size() < std::size_t(l) + 2) levels_.emplace_back();
    SparseMatrixR& Ac = levels_[std::size_t(l) + 1].A;
    galerkinProduct(L.R, *cur, L.P, Ac);
    Ac.prune(0.0);
    cur = &Ac;
  }
}

void AggregationAMG::cycle(int l, const SparseMatrixR& A, const double* bp, double* xp) const {
  const Level& L = levels_[l];
  const int n = int(A.rows());
  if (l + 1 == int(levels_.size())) {
    std::copy(bp, bp + n, xp);
    coarse_.solveInPlace(xp);
    return;
  }
  double* x = xp;
  L.split.sweepFromZero(A, L.invDiag.data(), bp, x);
  // r = b - A x (from the entries the sweep from zero did not use where that is exact), restricted.
  static_assert(kSweeps == 1, "the residual is taken right after the one sweep from zero");
  L.split.residualAfterSweepFromZero(A, bp, x, L.r.data(), A.nonZeros() > kParallelEntries);
  const Level& C = levels_[l + 1];
  spmv(L.R, L.r.data(), C.b.data());
  cycle(l + 1, C.A, C.b.data(), C.x.data());
  // x += P x_c.
  {
    const int* outer = L.P.outerIndexPtr();
    const int* col = L.P.innerIndexPtr();
    const double* val = L.P.valuePtr();
    const double* xc = C.x.data();
#pragma omp parallel for schedule(static) if (L.P.nonZeros() > kParallelEntries)
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int p = outer[i]; p < outer[i + 1]; ++p) s += val[p] * xc[col[p]];
      x[i] += s;
    }
  }
  for (int k = 0; k < kSweeps; ++k) L.split.sweep(A, L.invDiag.data(), bp, x, false);
}

void AggregationAMG::apply(const double* r, double* z) const { cycle(0, *fine_, r, z); }

}  // namespace shizuku
