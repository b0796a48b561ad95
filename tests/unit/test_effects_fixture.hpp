// Test helpers for the shifting effects: lattice particle sets and a FlowState
// filled the way the solver fills it at the start of a step (neighbour list,
// SPH(2) weights for fluid particles, summation density), with surface classes
// and normals set by the test. Cubic spline, h = 1.2 d0, rho0 = 1000, mass
// calibrated on the d0 lattice (docs/method.md 2).
#pragma once
#include "operators/DerivativeOperator.hpp"
#include "operators/FlowState.hpp"
#include "particles/NeighbourList.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace shizuku::testing {

template <int D>
struct Fixture {
  FlowState<D> s;
  double d0 = 1.0;
  FallbackThresholds thresholds;  // of the SPH(2) weights update() computes

  explicit Fixture(double spacing = 1.0, double hRatio = 1.2) : d0(spacing) {
    s.d0 = d0;
    s.h = hRatio * d0;
    s.kernel = Kernel<D>(KernelType::cubicSpline, s.h);
    s.rho0 = 1000;
    s.dt = 1e-4;
    s.particles.rho0 = s.rho0;
    s.particles.spacing = d0;
    s.particles.mass = s.rho0 / s.kernel.latticeSum(d0);
  }

  std::size_t add(const Vec<D>& x, ParticleType t = ParticleType::fluid,
                  SurfaceClass c = SurfaceClass::interior) {
    auto& p = s.particles;
    p.position.push_back(x);
    p.velocity.push_back(Vec<D>::Zero());
    p.pressure.push_back(0);
    p.density.push_back(0);
    p.type.push_back(std::uint8_t(t));
    p.surface.push_back(std::uint8_t(c));
    p.id.push_back(std::int64_t(p.id.size()));
    p.normal.push_back(Vec<D>::Zero());
    return p.position.size() - 1;
  }

  // Neighbour list, SPH(2) weights (fluid particles), density.
  void update() {
    const std::size_t n = s.size();
    s.isFluidMask.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.isFluidMask[i] = s.particles.isFluid(i) ? 1 : 0;
    NeighbourSearch<D> search(s.kernel.support(), s.periodic);
    search.build(s.particles.position, s.neighbours);
    auto op = DerivativeOperator<D>::create(DerivativeScheme::SPH2, thresholds);
    op->computeWeights(s.kernel, s.V(), s.neighbours, s.isFluidMask, s.weights);
    s.computeDensity();
  }

  // Periodic in every direction over [lo, hi).
  void setPeriodic(const Vec<D>& lo, const Vec<D>& hi) {
    for (int a = 0; a < D; ++a) s.periodic.periodic[a] = true;
    s.periodic.lo = lo;
    s.periodic.hi = hi;
  }

  // Periodic along a surface normal to e_D: the first D - 1 directions, over
  // [-a/2, (width - 1/2) a) (`width` lattice sites of spacing a).
  void setPeriodicAlongSurface(int width, double a = 1.0) {
    for (int k = 0; k < D - 1; ++k) s.periodic.periodic[k] = true;
    s.periodic.lo = Vec<D>::Constant(-0.5 * a);
    s.periodic.hi = Vec<D>::Constant((width - 0.5) * a);
  }

  // x += dr for every particle (wrapped if periodic).
  void move(const std::vector<Vec<D>>& dr) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      s.particles.position[i] += dr[i];
      if (s.periodic.any()) s.periodic.wrap(s.particles.position[i]);
    }
  }

  // Standard deviation of <rho>/rho0 over fluid particles.
  double densityStd() const {
    double sum = 0, sum2 = 0;
    long n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!s.particles.isFluid(i)) continue;
      const double r = s.particles.density[i] / s.rho0;
      sum += r;
      sum2 += r * r;
      ++n;
    }
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  }

  // Positions moved, same pairs: the density (as the solver does; W and r_ij follow the
  // positions by themselves).
  void refresh() {
    s.computeDensity();
  }
};

// Integer lattice index -> position (spacing a).
template <int D>
Vec<D> latticePoint(const std::array<int, 3>& idx, double a) {
  Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = a * idx[k];
  return x;
}

// Calls f(index triple) for every point of the box [lo, hi] (inclusive) of integers.
template <int D, class F>
void forBox(const std::array<int, 3>& lo, const std::array<int, 3>& hi, F&& f) {
  const int z0 = D == 3 ? lo[2] : 0, z1 = D == 3 ? hi[2] : 0;
  for (int z = z0; z <= z1; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) f(std::array<int, 3>{x, y, z});
}

// Calls f(index triple) for every site of a slab: [0, width - 1] along the first D - 1
// directions, [z0, z1] along e_D.
template <int D, class F>
void forSlab(int width, int z0, int z1, F&& f) {
  std::array<int, 3> lo{0, 0, 0}, hi{width - 1, width - 1, width - 1};
  lo[D - 1] = z0;
  hi[D - 1] = z1;
  forBox<D>(lo, hi, f);
}

inline std::mt19937& rng() {
  static std::mt19937 g(12345);
  return g;
}

}  // namespace shizuku::testing
