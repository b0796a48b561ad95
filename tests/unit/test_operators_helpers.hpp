// Shared helpers of the operator tests: lattices with optional random
// disorder, neighbour lists and weights on them, error norms and least-squares
// convergence orders.
#pragma once
#include "kernels/Kernel.hpp"
#include "operators/Ops.hpp"
#include "particles/NeighbourList.hpp"
#include <cmath>
#include <random>
#include <vector>

namespace shizuku::testing {

// (n+1)^D lattice points on [0,L]^D with spacing d0 = L/n, each moved by a
// uniform random offset in [-eps d0, eps d0] per direction (fixed seed).
template <int D>
std::vector<Vec<D>> lattice(int n, double L, double eps, unsigned seed = 1234) {
  const double d0 = L / n;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-eps * d0, eps * d0);
  std::vector<Vec<D>> x;
  const int nz = D == 3 ? n : 0;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec<D> p;
        p[0] = i * d0;
        p[1] = j * d0;
        if constexpr (D == 3) p[2] = k * d0;
        if (eps > 0)
          for (int a = 0; a < D; ++a) p[a] += u(gen);
        x.push_back(p);
      }
  return x;
}

// Particles whose every coordinate lies in (lo, hi).
template <int D>
std::vector<std::uint8_t> inside(const std::vector<Vec<D>>& x, double lo, double hi) {
  std::vector<std::uint8_t> m(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) m[i] = (x[i].minCoeff() > lo && x[i].maxCoeff() < hi);
  return m;
}

// Everything needed to apply operators on a particle set.
template <int D>
struct Setup {
  std::vector<Vec<D>> x;
  Kernel<D> kernel;
  double d0 = 0, V = 0;
  NeighbourList<D> nl;
  PairWeights<D> pw;
  std::vector<std::uint8_t> mask;
  Setup(std::vector<Vec<D>> pts, double spacing, DerivativeScheme scheme, std::vector<std::uint8_t> computeFor,
        KernelType kt = KernelType::cubicSpline, double hRatio = 1.2)
      : x(std::move(pts)), kernel(kt, hRatio * spacing), d0(spacing), mask(std::move(computeFor)) {
    V = std::pow(d0, D);
    NeighbourSearch<D> search(kernel.support());
    search.build(x, nl);
    DerivativeOperator<D>::create(scheme)->computeWeights(kernel, V, nl, mask, pw);
  }
};

// Root mean square over the masked particles.
inline double rms(const std::vector<double>& e, const std::vector<std::uint8_t>& mask) {
  double s = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < e.size(); ++i)
    if (mask[i]) {
      s += e[i] * e[i];
      ++n;
    }
  return std::sqrt(s / double(n));
}

// Least-squares slope of log(error) against log(1/d0): the convergence order
// fitted over the whole sequence.
inline double fittedOrder(const std::vector<double>& d0, const std::vector<double>& err) {
  const std::size_t n = d0.size();
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < n; ++k) {
    mx += -std::log(d0[k]) / n;
    my += std::log(err[k]) / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = -std::log(d0[k]) - mx, dy = std::log(err[k]) - my;
    sxy += dx * dy;
    sxx += dx * dx;
  }
  return -sxy / sxx;
}

}  // namespace shizuku::testing
