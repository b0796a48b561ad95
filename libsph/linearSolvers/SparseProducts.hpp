// Row-parallel sparse products of the AMG setup (docs/method.md 4.2): the smoothed
// prolongator P = (I - omega D^-1 A) P0 of an aggregation, the transpose R = P^T and
// the Galerkin coarse operator A_c = R (A P), the last without storing A P: each row of
// A P is formed where a row of R needs it and kept in a bounded per-thread cache, so the
// setup's peak holds A_c's rows and not the larger A P.
// Each result is built in two passes over its rows (how many columns each row has, then
// the columns and their values) straight into its compressed arrays: no temporaries
// beyond a dense row of the result's width per thread, where Eigen's products build, sort and copy their
// results on one thread. Every row is summed in the order Eigen sums it (its entries k
// in increasing column order, the first product assigned, the others added), so the
// results equal Eigen's products bit for bit, whatever the thread count.
// No dictionary keys.
#pragma once
#include <Eigen/Sparse>
#include <vector>

namespace shizuku {

using SparseMatrixR = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// out = R (A P), equal bit for bit to Eigen's R * (A * P) (structural zeros of
// cancellation kept, as Eigen's). The rows of A P live in a per-thread cache of at most
// `cacheEntries` entries (emptied when full; a row needed again is recomputed).
void galerkinProduct(const SparseMatrixR& R, const SparseMatrixR& A, const SparseMatrixR& P, SparseMatrixR& out,
                     std::size_t cacheEntries = std::size_t(1) << 18);

// out = X^T (rows sorted by column).
void transposeSparse(const SparseMatrixR& X, SparseMatrixR& out);

// P = P0 - omega D^-1 A P0 with P0 the aggregate indicator (row i: 1 in column agg[i],
// none when agg[i] < 0) and invDiag = D^-1: row i holds the aggregates of its row of A,
// P_iK = [K == agg_i] + (-omega invDiag_i) sum_{j in K} a_ij. Exact zeros stay entries
// (as in Eigen's P0 + A P0): prune them.
void smoothedProlongator(const SparseMatrixR& A, const std::vector<double>& invDiag, const std::vector<int>& agg,
                         int numAggregates, double omega, SparseMatrixR& P);

}  // namespace shizuku
