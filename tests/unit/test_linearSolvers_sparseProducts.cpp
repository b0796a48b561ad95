// The AMG setup's row-parallel sparse products (libsph/linearSolvers/SparseProducts)
// against Eigen's own products, which they replace: X^T, the smoothed
// prolongator P0 - omega D^-1 A P0 and the Galerkin product R (A P) (formed without
// storing A P, also with a cache small enough to be emptied many times) must equal
// Eigen's results bit for bit (same
// pattern, same values: the AMG hierarchy and so every trajectory are unchanged), on
// one thread and on two, below and above the size at which rows are split between
// threads; and the prolongator of a matrix with zero row sums keeps constants
// (P 1 = 1 - omega D^-1 A 1 = 1), the property smoothed aggregation relies on.
#define BOOST_TEST_MODULE linearSolvers_sparseProducts
#include <boost/test/unit_test.hpp>
#include "linearSolvers/SparseProducts.hpp"
#include <omp.h>
#include <random>

using namespace shizuku;

namespace {

// rows x cols, each row with up to `perRow` entries at random columns (duplicates summed),
// values from a few levels so that some sums cancel exactly.
SparseMatrixR randomMatrix(int rows, int cols, int perRow, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_int_distribution<int> col(0, cols - 1), count(0, perRow);
  std::uniform_int_distribution<int> level(-4, 4);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < rows; ++i) {
    const int k = count(g);
    for (int e = 0; e < k; ++e) t.emplace_back(i, col(g), (e % 3 == 0) ? 0.25 * level(g) : u(g));
  }
  SparseMatrixR M(rows, cols);
  M.setFromTriplets(t.begin(), t.end());
  M.makeCompressed();
  return M;
}

// A 2D grid Laplacian with zero row sums (Neumann): rows of 5 points, diagonal 4 minus
// the missing neighbours.
SparseMatrixR neumannLaplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int r = j * n + i;
      int deg = 0;
      for (auto [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= n || jj >= n) continue;
        t.emplace_back(r, jj * n + ii, -1.0);
        ++deg;
      }
      t.emplace_back(r, r, double(deg));
    }
  SparseMatrixR A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// Aggregates of 2 x 2 grid blocks; every 11th row left out (-1), as rows with no coupling are.
std::vector<int> blockAggregates(int n, int& numAggregates) {
  std::vector<int> agg(std::size_t(n) * n);
  const int m = (n + 1) / 2;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) agg[std::size_t(j * n + i)] = (j / 2) * m + i / 2;
  numAggregates = m * m;
  return agg;
}

// The prolongator as the AMG built it with Eigen's products.
SparseMatrixR eigenProlongator(const SparseMatrixR& A, const std::vector<double>& inv, const std::vector<int>& agg,
                               int nc, double omega) {
  const int n = int(A.rows());
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    if (agg[std::size_t(i)] >= 0) t.emplace_back(i, agg[std::size_t(i)], 1.0);
  SparseMatrixR P0(n, nc);
  P0.setFromTriplets(t.begin(), t.end());
  SparseMatrixR AP0 = A * P0;
  for (int i = 0; i < n; ++i)
    for (SparseMatrixR::InnerIterator it(AP0, i); it; ++it) it.valueRef() *= -omega * inv[std::size_t(i)];
  SparseMatrixR P = P0 + AP0;
  P.prune(0.0);
  P.makeCompressed();
  return P;
}

// Same shape, same pattern, same values bit for bit.
void requireIdentical(const SparseMatrixR& a, const SparseMatrixR& b) {
  BOOST_REQUIRE_EQUAL(a.rows(), b.rows());
  BOOST_REQUIRE_EQUAL(a.cols(), b.cols());
  BOOST_REQUIRE_EQUAL(a.nonZeros(), b.nonZeros());
  int patternDiffers = 0, valueDiffers = 0;
  for (int i = 0; i <= a.rows(); ++i) patternDiffers += a.outerIndexPtr()[i] != b.outerIndexPtr()[i];
  for (int p = 0; p < a.nonZeros(); ++p) {
    patternDiffers += a.innerIndexPtr()[p] != b.innerIndexPtr()[p];
    valueDiffers += a.valuePtr()[p] != b.valuePtr()[p];
  }
  BOOST_CHECK_EQUAL(patternDiffers, 0);
  BOOST_CHECK_EQUAL(valueDiffers, 0);
}

const int kThreads[] = {1, 2};

}  // namespace

BOOST_AUTO_TEST_CASE(galerkin_product_equals_eigens_bit_for_bit) {
  // Coarse rows on one thread, and split between threads; ten fine rows per coarse one,
  // so that many products meet in each entry of A P and of A_c (summation order matters).
  for (int rows : {300, 10000})
    for (int threads : kThreads) {
      omp_set_num_threads(threads);
      const int fine = 10 * rows;
      const SparseMatrixR A = randomMatrix(fine, fine, 14, 3u + unsigned(rows));
      const SparseMatrixR P = randomMatrix(fine, rows, 6, 4u + unsigned(rows));
      const SparseMatrixR R = SparseMatrixR(P.transpose());
      const SparseMatrixR AP = A * P;
      const SparseMatrixR expected = R * AP;
      for (std::size_t cache : {std::size_t(1) << 18, std::size_t(64), std::size_t(1)}) {
        BOOST_TEST_CONTEXT("rows " << rows << ", threads " << threads << ", cache " << cache) {
          SparseMatrixR mine;
          galerkinProduct(R, A, P, mine, cache);
          requireIdentical(mine, expected);
        }
      }
    }
}

BOOST_AUTO_TEST_CASE(transpose_equals_eigens) {
  const SparseMatrixR X = randomMatrix(5000, 700, 9, 7u);
  SparseMatrixR mine;
  transposeSparse(X, mine);
  SparseMatrixR eigen = X.transpose();
  eigen.makeCompressed();
  requireIdentical(mine, eigen);
}

BOOST_AUTO_TEST_CASE(prolongator_equals_eigens_and_keeps_constants) {
  const double omega = 2.0 / 3.0;
  for (int n : {20, 120})  // 400 and 14400 rows
    for (int threads : kThreads) {
      omp_set_num_threads(threads);
      SparseMatrixR A = neumannLaplacian(n);
      int nc = 0;
      std::vector<int> agg = blockAggregates(n, nc);
      std::vector<double> inv(std::size_t(n) * n);
      for (int i = 0; i < n * n; ++i) inv[std::size_t(i)] = 1.0 / A.coeff(i, i);
      SparseMatrixR mine;
      smoothedProlongator(A, inv, agg, nc, omega, mine);
      mine.prune(0.0);
      BOOST_TEST_CONTEXT("n " << n << ", threads " << threads) {
        requireIdentical(mine, eigenProlongator(A, inv, agg, nc, omega));
        const Eigen::VectorXd ones = mine * Eigen::VectorXd::Ones(nc);
        BOOST_CHECK_SMALL((ones.array() - 1.0).abs().maxCoeff(), 1e-14);
      }
      // Rows left out of the aggregation (agg = -1) and a random matrix's rows.
      for (int i = 0; i < n * n; i += 11) agg[std::size_t(i)] = -1;
      const SparseMatrixR B = randomMatrix(n * n, n * n, 10, 3u) + A;
      for (int i = 0; i < n * n; ++i) inv[std::size_t(i)] = B.coeff(i, i) != 0 ? 1.0 / B.coeff(i, i) : 0.0;
      smoothedProlongator(B, inv, agg, nc, omega, mine);
      mine.prune(0.0);
      BOOST_TEST_CONTEXT("random rows, n " << n << ", threads " << threads)
      requireIdentical(mine, eigenProlongator(B, inv, agg, nc, omega));
    }
}
