// The advection stage's position update (docs/method.md 4.1, eqs. 7 and 7b;
// libsph/isph/PositionUpdate.hpp). Known answers, on a lattice block with the linear
// divergence-free velocity u = A x (tr A = 0), whose SPH(2) gradient is A to round-off:
//  - midpoint moves interior and vicinity particles by the Cayley map,
//    r' = (I - dt/2 A)^{-1} (I + dt/2 A) r, exactly; its determinant is 1 in 2D (areas kept)
//    and 1 + O(dt^3) in 3D;
//  - euler moves every particle by dt u, whose map has determinant det(I + dt A) =
//    1 + dt^2 det A in 2D: a strain compresses the fluid by dt^2 s^2 per step;
//  - free and splash particles take the Euler step under either rule;
//  - an extra advection velocity (XSPH's du) is moved with the same factor.
#define BOOST_TEST_MODULE isph_positionUpdate
#include <boost/test/unit_test.hpp>
#include "isph/PositionUpdate.hpp"
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;

namespace {

// A traceless velocity gradient: strain s along the axes plus a shear.
template <int D>
Mat<D> velocityGradient() {
  Mat<D> A = Mat<D>::Zero();
  A(0, 0) = 3.0;
  A(1, 1) = D == 2 ? -3.0 : -1.0;
  if (D == 3) A(2, 2) = -2.0;
  A(0, 1) = 1.5;
  A(1, 0) = -0.5;
  if (D == 3) A(2, 0) = 0.7;
  return A;
}

// A lattice block of 10^D fluid particles, spacing 1, velocity A r; the outer layer is
// classed free, the next vicinity, the rest interior (as a detector would see a blob).
template <int D>
Fixture<D> block(const Mat<D>& A) {
  Fixture<D> f;
  const int n = 10;
  forBox<D>({0, 0, 0}, {n - 1, n - 1, n - 1}, [&](const std::array<int, 3>& idx) {
    int depth = n;
    for (int a = 0; a < D; ++a) depth = std::min({depth, idx[a], n - 1 - idx[a]});
    const SurfaceClass c = depth == 0 ? SurfaceClass::free : depth == 1 ? SurfaceClass::vicinity : SurfaceClass::interior;
    const std::size_t i = f.add(latticePoint<D>(idx, 1.0), ParticleType::fluid, c);
    f.s.particles.velocity[i] = A * f.s.particles.position[i];
  });
  f.update();
  f.s.dt = 0.02;
  return f;
}

template <int D>
void check(typename PositionUpdate<D>::Rule rule, bool withExtraVelocity) {
  const bool isMidpoint = rule == PositionUpdate<D>::Rule::midpoint;
  const Mat<D> A = velocityGradient<D>();
  Fixture<D> f = block<D>(A);
  const double dt = f.s.dt;
  const auto before = f.s.particles.position;
  std::vector<Vec<D>> du;
  if (withExtraVelocity) du.assign(f.s.size(), Vec<D>::Zero());
  if (withExtraVelocity)
    for (std::size_t i = 0; i < du.size(); ++i) du[i] = 0.1 * (A * before[i]);  // u + du = 1.1 A r
  const double scale = withExtraVelocity ? 1.1 : 1.0;
  PositionUpdate<D> update(rule);
  update.allocate(f.s.size());
  update.move(f.s, du);
  const Mat<D> I = Mat<D>::Identity(), B = (0.5 * dt) * A;
  const Mat<D> cayley = I + (I - B).inverse() * (dt * scale) * A;  // r + dt (I - B)^{-1} (scale A r)
  const Mat<D> euler = I + (dt * scale) * A;
  double worst = 0;
  long midpointMoved = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const bool surface = f.s.surfaceClass(i) == SurfaceClass::free;
    const bool midpoint = isMidpoint && !surface;
    midpointMoved += midpoint;
    const Vec<D> expected = (midpoint ? cayley : euler) * before[i];
    worst = std::max(worst, (f.s.particles.position[i] - expected).norm());
  }
  BOOST_TEST_MESSAGE(D << "D, " << (isMidpoint ? "midpoint" : "euler") << (withExtraVelocity ? " with du" : "")
                       << ": largest |r' - expected| " << worst << ", det of the map "
                       << (isMidpoint ? cayley : euler).determinant());
  // Round-off: positions up to 9 d0, gradients exact to about 1e-13 (SPH2 on a lattice).
  BOOST_TEST(worst < 1e-12);
  BOOST_TEST((midpointMoved > 0) == isMidpoint);
}

}  // namespace

BOOST_AUTO_TEST_CASE(each_rule_moves_by_its_map) {
  for (bool du : {false, true}) {
    check<2>(PositionUpdate<2>::Rule::euler, du);
    check<2>(PositionUpdate<2>::Rule::midpoint, du);
    check<3>(PositionUpdate<3>::Rule::euler, du);
    check<3>(PositionUpdate<3>::Rule::midpoint, du);
  }
}

// The property that makes eq. 7b worth its gradient: the Cayley map of a traceless gradient
// keeps areas in 2D exactly and volumes in 3D to O(dt^3), where Euler's map changes them by
// dt^2 det A (2D) per step. Measured on the maps themselves (the check above ties the update
// to them): halving dt divides the 3D error by about 8.
BOOST_AUTO_TEST_CASE(the_midpoint_map_keeps_the_volume) {
  const Mat<2> A2 = velocityGradient<2>();
  const Mat<3> A3 = velocityGradient<3>();
  std::vector<double> err3;
  for (double dt : {0.02, 0.01}) {
    const Mat<2> B2 = 0.5 * dt * A2;
    const Mat<3> B3 = 0.5 * dt * A3;
    const double cayley2 = ((Mat<2>::Identity() - B2).inverse() * (Mat<2>::Identity() + B2)).determinant();
    const double euler2 = (Mat<2>::Identity() + dt * A2).determinant();
    const double cayley3 = ((Mat<3>::Identity() - B3).inverse() * (Mat<3>::Identity() + B3)).determinant();
    BOOST_TEST_MESSAGE("dt " << dt << ": 2D det " << cayley2 << " (Euler " << euler2 << "), 3D det " << cayley3);
    BOOST_TEST(std::abs(cayley2 - 1) < 1e-15);
    BOOST_TEST(euler2 - 1 == dt * dt * A2.determinant(), boost::test_tools::tolerance(1e-9));
    err3.push_back(std::abs(cayley3 - 1));
  }
  BOOST_TEST(err3[0] / err3[1] > 7.5);
}
