// Tests of the XSPH advection velocity (docs/method.md 10), in 2D and 3D, on a fluid slab
// over three wall layers, periodic along the wall: free top row, vicinity rows below it.
// Known answers: a uniform velocity gives du = 0; one free particle moving at u_c among
// fluid at rest gets du = -epsilon V sum_fluid W_ij u_c (the kernel sum recomputed here
// by brute force), toward the neighbours' mean; interior particles and walls get nothing;
// wall neighbours (moving at (5, 5, 5) here) are not in the sum.
#define BOOST_TEST_MODULE effects_xsph
#include <boost/test/unit_test.hpp>
#include "effects/XSPH.hpp"
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;
namespace tt = boost::test_tools;

namespace {

constexpr int kWidth = 10;  // sites along each periodic direction

// Rows 0..6 on 3 wall layers, periodic along the wall over kWidth: free top row,
// vicinity rows 4-5.
template <int D>
void slab(Fixture<D>& f) {
  forSlab<D>(kWidth, -3, 6, [&](const std::array<int, 3>& idx) {
    const int z = idx[D - 1];
    const bool wall = z < 0;
    const SurfaceClass c = wall ? SurfaceClass::interior : z == 6 ? SurfaceClass::free
                           : z >= 4 ? SurfaceClass::vicinity : SurfaceClass::interior;
    f.add(latticePoint<D>(idx, 1.0), wall ? ParticleType::wall : ParticleType::fluid, c);
  });
  f.setPeriodicAlongSurface(kWidth);
  f.update();
}

// The index of the particle at the middle of the periodic directions and height z; every
// wall particle is given the velocity (5, 5[, 5]) in u, which the XSPH sum over fluid
// neighbours must not see.
template <int D>
std::size_t particleAtWithMovingWalls(const Fixture<D>& f, std::vector<Vec<D>>& u, double z) {
  Vec<D> x = Vec<D>::Constant(kWidth / 2);
  x[D - 1] = z;
  std::size_t c = f.s.size();
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if ((f.s.particles.position[i] - x).norm() == 0) c = i;
    if (f.s.particles.isWall(i)) u[i] = Vec<D>::Constant(5);
  }
  BOOST_REQUIRE(c < f.s.size());
  return c;
}

// V sum_j W(|x_c - x_j|) over the fluid particles j != c, by brute force (minimum image).
template <int D>
double fluidKernelSum(const FlowState<D>& s, std::size_t c) {
  double sum = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double r = s.periodic.difference(s.particles.position[c], s.particles.position[j]).norm();
    if (j != c && s.particles.isFluid(j) && r < s.kernel.support()) sum += s.V() * s.kernel.w(r);
  }
  return sum;
}

template <int D>
void checkUniform() {
  Fixture<D> f;
  slab(f);
  Vec<D> u0 = Vec<D>::Constant(-1.0);
  u0[0] = 3.0;
  std::vector<Vec<D>> u(f.s.size(), u0), du(f.s.size(), Vec<D>::Zero());
  XSPH<D> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  for (auto& d : du) BOOST_TEST(d.norm() == 0.0);
  BOOST_TEST(e.lastActionCount() == 3 * std::pow(kWidth, D - 1));  // the free row and 2 vicinity rows
}

// One free particle moving at (1, 0.5[, -0.25]), everything else at rest (walls moving at
// (5, 5[, 5]) must not matter): du = -eps V sum_fluid W_ij u_c, toward the neighbours'
// mean velocity 0. Its free and vicinity neighbours are pulled along +u_c; interior
// particles and walls get nothing.
template <int D>
void checkJump() {
  Fixture<D> f;
  slab(f);
  std::vector<Vec<D>> u(f.s.size(), Vec<D>::Zero()), du(f.s.size(), Vec<D>::Zero());
  const std::size_t c = particleAtWithMovingWalls(f, u, 6);
  u[c] = Vec<D>::Zero();
  u[c][0] = 1;
  u[c][1] = 0.5;
  if (D == 3) u[c][D - 1] = -0.25;
  XSPH<D> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  const Vec<D> expected = -0.5 * fluidKernelSum(f.s, c) * u[c];
  BOOST_TEST((du[c] - expected).norm() < 1e-14);
  BOOST_TEST(du[c].dot(-u[c]) > 0);
  long pulled = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (i == c) continue;
    const bool acted = f.s.particles.isFluid(i) && f.s.surfaceClass(i) != SurfaceClass::interior;
    if (!acted) BOOST_TEST(du[i].norm() == 0.0);
    if (!acted || du[i].norm() == 0) continue;
    BOOST_TEST(du[i].dot(u[c]) > 0);
    ++pulled;
  }
  BOOST_TEST(pulled > 0);
}

template <int D>
void checkInteriorUntouched() {
  Fixture<D> f;
  slab(f);
  std::vector<Vec<D>> u(f.s.size()), du(f.s.size(), Vec<D>::Zero());
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    u[i] = Vec<D>::Constant(0.1 * i);
    u[i][0] = std::sin(f.s.particles.position[i].x());
  }
  XSPH<D> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const bool acted = f.s.particles.isFluid(i) && f.s.surfaceClass(i) != SurfaceClass::interior;
    if (!acted) BOOST_TEST(du[i].norm() == 0.0);
    else BOOST_TEST(du[i].norm() > 0.0);
  }
}

// A free particle in the first fluid row (wall neighbours within 2h), fluid at rest,
// walls moving: du = 0.
template <int D>
void checkWallNeighbours() {
  Fixture<D> f;
  slab(f);
  std::vector<Vec<D>> u(f.s.size(), Vec<D>::Zero()), du(f.s.size(), Vec<D>::Zero());
  const std::size_t c = particleAtWithMovingWalls(f, u, 0);
  f.s.particles.surface[c] = std::uint8_t(SurfaceClass::free);
  bool hasWall = false;
  for (Index k = f.s.neighbours.begin(c); k < f.s.neighbours.end(c); ++k)
    hasWall = hasWall || !f.s.isFluid(f.s.neighbours.j[k]);
  BOOST_TEST(hasWall);
  XSPH<D> e(0.5);
  e.addAdvectionVelocity(f.s, u, du);
  BOOST_TEST(du[c].norm() == 0.0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(uniform_velocity_gives_zero_2d) { checkUniform<2>(); }

BOOST_AUTO_TEST_CASE(uniform_velocity_gives_zero_3d) { checkUniform<3>(); }

BOOST_AUTO_TEST_CASE(jump_pulls_toward_neighbour_mean_2d) { checkJump<2>(); }

BOOST_AUTO_TEST_CASE(jump_pulls_toward_neighbour_mean_3d) { checkJump<3>(); }

BOOST_AUTO_TEST_CASE(interior_particles_untouched_2d) { checkInteriorUntouched<2>(); }

BOOST_AUTO_TEST_CASE(interior_particles_untouched_3d) { checkInteriorUntouched<3>(); }

BOOST_AUTO_TEST_CASE(wall_neighbours_not_in_the_sum_2d) { checkWallNeighbours<2>(); }

BOOST_AUTO_TEST_CASE(wall_neighbours_not_in_the_sum_3d) { checkWallNeighbours<3>(); }
