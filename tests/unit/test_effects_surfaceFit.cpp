// Tests of the leave-one-out surface fit and curvature (docs/method.md 8.2, 8.4) and of
// the surface-fitting shift, eq. (19) with its gates and sign (docs/method.md 8.1, 8.3).
#define BOOST_TEST_MODULE effects_surfaceFit
#include <boost/test/unit_test.hpp>
#include "effects/SurfaceFitting.hpp"
#include "surface/SurfaceFit.hpp"
#include "test_effects_fixture.hpp"
#include <iostream>

using namespace shizuku;
using namespace shizuku::testing;
namespace tt = boost::test_tools;

namespace {

// Slab periodic in x (and y in 3D): rows 0..top, free top row, vicinity within 2h of
// it, normals e_D for free and vicinity particles. Returns the index of the free
// particle at the middle of the top row.
template <int D>
std::size_t flatSurface(Fixture<D>& f, int width, int top) {
  std::size_t centre = 0;
  std::array<int, 3> lo{0, 0, 0}, hi{width - 1, width - 1, width - 1};
  lo[D - 1] = 0;
  hi[D - 1] = top;
  forBox<D>(lo, hi, [&](const std::array<int, 3>& idx) {
    const int depth = top - idx[D - 1];
    const SurfaceClass c = depth == 0 ? SurfaceClass::free : depth < 2.4 ? SurfaceClass::vicinity
                                                                          : SurfaceClass::interior;
    const std::size_t i = f.add(latticePoint<D>(idx, 1.0), ParticleType::fluid, c);
    if (c != SurfaceClass::interior) f.s.particles.normal[i] = Vec<D>::Unit(D - 1);
    bool middle = depth == 0;
    for (int k = 0; k < D - 1; ++k) middle = middle && idx[k] == width / 2;
    if (middle) centre = i;
  });
  for (int k = 0; k < D - 1; ++k) f.s.periodic.periodic[k] = true;
  f.s.periodic.lo = Vec<D>::Constant(-0.5);
  f.s.periodic.hi = Vec<D>::Constant(width - 0.5);
  return centre;
}

template <int D>
void checkDisplaced(double delta) {
  Fixture<D> f;
  const std::size_t c = flatSurface(f, D == 2 ? 20 : 10, 6);
  f.s.particles.position[c][D - 1] += delta;
  f.update();
  const auto detectorNormals = f.s.particles.normal;
  computeSurfaceFit(f.s);
  // Leave-one-out: the other free particles lie exactly on the plane, so s = delta and
  // n = e_D to round-off (measured |error| <= 1e-15).
  BOOST_TEST(f.s.fitDistance[c] == delta, tt::tolerance(1e-12));
  BOOST_TEST((f.s.fitNormal[c] - Vec<D>::Unit(D - 1)).norm() < 1e-12);
  // The detector's normals, which OPS projects with, are left as they were.
  for (std::size_t i = 0; i < f.s.size(); ++i) BOOST_TEST((f.s.particles.normal[i] - detectorNormals[i]).norm() == 0.0);
}

struct FittingOutcome {
  Vec<2> dr;
  double kappa, s;
};

FittingOutcome fittingShift(double delta, bool smoothing) {
  Fixture<2> f;
  const std::size_t c = flatSurface(f, 20, 6);
  f.s.particles.position[c].y() += delta;
  f.update();
  computeSurfaceFit(f.s);
  SurfaceFittingParameters p;
  p.smoothingSign = smoothing;
  SurfaceFitting<2> e(p);
  std::vector<Vec<2>> dr(f.s.size(), Vec<2>::Zero());
  e.addShift(f.s, dr);
  return {dr[c], f.s.curvature[c], f.s.fitDistance[c]};
}

}  // namespace

BOOST_AUTO_TEST_CASE(flat_surface_distance_and_normal_2d) {
  for (double delta : {0.1, 0.3, 0.8, -0.3}) checkDisplaced<2>(delta);
}

BOOST_AUTO_TEST_CASE(flat_surface_distance_and_normal_3d) {
  for (double delta : {0.1, 0.3, 0.8}) checkDisplaced<3>(delta);
}

BOOST_AUTO_TEST_CASE(undisturbed_surface_and_vicinity) {
  // Vicinity particles get s = -depth, free ones 0; all normals identical -> kappa = 0.
  Fixture<2> f;
  flatSurface(f, 20, 6);
  f.update();
  computeSurfaceFit(f.s);
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const double depth = 6 - f.s.particles.position[i].y();
    switch (f.s.surfaceClass(i)) {
      case SurfaceClass::free:
        BOOST_TEST(std::abs(f.s.fitDistance[i]) < 1e-12);
        BOOST_TEST(f.s.curvature[i] == 0.0);
        break;
      case SurfaceClass::vicinity: BOOST_TEST(f.s.fitDistance[i] == -depth, tt::tolerance(1e-12)); break;
      default:
        BOOST_TEST(std::isnan(f.s.fitDistance[i]));
        BOOST_TEST(std::isnan(f.s.curvature[i]));
    }
  }
}

BOOST_AUTO_TEST_CASE(quality_gate_rejects_a_blob) {
  // A 5x5 patch all flagged free: the neighbours do not lie on a line (eigenvalue
  // ratio ~1 > 0.3), so the centre is not fitted and keeps its normal.
  Fixture<2> f;
  std::size_t centre = 0;
  forBox<2>({0, 0, 0}, {4, 4, 0}, [&](const std::array<int, 3>& idx) {
    const std::size_t i = f.add(latticePoint<2>(idx, 1.0), ParticleType::fluid, SurfaceClass::free);
    f.s.particles.normal[i] = Vec<2>(1, 0);
    if (idx[0] == 2 && idx[1] == 2) centre = i;
  });
  f.update();
  computeSurfaceFit(f.s);
  BOOST_TEST(std::isnan(f.s.fitDistance[centre]));
  BOOST_TEST((f.s.fitNormal[centre] - Vec<2>(1, 0)).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(too_few_free_neighbours) {
  // Two free particles 1 d0 apart: each has one free neighbour (< D): no fit.
  Fixture<2> f;
  for (int k = 0; k < 2; ++k) {
    const std::size_t i = f.add(Vec<2>(k, 0), ParticleType::fluid, SurfaceClass::free);
    f.s.particles.normal[i] = Vec<2>(0, 1);
  }
  f.update();
  computeSurfaceFit(f.s);
  BOOST_TEST(std::isnan(f.s.fitDistance[0]));
  BOOST_TEST(std::isnan(f.s.fitDistance[1]));
}

BOOST_AUTO_TEST_CASE(fitting_shift_sign_and_gates) {
  const double Ch = 1e-4 * 1.2;
  // 0.3 d0 outside: inside the gates; smoothing moves it back toward the line by C h s.
  FittingOutcome o = fittingShift(0.3, true);
  std::cout << "displaced 0.3 d0: s = " << o.s << ", kappa d0 (factor 0.34) = " << o.kappa << ", dr = ("
            << o.dr.transpose() << ")\n";
  BOOST_TEST(o.dr.y() == -Ch * 0.3, tt::tolerance(1e-9));
  BOOST_TEST(std::abs(o.dr.x()) < 1e-15);
  // asPrinted: the literal eq. 19 moves it further out.
  o = fittingShift(0.3, false);
  BOOST_TEST(o.dr.y() == Ch * 0.3, tt::tolerance(1e-9));
  // 0.3 d0 inside: moved outward, toward the line.
  o = fittingShift(-0.3, true);
  BOOST_TEST(o.dr.y() == Ch * 0.3, tt::tolerance(1e-9));
  // Outside the distance band: not moved.
  BOOST_TEST(fittingShift(0.1, true).dr.norm() == 0.0);
  BOOST_TEST(fittingShift(0.8, true).dr.norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(curvature_gate) {
  // maxCurvature below the measured |kappa| of the 0.3 d0 bump switches the shift off.
  Fixture<2> f;
  const std::size_t c = flatSurface(f, 20, 6);
  f.s.particles.position[c].y() += 0.3;
  f.update();
  computeSurfaceFit(f.s);
  const double kappa = std::abs(f.s.curvature[c]);
  BOOST_TEST(kappa > 0);
  SurfaceFittingParameters p;
  p.maxCurvature = 0.9 * kappa;
  SurfaceFitting<2> e(p);
  std::vector<Vec<2>> dr(f.s.size(), Vec<2>::Zero());
  e.addShift(f.s, dr);
  BOOST_TEST(dr[c].norm() == 0.0);
  p.maxCurvature = 1.1 * kappa;
  SurfaceFitting<2> e2(p);
  e2.addShift(f.s, dr);
  BOOST_TEST(dr[c].norm() > 0.0);
}

BOOST_AUTO_TEST_CASE(disc_curvature_calibration) {
  // Lattice disc of radius R = 20 d0; free = lattice points inside with an axis
  // neighbour outside; vicinity within 2h; exact radial normals (as docs/method.md 8.4)
  // or fitted normals. Reported: the factor that makes kappa = 1/R, (d0/R) / mean sum.
  // Measured: exact normals: 112 free particles, mean sum 0.0529 (sd 0.021), factor
  // 0.945 (docs/method.md 8.4: 0.84-0.96); with the paper's 0.34, kappa R = 0.36.
  // Fitted normals follow the lattice staircase (the axis tips stick out by 1 d0, s = 1):
  // mean sum 0.30 (sd 1.19) dominated by the tips; the median is printed.
  const double R = 20;
  for (int fitted = 0; fitted < 2; ++fitted) {
    Fixture<2> f;
    auto inside = [&](int x, int y) { return double(x) * x + double(y) * y <= R * R; };
    forBox<2>({-21, -21, 0}, {21, 21, 0}, [&](const std::array<int, 3>& idx) {
      const int x = idx[0], y = idx[1];
      if (!inside(x, y)) return;
      const bool free = !inside(x + 1, y) || !inside(x - 1, y) || !inside(x, y + 1) || !inside(x, y - 1);
      const Vec<2> p = latticePoint<2>(idx, 1.0);
      const double depth = R - p.norm();
      const SurfaceClass c = free ? SurfaceClass::free : depth < 2.4 ? SurfaceClass::vicinity : SurfaceClass::interior;
      const std::size_t i = f.add(p, ParticleType::fluid, c);
      if (c != SurfaceClass::interior) f.s.particles.normal[i] = p.normalized();
    });
    f.update();
    if (fitted) computeSurfaceFit(f.s, SurfaceFitSettings{1.0});
    else f.s.fitNormal = f.s.particles.normal;  // curvatureSum reads the fit's normals
    std::vector<double> k;
    for (std::size_t i = 0; i < f.s.size(); ++i)
      if (f.s.surfaceClass(i) == SurfaceClass::free) k.push_back(curvatureSum(f.s, i));
    double sum = 0, sum2 = 0;
    for (double v : k) sum += v, sum2 += v * v;
    const double mean = sum / k.size(), sd = std::sqrt(sum2 / k.size() - mean * mean);
    std::nth_element(k.begin(), k.begin() + k.size() / 2, k.end());
    const double median = k[k.size() / 2];
    std::cout << "disc R = 20 d0, " << (fitted ? "fitted" : "exact") << " normals: " << k.size()
              << " free particles, curvature sum mean " << mean << " (sd " << sd << "), median " << median
              << "; factor for kappa = 1/R from the mean " << (1 / R) / mean << ", from the median "
              << (1 / R) / median << "; with 0.34: kappa R = " << 0.34 * mean * R << "\n";
    if (!fitted) {
      BOOST_TEST((1 / R) / mean > 0.85);
      BOOST_TEST((1 / R) / mean < 1.05);
    } else {
      BOOST_TEST(median > 0);  // convex
    }
  }
}
