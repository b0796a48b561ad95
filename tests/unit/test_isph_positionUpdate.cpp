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
  f.s.uStar.resize(f.s.size());  // the midpoint rule's scratch, sized by the solver's set-up
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

// The property that makes eq. 7b worth its gradient, measured on the moved particles: the
// volume of the cell spanned by an interior particle and its D lattice neighbours along the
// axes, after one update, over its volume before. Known answers: midpoint 1 in 2D (exactly:
// the Cayley map of a traceless gradient), 1 + O(dt^3) in 3D (halving dt divides the error by
// about 8); Euler 1 + dt^2 det A in 2D.
template <int D>
double cellVolumeRatio(typename PositionUpdate<D>::Rule rule, double dt) {
  Fixture<D> f = block<D>(velocityGradient<D>());
  f.s.dt = dt;
  const auto before = f.s.particles.position;
  PositionUpdate<D> update(rule);
  update.allocate(f.s.size());
  update.move(f.s, {});
  // Particle indices on the 10^D block (x fastest): the corner (4, 4, 4) and its neighbours.
  const std::size_t i = D == 2 ? 44 : 444, stride[3] = {1, 10, 100};
  Mat<D> a, b;
  for (int k = 0; k < D; ++k) {
    a.col(k) = before[i + stride[k]] - before[i];
    b.col(k) = f.s.particles.position[i + stride[k]] - f.s.particles.position[i];
  }
  BOOST_REQUIRE(f.s.surfaceClass(i) == SurfaceClass::interior);
  return b.determinant() / a.determinant();
}

BOOST_AUTO_TEST_CASE(the_midpoint_update_keeps_the_volume) {
  using R2 = PositionUpdate<2>::Rule;
  using R3 = PositionUpdate<3>::Rule;
  const double dt = 0.02, det2 = velocityGradient<2>().determinant();
  const double mid2 = cellVolumeRatio<2>(R2::midpoint, dt), euler2 = cellVolumeRatio<2>(R2::euler, dt);
  const double mid3 = cellVolumeRatio<3>(R3::midpoint, dt), mid3half = cellVolumeRatio<3>(R3::midpoint, dt / 2);
  BOOST_TEST_MESSAGE("cell volume after one update / before: 2D midpoint " << mid2 << ", Euler " << euler2
                     << " (1 + dt^2 det A = " << 1 + dt * dt * det2 << "); 3D midpoint " << mid3 << ", at dt/2 "
                     << mid3half);
  BOOST_TEST(std::abs(mid2 - 1) < 1e-13);
  BOOST_TEST(euler2 - 1 == dt * dt * det2, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(std::abs(euler2 - 1) > 1e-3);  // the compression eq. 7b removes is not round-off
  BOOST_TEST((mid3 - 1) / (mid3half - 1) > 7.5);
  BOOST_TEST((mid3 - 1) / (mid3half - 1) < 8.5);
}
