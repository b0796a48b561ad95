// Tests of the XSPH advection velocity (docs/method.md 10).
#define BOOST_TEST_MODULE effects_xsph
#include <boost/test/unit_test.hpp>
#include "effects/XSPH.hpp"
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;
namespace tt = boost::test_tools;

namespace {

// Rows 0..6 on 3 wall layers, x periodic over 10: free top row, vicinity rows 4-5.
void slab(Fixture<2>& f) {
  forBox<2>({0, -3, 0}, {9, 6, 0}, [&](const std::array<int, 3>& idx) {
    const bool wall = idx[1] < 0;
    const SurfaceClass c = wall ? SurfaceClass::interior : idx[1] == 6 ? SurfaceClass::free
                           : idx[1] >= 4 ? SurfaceClass::vicinity : SurfaceClass::interior;
    f.add(latticePoint<2>(idx, 1.0), wall ? ParticleType::wall : ParticleType::fluid, c);
  });
  f.s.periodic.periodic = {true, false};
  f.s.periodic.lo = Vec<2>(-0.5, 0);
  f.s.periodic.hi = Vec<2>(9.5, 0);
  f.update();
}

// The index of the particle at (x, y); every wall particle is given the velocity
// (5, 5) in u, which the XSPH sum over fluid neighbours must not see.
std::size_t particleAtWithMovingWalls(const Fixture<2>& f, std::vector<Vec<2>>& u, double x, double y) {
  std::size_t c = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const Vec<2> p = f.s.particles.position[i];
    if (p.y() == y && p.x() == x) c = i;
    if (f.s.particles.isWall(i)) u[i] = Vec<2>(5, 5);
  }
  return c;
}

}  // namespace

BOOST_AUTO_TEST_CASE(uniform_velocity_gives_zero) {
  Fixture<2> f;
  slab(f);
  std::vector<Vec<2>> u(f.s.size(), Vec<2>(3.0, -1.0)), du(f.s.size(), Vec<2>::Zero());
  XSPH<2> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  for (auto& d : du) BOOST_TEST(d.norm() == 0.0);
  BOOST_TEST(e.lastActionCount() == 30);  // 10 free + 20 vicinity
}

BOOST_AUTO_TEST_CASE(jump_pulls_toward_neighbour_mean) {
  // One free particle moving at (1, 0.5), everything else at rest (walls moving at
  // (5, 5) must not matter): du = -eps V sum_fluid W_ij u_i, i.e. toward the
  // neighbours' mean velocity 0, with the known magnitude.
  Fixture<2> f;
  slab(f);
  std::vector<Vec<2>> u(f.s.size(), Vec<2>::Zero()), du(f.s.size(), Vec<2>::Zero());
  const std::size_t c = particleAtWithMovingWalls(f, u, 4, 6);
  u[c] = Vec<2>(1, 0.5);
  XSPH<2> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  double shepard = 0;  // V sum of W over fluid neighbours of c
  for (Index k = f.s.neighbours.begin(c); k < f.s.neighbours.end(c); ++k)
    if (f.s.isFluid(f.s.neighbours.j[k])) shepard += f.s.V() * f.s.weights.w[k];
  const Vec<2> expected = -0.5 * shepard * u[c];
  BOOST_TEST((du[c] - expected).norm() < 1e-14);
  BOOST_TEST(du[c].dot(-u[c]) > 0);
  // Its free and vicinity neighbours are pulled along +u[c]; interior particles get nothing.
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (i == c) continue;
    if (f.s.particles.isFluid(i) && f.s.surfaceClass(i) == SurfaceClass::interior) BOOST_TEST(du[i].norm() == 0.0);
    if (f.s.particles.isWall(i)) BOOST_TEST(du[i].norm() == 0.0);
    if (f.s.particles.isFluid(i) && f.s.surfaceClass(i) != SurfaceClass::interior && du[i].norm() > 0)
      BOOST_TEST(du[i].dot(u[c]) > 0);
  }
}

BOOST_AUTO_TEST_CASE(interior_particles_untouched) {
  Fixture<2> f;
  slab(f);
  std::vector<Vec<2>> u(f.s.size()), du(f.s.size(), Vec<2>::Zero());
  for (std::size_t i = 0; i < f.s.size(); ++i) u[i] = Vec<2>(std::sin(f.s.particles.position[i].x()), 0.1 * i);
  XSPH<2> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const bool acted = f.s.particles.isFluid(i) && f.s.surfaceClass(i) != SurfaceClass::interior;
    if (!acted) BOOST_TEST(du[i].norm() == 0.0);
    else BOOST_TEST(du[i].norm() > 0.0);
  }
}

BOOST_AUTO_TEST_CASE(wall_neighbours_not_in_the_sum) {
  // A free particle in the first fluid row (wall neighbours within 2h), fluid at rest,
  // walls moving at (5, 5): du = 0.
  Fixture<2> f;
  slab(f);
  std::vector<Vec<2>> u(f.s.size(), Vec<2>::Zero()), du(f.s.size(), Vec<2>::Zero());
  const std::size_t c = particleAtWithMovingWalls(f, u, 4, 0);
  f.s.particles.surface[c] = std::uint8_t(SurfaceClass::free);
  bool hasWall = false;
  for (Index k = f.s.neighbours.begin(c); k < f.s.neighbours.end(c); ++k)
    hasWall = hasWall || !f.s.isFluid(f.s.neighbours.j[k]);
  BOOST_TEST(hasWall);
  XSPH<2> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  BOOST_TEST(du[c].norm() == 0.0);
}
