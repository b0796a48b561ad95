// The AMG smoother's sweeps (linearSolvers/HybridGaussSeidel.hpp) on a random sparse matrix
// with couplings across the threads' row blocks and one zero diagonal, on 1, 2 and 3 threads:
// the sweep from zero (which stops each row at its diagonal and reads nothing outside its
// block) equals a full forward sweep on x = 0 bit for bit, and that sweep solves each row
// against the values of its own block only (Gauss-Seidel inside a block, Jacobi across).
#define BOOST_TEST_MODULE linearSolvers_hybridGaussSeidel
#include "linearSolvers/HybridGaussSeidel.hpp"
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <omp.h>
#include <random>

using namespace shizuku;

namespace {

struct Problem {
  SparseMatrixR A;
  std::vector<double> inv, b;
};

// Each row couples to 12 random columns anywhere (so every block reads the others);
// row 17 has no diagonal entry.
Problem randomProblem(int n) {
  std::mt19937 gen(5);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::uniform_real_distribution<double> value(0.1, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  Problem p;
  p.b.resize(n);
  p.inv.resize(n);
  for (int i = 0; i < n; ++i) {
    double sum = 0;
    for (int k = 0; k < 12; ++k) {
      const int j = column(gen);
      if (j == i) continue;
      const double v = value(gen);
      t.emplace_back(i, j, -v);
      sum += v;
    }
    const double d = i == 17 ? 0.0 : 1.5 * sum;
    if (d != 0) t.emplace_back(i, i, d);
    p.inv[i] = d != 0 ? 1.0 / d : 0.0;
    p.b[i] = value(gen) - 0.5;
  }
  p.A.resize(n, n);
  p.A.setFromTriplets(t.begin(), t.end());
  p.A.makeCompressed();
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_sweep_from_zero_is_a_hybrid_gauss_seidel_sweep) {
  const int n = 3001;
  const Problem p = randomProblem(n);
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    std::vector<double> x(n, 7.0), ref(n, 0.0), old(n);
    hybridGaussSeidel::sweepFromZero(p.A, p.inv.data(), p.b.data(), x.data(), true);
    hybridGaussSeidel::sweep(p.A, p.inv.data(), p.b.data(), ref.data(), old.data(), true, true);
    BOOST_TEST(x == ref);  // the same values, bit for bit (7.0 on entry is never read)
    // Row i of block [lo, hi): b_i - sum_{lo <= j <= i} a_ij x_j = 0 (zero diagonal: x_i = 0).
    double worst = 0, scale = 0;
    for (int t = 0; t < threads; ++t) {
      int lo, hi;
      hybridGaussSeidel::rowBlock(n, t, threads, lo, hi);
      for (int i = lo; i < hi; ++i) {
        double s = p.b[i];
        for (SparseMatrixR::InnerIterator it(p.A, i); it; ++it)
          if (it.col() >= lo && it.col() <= i) s -= it.value() * x[it.col()];
        if (p.inv[i] != 0) worst = std::max(worst, std::abs(s));
        else BOOST_TEST(x[i] == 0.0);
        scale = std::max(scale, std::abs(p.b[i]));
      }
    }
    BOOST_TEST_MESSAGE(threads << " threads: largest unsolved part of a row " << worst);
    BOOST_TEST(worst <= 1e-14 * scale);
  }
}
