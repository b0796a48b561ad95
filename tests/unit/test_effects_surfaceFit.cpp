// Tests of the leave-one-out surface fit and curvature (docs/method.md 8.2, 8.4) and of
// the surface-fitting shift, eq. (19) with its gates and sign (docs/method.md 8.1, 8.3),
// in 2D and 3D. Known answers: a flat surface with one particle displaced by delta gives
// s = delta and n = e_D exactly, and the shift -C h s n; a blob, fewer than D points or (3D)
// collinear points are not fitted; the sum of eq. 20 with exact normals is the sum of the
// principal curvatures, 1/R on a disc, 2/R on a ball, 1/R on a cylinder, to within a bound
// from a resolution study; fitted normals on a ball are radial within a studied angle.
// The count gate (|Q| >= D) is never the deciding one: fewer than D points of Q always
// span less than a line (2D) or a plane (3D), which the eigenvalue gates reject anyway.
#define BOOST_TEST_MODULE effects_surfaceFit
#include <boost/test/unit_test.hpp>
#include "effects/SurfaceFitting.hpp"
#include "surface/SurfaceFit.hpp"
#include "test_surface_shapes.hpp"
#include <iostream>
#include <limits>

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
  forSlab<D>(width, 0, top, [&](const std::array<int, 3>& idx) {
    const int depth = top - idx[D - 1];
    const SurfaceClass c = depth == 0 ? SurfaceClass::free : depth < 2.4 ? SurfaceClass::vicinity
                                                                          : SurfaceClass::interior;
    const std::size_t i = f.add(latticePoint<D>(idx, 1.0), ParticleType::fluid, c);
    if (c != SurfaceClass::interior) f.s.particles.normal[i] = Vec<D>::Unit(D - 1);
    bool middle = depth == 0;
    for (int k = 0; k < D - 1; ++k) middle = middle && idx[k] == width / 2;
    if (middle) centre = i;
  });
  f.setPeriodicAlongSurface(width);
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

template <int D>
struct FittingOutcome {
  Vec<D> dr;
  double kappa, s;
};

template <int D>
FittingOutcome<D> fittingShift(double delta, bool smoothing) {
  Fixture<D> f;
  const std::size_t c = flatSurface(f, D == 2 ? 20 : 10, 6);
  f.s.particles.position[c][D - 1] += delta;
  f.update();
  computeSurfaceFit(f.s);
  SurfaceFittingParameters p;
  p.smoothingSign = smoothing;
  SurfaceFitting<D> e(p);
  std::vector<Vec<D>> dr(f.s.size(), Vec<D>::Zero());
  e.addShift(f.s, dr);
  return {dr[c], f.s.curvature[c], f.s.fitDistance[c]};
}

// The shift moves a displaced free particle along e_D by -C h s (smoothing) or +C h s
// (asPrinted), and not at all outside the distance band.
template <int D>
void checkFittingShift() {
  const double Ch = 1e-4 * 1.2;
  // 0.3 d0 outside: inside the gates; smoothing moves it back toward the line by C h s.
  FittingOutcome<D> o = fittingShift<D>(0.3, true);
  std::cout << D << "D displaced 0.3 d0: s = " << o.s << ", kappa d0 (factor 0.34) = " << o.kappa << ", dr = ("
            << o.dr.transpose() << ")\n";
  BOOST_TEST(o.dr[D - 1] == -Ch * 0.3, tt::tolerance(1e-9));
  BOOST_TEST(o.dr.head(D - 1).norm() < 1e-15);
  // asPrinted: the literal eq. 19 moves it further out.
  o = fittingShift<D>(0.3, false);
  BOOST_TEST(o.dr[D - 1] == Ch * 0.3, tt::tolerance(1e-9));
  // 0.3 d0 inside: moved outward, toward the line.
  o = fittingShift<D>(-0.3, true);
  BOOST_TEST(o.dr[D - 1] == Ch * 0.3, tt::tolerance(1e-9));
  // Outside the distance band: not moved.
  BOOST_TEST(fittingShift<D>(0.1, true).dr.norm() == 0.0);
  BOOST_TEST(fittingShift<D>(0.8, true).dr.norm() == 0.0);
}

// maxCurvature below the measured |kappa| of the 0.3 d0 bump switches the shift off,
// above it lets it act.
template <int D>
void checkCurvatureGate() {
  Fixture<D> f;
  const std::size_t c = flatSurface(f, D == 2 ? 20 : 10, 6);
  f.s.particles.position[c][D - 1] += 0.3;
  f.update();
  computeSurfaceFit(f.s);
  const double kappa = std::abs(f.s.curvature[c]);
  std::cout << D << "D bump 0.3 d0: |kappa| d0 = " << kappa << "\n";
  BOOST_TEST(kappa > 0);
  for (double ratio : {0.9, 1.1}) {
    SurfaceFittingParameters p;
    p.maxCurvature = ratio * kappa;
    SurfaceFitting<D> e(p);
    std::vector<Vec<D>> dr(f.s.size(), Vec<D>::Zero());
    e.addShift(f.s, dr);
    BOOST_TEST((dr[c].norm() > 0.0) == (ratio > 1), D << "D, maxCurvature " << ratio << " |kappa|");
  }
}

// Free particles at the given lattice sites (spacing d0), all with the outward normal n.
template <int D>
Fixture<D> freeParticles(const std::vector<Vec<D>>& x, const Vec<D>& n) {
  Fixture<D> f;
  for (const Vec<D>& p : x) {
    const std::size_t i = f.add(p, ParticleType::fluid, SurfaceClass::free);
    f.s.particles.normal[i] = n;
  }
  f.update();
  computeSurfaceFit(f.s);
  return f;
}

// A (2h)-block of free particles, 5^D: its points fill the block, so the eigenvalue
// ratio is about 1 > 0.3 and the centre is not fitted; it keeps the detector's normal.
template <int D>
void checkBlob() {
  std::vector<Vec<D>> x;
  forBox<D>({0, 0, 0}, {4, 4, 4}, [&](const std::array<int, 3>& idx) { x.push_back(latticePoint<D>(idx, 1.0)); });
  const Fixture<D> f = freeParticles<D>(x, Vec<D>::Unit(0));
  const std::size_t centre = x.size() / 2;  // (2, 2[, 2])
  BOOST_TEST((f.s.particles.position[centre] - Vec<D>::Constant(2)).norm() == 0.0);
  BOOST_TEST(std::isnan(f.s.fitDistance[centre]));
  BOOST_TEST((f.s.fitNormal[centre] - Vec<D>::Unit(0)).norm() == 0.0);
}

// Three free particles at a right-angled corner: each has 2 free neighbours. In 2D two
// points define the line (the corner's s is -(1/2, 1/2) . (1, 1)/sqrt 2 = -1/sqrt 2); in 3D
// they are fewer than D = 3 (and collinear), so nothing is fitted.
template <int D>
void checkTooFew() {
  const Vec<D> n = (Vec<D>::Unit(0) + Vec<D>::Unit(1)).normalized();
  const Fixture<D> f = freeParticles<D>({Vec<D>::Zero(), Vec<D>::Unit(0), Vec<D>::Unit(1)}, n);
  if (D == 2) {
    BOOST_TEST(f.s.fitDistance[0] == -1 / std::sqrt(2.0), tt::tolerance(1e-12));
    BOOST_TEST((f.s.fitNormal[0] - n).norm() < 1e-12);
  } else {
    for (std::size_t i = 0; i < 3; ++i) BOOST_TEST(std::isnan(f.s.fitDistance[i]));
  }
}

// Five free particles on a line along x (normal e_D): in 2D the middle one lies on the line
// fitted through the others (s = 0, n = e_D); in 3D they span no plane (the second
// eigenvalue is 0 < 0.05 of the largest) and nothing is fitted.
template <int D>
void checkCollinear() {
  std::vector<Vec<D>> x;
  for (int k = -2; k <= 2; ++k) x.push_back(double(k) * Vec<D>::Unit(0));
  const Fixture<D> f = freeParticles<D>(x, Vec<D>::Unit(D - 1));
  if (D == 2) {
    BOOST_TEST(std::abs(f.s.fitDistance[2]) < 1e-12);
    BOOST_TEST((f.s.fitNormal[2] - Vec<D>::Unit(D - 1)).norm() < 1e-12);
  } else {
    for (std::size_t i = 0; i < x.size(); ++i) BOOST_TEST(std::isnan(f.s.fitDistance[i]));
  }
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

BOOST_AUTO_TEST_CASE(quality_gate_rejects_a_blob_2d) { checkBlob<2>(); }

BOOST_AUTO_TEST_CASE(quality_gate_rejects_a_blob_3d) { checkBlob<3>(); }

BOOST_AUTO_TEST_CASE(too_few_free_neighbours_2d) {
  // Two free particles 1 d0 apart: each has one free neighbour (< D): no fit.
  const Fixture<2> f = freeParticles<2>({Vec<2>(0, 0), Vec<2>(1, 0)}, Vec<2>(0, 1));
  BOOST_TEST(std::isnan(f.s.fitDistance[0]));
  BOOST_TEST(std::isnan(f.s.fitDistance[1]));
  checkTooFew<2>();
}

BOOST_AUTO_TEST_CASE(too_few_free_neighbours_3d) { checkTooFew<3>(); }

BOOST_AUTO_TEST_CASE(collinear_free_neighbours_2d) { checkCollinear<2>(); }

BOOST_AUTO_TEST_CASE(collinear_free_neighbours_3d) { checkCollinear<3>(); }

BOOST_AUTO_TEST_CASE(fitting_shift_sign_and_gates_2d) { checkFittingShift<2>(); }

BOOST_AUTO_TEST_CASE(fitting_shift_sign_and_gates_3d) { checkFittingShift<3>(); }

BOOST_AUTO_TEST_CASE(curvature_gate_2d) { checkCurvatureGate<2>(); }

BOOST_AUTO_TEST_CASE(curvature_gate_3d) { checkCurvatureGate<3>(); }

namespace {

// Lattice ball (disc in 2D) or 3D cylinder of radius R (test_surface_shapes.hpp), a shell
// 5 d0 deep (the free particles' weights see 3.4 d0 deep at most): free = the axis layer,
// vicinity = the other particles shallower than 2h, detector normals exactly radial.
// Every fluid row takes the FI weights (SPH(2)), whose divergence of n is the one that
// converges to the curvature: the amplification bound of docs/method.md 3.4 is lifted, since
// a free surface's FI row exceeds it (19 times the kernel gradient in 2D, 59 in 3D) and the
// solver's free rows take first order, where the sum reads low (section 8.4).
template <int D>
Fixture<D> curvedBody(double R, bool cylinder) {
  const int length = 8;
  Fixture<D> f;
  f.thresholds.maxGradientAmplification = std::numeric_limits<double>::infinity();
  for (const BodySite& b : bodySites<D>(R, cylinder, length, 5.0)) {
    const SurfaceClass c = b.axisOutside ? SurfaceClass::free : b.depth < 2.4 ? SurfaceClass::vicinity
                                                                               : SurfaceClass::interior;
    const Vec<D> x = latticePoint<D>(b.idx, 1.0);
    const std::size_t i = f.add(x, ParticleType::fluid, c);
    if (c != SurfaceClass::interior) f.s.particles.normal[i] = curvedPart<D>(x, cylinder).normalized();
  }
  if (cylinder) periodicAxis(f, length);
  f.update();
  return f;
}

struct CurvatureSums {
  long count = 0;
  double mean = 0, sd = 0, median = 0;
};

// Statistics of the sum of eq. 20 (curvatureSum, no factor) over the free particles, with
// the normals in s.fitNormal.
template <int D>
CurvatureSums freeCurvatureSums(const FlowState<D>& s) {
  std::vector<double> k;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.surfaceClass(i) == SurfaceClass::free) k.push_back(curvatureSum(s, i));
  CurvatureSums c;
  c.count = long(k.size());
  double sum = 0, sum2 = 0;
  for (double v : k) sum += v, sum2 += v * v;
  c.mean = sum / k.size();
  c.sd = std::sqrt(sum2 / k.size() - c.mean * c.mean);
  std::nth_element(k.begin(), k.begin() + k.size() / 2, k.end());
  c.median = k[k.size() / 2];
  return c;
}

// Curvature with exact normals: the sum of eq. 20 without its factor is the SPH(2)
// divergence of n over the surface, which is the sum of the principal curvatures: (D - 1)/R
// on a ball, 1/R on a cylinder. Resolution study (2026-12-02), mean sum R / (D - 1) (on the
// cylinder: mean sum R):
//   R/d0            8        16       32       64
//   2D disc       1.2506   1.1081   1.0408   1.0326
//   3D ball       1.2063   1.0571   0.9860
//   3D cylinder   1.1144   1.0801   1.0292
// The error falls with R about as d0/R: error R/d0 = 2.00, 1.73, 1.31, 2.09 (disc), 1.65,
// 0.91, -0.45 (ball), 0.92, 1.28, 0.94 (cylinder). Bound: |error| < 3 d0/R (the largest,
// 2.09, is 0.70 of it), asserted at R = 8 and 16, and the error must fall from 8 to 16.
template <int D>
double curvatureError(double R, bool cylinder) {
  Fixture<D> f = curvedBody<D>(R, cylinder);
  f.s.fitNormal = f.s.particles.normal;  // curvatureSum reads the fit's normals
  const CurvatureSums c = freeCurvatureSums(f.s);
  const double exact = (cylinder ? 1.0 : D - 1.0) / R;
  const double error = c.mean / exact - 1;
  std::cout << D << "D " << (cylinder ? "cylinder" : "ball") << " R = " << R << " d0, exact normals: " << c.count
            << " free, mean sum / " << (cylinder ? "(1/R)" : "((D-1)/R)") << " = " << c.mean / exact << " (sd "
            << c.sd / exact << "), error R/d0 = " << error * R << "\n";
  BOOST_TEST(std::abs(error) < 3 / R, D << "D R = " << R << ": error " << error);
  return std::abs(error);
}

template <int D>
void checkCurvature(bool cylinder) {
  const double coarse = curvatureError<D>(8, cylinder), fine = curvatureError<D>(16, cylinder);
  BOOST_TEST(fine < coarse);
}

// The fit on a ball of radius 16 d0: every free particle is fitted (the quality gates pass
// on a smooth surface), its fitted normal is outward and radial within the angle of a
// resolution study (2026-12-02), max (rms) over the free particles in degrees:
//   R/d0            8             16            32
//   2D disc       15.8 (11.3)   19.4 (9.4)    21.4 (10.1)
//   3D ball       18.7 (10.0)   25.1 (8.9)    23.1 (9.5)
//   3D cylinder   17.6 (12.4)   16.3 (9.4)    19.0 (10.4)
// Bounds 35 (1.4 times the largest) and rms 15 (1.2 times). Curvature from the fitted
// normals follows the lattice staircase (test disc_curvature_calibration): only its sign,
// the median's, is asserted.
template <int D>
void checkFittedBall(double R) {
  Fixture<D> f = curvedBody<D>(R, false);
  computeSurfaceFit(f.s, SurfaceFitSettings{1.0});
  long free = 0, fitted = 0;
  double maxAngle = 0, sum2 = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (f.s.surfaceClass(i) != SurfaceClass::free) continue;
    ++free;
    if (std::isnan(f.s.fitDistance[i])) continue;
    ++fitted;
    const double a = angleDegrees<D>(f.s.fitNormal[i], f.s.particles.position[i]);
    maxAngle = std::max(maxAngle, a);
    sum2 += a * a;
  }
  const double rms = std::sqrt(sum2 / std::max(1L, fitted)), median = freeCurvatureSums(f.s).median;
  std::cout << D << "D ball R = " << R << " d0, fitted normals: " << fitted << " of " << free
            << " free fitted, angle to the radius max " << maxAngle << ", rms " << rms << " degrees; median sum R / (D-1) "
            << median * R / (D - 1) << "\n";
  BOOST_TEST(fitted == free);
  BOOST_TEST(maxAngle < 35.0);
  BOOST_TEST(rms < 15.0);
  BOOST_TEST(median > 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(disc_curvature_2d) { checkCurvature<2>(false); }

BOOST_AUTO_TEST_CASE(ball_curvature_3d) { checkCurvature<3>(false); }

BOOST_AUTO_TEST_CASE(cylinder_curvature_3d) { checkCurvature<3>(true); }

BOOST_AUTO_TEST_CASE(disc_fitted_normals_2d) { checkFittedBall<2>(16); }

BOOST_AUTO_TEST_CASE(ball_fitted_normals_3d) { checkFittedBall<3>(16); }

BOOST_AUTO_TEST_CASE(disc_curvature_calibration) {
  // Lattice disc of radius R = 20 d0; free = lattice points inside with an axis
  // neighbour outside; vicinity within 2h; exact radial normals (as docs/method.md 8.4)
  // or fitted normals. Reported: the factor that makes kappa = 1/R, (d0/R) / mean sum.
  // Measured: exact normals: 112 free particles, mean sum 0.0529 (sd 0.021), factor
  // 0.945 (docs/method.md 8.4: 0.84-0.96); with the paper's 0.34, kappa R = 0.36.
  // Fitted normals follow the lattice staircase (the axis tips stick out by 1 d0, s = 1):
  // mean sum 0.30 (sd 1.19) dominated by the tips; the median is printed. The factor
  // depends on the resolution (the error study above: 1/1.108 at R = 16, 1/1.041 at 32).
  const double R = 20;
  for (int fitted = 0; fitted < 2; ++fitted) {
    Fixture<2> f = curvedBody<2>(R, false);
    if (fitted) computeSurfaceFit(f.s, SurfaceFitSettings{1.0});
    else f.s.fitNormal = f.s.particles.normal;  // curvatureSum reads the fit's normals
    const CurvatureSums c = freeCurvatureSums(f.s);
    std::cout << "disc R = 20 d0, " << (fitted ? "fitted" : "exact") << " normals: " << c.count
              << " free particles, curvature sum mean " << c.mean << " (sd " << c.sd << "), median " << c.median
              << "; factor for kappa = 1/R from the mean " << (1 / R) / c.mean << ", from the median "
              << (1 / R) / c.median << "; with 0.34: kappa R = " << 0.34 * c.mean * R << "\n";
    if (!fitted) {
      BOOST_TEST((1 / R) / c.mean > 0.85);
      BOOST_TEST((1 / R) / c.mean < 1.05);
    } else {
      BOOST_TEST(c.median > 0);  // convex
    }
  }
}
