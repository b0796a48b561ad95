// Tests of ADS (docs/method.md 9): pairs closer than d_ADS are restored in one Jacobi
// application, walls and interior particles are not moved, a lattice at spacing d0
// is untouched.
#define BOOST_TEST_MODULE effects_ads
#include <boost/test/unit_test.hpp>
#include "effects/ADS.hpp"
#include <algorithm>
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;
namespace tt = boost::test_tools;

namespace {

template <int D>
void apply(Fixture<D>& f, ADS<D>& e) {
  f.update();
  e.allocate(f.s);
  e.correctPositions(f.s);
}

template <int D>
double dist(const Fixture<D>& f, std::size_t a, std::size_t b) {
  return (f.s.particles.position[a] - f.s.particles.position[b]).norm();
}

}  // namespace

BOOST_AUTO_TEST_CASE(free_pair_restored_to_d0) {
  for (double C : {1.0, 0.5}) {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::fluid, SurfaceClass::free);
    f.add(Vec<2>(0.48, 0.64), ParticleType::fluid, SurfaceClass::vicinity);  // 0.8 d0 apart
    ADS<2> e(1.0, C);
    apply(f, e);
    // Each takes half of d0 - 0.8 along the pair axis: exact up to round-off (1e-16).
    BOOST_TEST(dist(f, 0, 1) == 0.8 + C * 0.2, tt::tolerance(1e-12));
    BOOST_TEST(e.lastActionCount() == 2);
  }
}

BOOST_AUTO_TEST_CASE(free_pair_3d_and_distance_keyword) {
  Fixture<3> f;
  f.add(Vec<3>(0, 0, 0), ParticleType::fluid, SurfaceClass::free);
  f.add(Vec<3>(0.5, 0.5, 0.5), ParticleType::fluid, SurfaceClass::free);  // 0.866 d0
  ADS<3> e(1.1, 1.0);  // d_ADS = 1.1 d0
  apply(f, e);
  BOOST_TEST(dist(f, 0, 1) == 1.1, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(unmoved_partner_gives_full_correction) {
  // A wall particle or an interior fluid particle is not moved by ADS: the free
  // particle takes the whole correction, the partner stays put.
  for (auto type : {ParticleType::wall, ParticleType::fluid}) {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), type, SurfaceClass::interior);
    f.add(Vec<2>(0, 0.8), ParticleType::fluid, SurfaceClass::free);
    ADS<2> e(1.0, 1.0);
    apply(f, e);
    BOOST_TEST(f.s.particles.position[0].norm() == 0.0);
    BOOST_TEST(dist(f, 0, 1) >= 1.0 - 1e-12);
    BOOST_TEST(dist(f, 0, 1) == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(e.lastActionCount() == 1);
  }
}

BOOST_AUTO_TEST_CASE(jacobi_update) {
  // Three free particles in a row at 0.8 d0: the middle one gets opposite, cancelling
  // contributions; the outer ones move 0.1 d0 outward (all computed before any move).
  Fixture<2> f;
  for (int k = 0; k < 3; ++k) f.add(Vec<2>(0.8 * k, 0), ParticleType::fluid, SurfaceClass::free);
  ADS<2> e(1.0, 1.0);
  apply(f, e);
  BOOST_TEST(f.s.particles.position[1].x() == 0.8, tt::tolerance(1e-12));
  BOOST_TEST(f.s.particles.position[0].x() == -0.1, tt::tolerance(1e-12));
  BOOST_TEST(f.s.particles.position[2].x() == 1.7, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(lattice_at_d0_untouched) {
  // Free, vicinity and interior rows of a d0 lattice on walls: no pair is closer than d0.
  Fixture<2> f;
  forBox<2>({0, -3, 0}, {9, 6, 0}, [&](const std::array<int, 3>& idx) {
    const bool wall = idx[1] < 0;
    const SurfaceClass c = wall ? SurfaceClass::interior : idx[1] == 6 ? SurfaceClass::free
                           : idx[1] >= 4 ? SurfaceClass::vicinity : SurfaceClass::interior;
    f.add(latticePoint<2>(idx, 1.0), wall ? ParticleType::wall : ParticleType::fluid, c);
  });
  const auto before = f.s.particles.position;
  ADS<2> e(1.0, 1.0);
  apply(f, e);
  for (std::size_t i = 0; i < before.size(); ++i) BOOST_TEST((f.s.particles.position[i] - before[i]).norm() == 0.0);
  BOOST_TEST(e.lastActionCount() == 0);
}

BOOST_AUTO_TEST_CASE(requires_allocate) {
  Fixture<2> f;
  f.add(Vec<2>(0, 0), ParticleType::fluid, SurfaceClass::free);
  f.update();
  ADS<2> e(1.0, 1.0);
  BOOST_CHECK_THROW(e.correctPositions(f.s), std::logic_error);
}

BOOST_AUTO_TEST_CASE(partners_pair_moves_interior_partner_by_half) {
  // partners pair: a free particle 0.8 d0 from an interior fluid particle; both move
  // 0.1 d0 apart along the pair axis, the centroid stays. A wall partner still stays put.
  ADS<2>::Options o;
  o.pairwise = true;
  {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::fluid, SurfaceClass::interior);
    f.add(Vec<2>(0, 0.8), ParticleType::fluid, SurfaceClass::free);
    ADS<2> e(1.0, 1.0, o);
    apply(f, e);
    BOOST_TEST(f.s.particles.position[0].y() == -0.1, tt::tolerance(1e-12));
    BOOST_TEST(f.s.particles.position[1].y() == 0.9, tt::tolerance(1e-12));
    BOOST_TEST(std::abs(f.s.particles.position[0].x()) < 1e-15);
    BOOST_TEST(e.lastActionCount() == 2);
  }
  {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::wall, SurfaceClass::interior);
    f.add(Vec<2>(0, 0.8), ParticleType::fluid, SurfaceClass::free);
    ADS<2> e(1.0, 1.0, o);
    apply(f, e);
    BOOST_TEST(f.s.particles.position[0].norm() == 0.0);
    BOOST_TEST(dist(f, 0, 1) == 1.0, tt::tolerance(1e-12));
  }
  {
    // Two interior particles close together are not an ADS pair.
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::fluid, SurfaceClass::interior);
    f.add(Vec<2>(0, 0.8), ParticleType::fluid, SurfaceClass::interior);
    ADS<2> e(1.0, 1.0, o);
    apply(f, e);
    BOOST_TEST(dist(f, 0, 1) == 0.8, tt::tolerance(1e-12));
    BOOST_TEST(e.lastActionCount() == 0);
  }
}

BOOST_AUTO_TEST_CASE(approaching_only_skips_separating_pairs) {
  // approaching yes: a free pair 0.8 d0 apart acts only when (u_i - u_j) . r_ij < 0.
  ADS<2>::Options o;
  o.approachingOnly = true;
  for (double sign : {-1.0, 1.0}) {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::fluid, SurfaceClass::free);
    f.add(Vec<2>(0.8, 0), ParticleType::fluid, SurfaceClass::free);
    // sign -1: particle 0 moves toward particle 1 (closing); +1: away (separating).
    f.s.particles.velocity[0] = Vec<2>(-sign, 0);
    ADS<2> e(1.0, 1.0, o);
    apply(f, e);
    BOOST_TEST(dist(f, 0, 1) == (sign < 0 ? 1.0 : 0.8), tt::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(wall_partners_keep_their_own_distance) {
  // distance 0.95: a free pair 0.97 d0 apart is left alone; a free particle 0.97 d0 from a
  // wall particle is pushed to wallDistance from it when that is larger.
  for (double wallDistance : {1.0, 0.95}) {
    Fixture<2> f;
    f.add(Vec<2>(0, 0), ParticleType::wall, SurfaceClass::interior);
    f.add(Vec<2>(0, 0.97), ParticleType::fluid, SurfaceClass::free);
    f.add(Vec<2>(5, 0), ParticleType::fluid, SurfaceClass::free);
    f.add(Vec<2>(5, 0.97), ParticleType::fluid, SurfaceClass::free);
    ADS<2>::Options o;
    o.wallDistance = wallDistance;
    ADS<2> e(0.95, 1.0, o);
    apply(f, e);
    BOOST_TEST_CONTEXT("wallDistance " << wallDistance) {
      BOOST_TEST(dist(f, 0, 1) == std::max(0.97, wallDistance), tt::tolerance(1e-12));
      BOOST_TEST(f.s.particles.position[0].norm() == 0.0);
      BOOST_TEST(dist(f, 2, 3) == 0.97, tt::tolerance(1e-12));
      BOOST_TEST(e.lastActionCount() == (wallDistance > 0.97 ? 1 : 0));
    }
  }
}
