// No particle is shifted across the free surface (docs/method.md 6, OPS): on a disordered
// block with a free top row, the combined shift (OPS + volume correction + surface
// fitting, capped at 0.1 h) has no component along each free particle's (fitted)
// normal beyond the surface-fitting term, C_suf h |s| <= 1e-4 * 1.2 * 0.6 d0.
#define BOOST_TEST_MODULE effects_freeSurfaceShift
#include <boost/test/unit_test.hpp>
#include "effects/ShiftCap.hpp"
#include "effects/ShiftingDistribution.hpp"
#include "effects/SurfaceFitting.hpp"
#include "effects/VolumeCorrection.hpp"
#include "surface/SurfaceFit.hpp"
#include "test_effects_fixture.hpp"
#include <iostream>

using namespace shizuku;
using namespace shizuku::testing;

namespace {

// Fluid rows 0..top (x periodic over 24) on 3 wall layers, every fluid particle
// perturbed by U(-0.1, 0.1) d0 per coordinate. Classes by row: free top row,
// vicinity within 2h below it, interior below; normals (0, 1) before the fit.
void disorderedBlock(Fixture<2>& f, int top) {
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  forBox<2>({0, -3, 0}, {23, top, 0}, [&](const std::array<int, 3>& idx) {
    const bool wall = idx[1] < 0;
    const int depth = top - idx[1];
    const SurfaceClass c = wall ? SurfaceClass::interior : depth == 0 ? SurfaceClass::free
                           : depth < 2.4 ? SurfaceClass::vicinity : SurfaceClass::interior;
    Vec<2> x = latticePoint<2>(idx, 1.0);
    if (!wall) x += Vec<2>(u(rng()), u(rng()));
    const std::size_t i = f.add(x, wall ? ParticleType::wall : ParticleType::fluid, c);
    if (c != SurfaceClass::interior) f.s.particles.normal[i] = Vec<2>(0, 1);
  });
  f.s.periodic.periodic = {true, false};
  f.s.periodic.lo = Vec<2>(-0.5, 0);
  f.s.periodic.hi = Vec<2>(23.5, 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(combined_shift_keeps_free_particles_on_the_surface) {
  Fixture<2> f;
  rng().seed(21);
  const int top = 10;
  disorderedBlock(f, top);
  ShiftingDistribution<2> dis(DistributionParameters{});
  VolumeCorrection<2> vol(0.1);
  SurfaceFitting<2> suf(SurfaceFittingParameters{});
  const double bound = 1e-4 * 1.2 * 0.6 * (1 + 1e-12);
  double maxOwn = 0, maxVertical = 0, maxTangential = 0, maxInterior = 0;
  long fitted = 0;
  for (int step = 0; step < 10; ++step) {
    f.update();
    // Restore the by-row normals each step (the solver's detector would), then fit.
    for (std::size_t i = 0; i < f.s.size(); ++i)
      if (f.s.particles.isFluid(i) && f.s.surfaceClass(i) != SurfaceClass::interior)
        f.s.particles.normal[i] = Vec<2>(0, 1);
    computeSurfaceFit(f.s);
    std::vector<Vec<2>> dr(f.s.size(), Vec<2>::Zero());
    dis.addShift(f.s, dr);
    vol.addShift(f.s, dr);
    suf.addShift(f.s, dr);
    capShift(dr, 0.1 * f.s.h);
    for (std::size_t i = 0; i < f.s.size(); ++i) {
      if (!f.s.particles.isFluid(i)) {
        BOOST_TEST(dr[i].norm() == 0.0);
        continue;
      }
      const SurfaceClass c = f.s.surfaceClass(i);
      if (c == SurfaceClass::free || c == SurfaceClass::vicinity) {
        const Vec<2>& n = f.s.particles.normal[i];
        const double own = std::abs(dr[i].dot(n));
        if (c == SurfaceClass::free) {
          maxOwn = std::max(maxOwn, own);
          maxVertical = std::max(maxVertical, std::abs(dr[i].y()));
          maxTangential = std::max(maxTangential, std::abs(dr[i].x()));
          fitted += !std::isnan(f.s.fitDistance[i]);
          BOOST_TEST(own <= bound);
        } else {
          BOOST_TEST(own < 1e-15);  // vicinity: projected, no fitting term
        }
      } else {
        maxInterior = std::max(maxInterior, dr[i].norm());
      }
    }
    f.move(dr);
  }
  std::cout << "10 combined shifts: free particles max |dr.n| " << maxOwn << " d0 (bound " << bound
            << "), max |dr_y| " << maxVertical << ", max |dr_x| " << maxTangential << "; interior max |dr| "
            << maxInterior << "; fits " << fitted << " of 240\n";
  BOOST_TEST(maxTangential > 1e-3);  // the free particles are shifted along the surface
  BOOST_TEST(maxInterior > 1e-3);
  BOOST_TEST(fitted > 200);
}
