// Tests of the distribution shift (OPS eqs. 11-13, DPS eq. 14; docs/method.md 6, 7):
// zero shift on a uniform lattice (also next to walls), the sign of the shift of a
// displaced particle, relaxation of a perturbed periodic lattice, and the
// tangential projection on free-surface and vicinity particles.
#define BOOST_TEST_MODULE effects_ops
#include <boost/test/unit_test.hpp>
#include "effects/ShiftCap.hpp"
#include "effects/ShiftingDistribution.hpp"
#include "surface/FreeSurface.hpp"
#include "test_effects_fixture.hpp"
#include <iostream>

using namespace shizuku;
using namespace shizuku::testing;

namespace {

using Gradient = DistributionParameters::Gradient;

DistributionParameters ops(Gradient g) {
  DistributionParameters p;
  p.gradient = g;
  return p;
}

DistributionParameters dps() {
  DistributionParameters p;
  p.type = DistributionParameters::Type::DPS;
  return p;
}

// Variants: OPS with each gradient, then DPS.
constexpr int kVariants = 4;
DistributionParameters variant(int v) {
  return v == 0 ? ops(Gradient::kernel) : v == 1 ? ops(Gradient::corrected) : v == 2 ? ops(Gradient::concentration) : dps();
}
const char* variantName(int v) {
  return v == 0 ? "OPS kernel" : v == 1 ? "OPS corrected" : v == 2 ? "OPS concentration" : "DPS";
}

// Periodic lattice n^D of spacing 1, each coordinate perturbed by U(-amp, amp).
template <int D>
void periodicLattice(Fixture<D>& f, int n, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  forBox<D>({0, 0, 0}, {n - 1, n - 1, n - 1}, [&](const std::array<int, 3>& idx) {
    Vec<D> x = latticePoint<D>(idx, 1.0);
    for (int a = 0; a < D; ++a) x[a] += u(rng());
    f.add(x);
  });
  f.setPeriodic(Vec<D>::Constant(-0.5), Vec<D>::Constant(n - 0.5));
}

template <int D>
std::vector<Vec<D>> shiftOnce(Fixture<D>& f, ShiftTerm<D>& e) {
  std::vector<Vec<D>> dr(f.s.size(), Vec<D>::Zero());
  e.addShift(f.s, dr);
  return dr;
}

// Relax with the solver's sequence (update, shift, cap 0.1 h, move); returns the
// density standard deviation after `iterations`.
template <int D>
double relax(Fixture<D>& f, ShiftTerm<D>& e, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    f.update();
    auto dr = shiftOnce(f, e);
    capShift(dr, 0.1 * f.s.h);
    f.move(dr);
  }
  f.update();
  return f.densityStd();
}

}  // namespace

BOOST_AUTO_TEST_CASE(uniform_lattice_gets_no_shift) {
  for (int v = 0; v < kVariants; ++v) {
    Fixture<2> f;
    periodicLattice(f, 12, 0.0);
    f.update();
    ShiftingDistribution<2> e(variant(v));
    auto dr = shiftOnce(f, e);
    double maxLen = 0;
    for (auto& d : dr) maxLen = std::max(maxLen, d.norm());
    // Symmetric neighbourhoods cancel: measured <= 3e-16 d0 (round-off of 20 terms).
    BOOST_TEST(maxLen < 1e-14, variantName(v) << ": max |dr| = " << maxLen);
  }
}

BOOST_AUTO_TEST_CASE(fluid_next_to_walls_gets_no_shift) {
  // Fluid rows y = 0..5 on 3 wall layers y = -3..-1, periodic in x: the fluid near the wall
  // is not pushed into it because wall particles are in the sum (docs/method.md 6).
  Fixture<2> f;
  forBox<2>({0, -3, 0}, {11, 8, 0}, [&](const std::array<int, 3>& idx) {
    f.add(latticePoint<2>(idx, 1.0), idx[1] < 0 ? ParticleType::wall : ParticleType::fluid);
  });
  f.s.periodic.periodic = {true, false};
  f.s.periodic.lo = Vec<2>(-0.5, 0);
  f.s.periodic.hi = Vec<2>(11.5, 0);
  f.update();
  ShiftingDistribution<2> e(ops(Gradient::kernel));
  auto dr = shiftOnce(f, e);
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const double y = f.s.particles.position[i].y();
    if (y >= 0 && y <= 4) BOOST_TEST(dr[i].norm() < 1e-14);  // rows not truncated at the top
    if (y < 0) BOOST_TEST(dr[i].norm() == 0.0);                // walls are never shifted
  }
}

BOOST_AUTO_TEST_CASE(displaced_particle_moves_back) {
  // One particle of a periodic lattice moved by (0.2, 0.1) d0: every variant shifts it
  // back, i.e. against the displacement (toward the sparser side).
  for (int v = 0; v < kVariants; ++v) {
    Fixture<2> f;
    periodicLattice(f, 10, 0.0);
    const std::size_t c = 55;
    const Vec<2> disp(0.2, 0.1);
    f.s.particles.position[c] += disp;
    f.update();
    ShiftingDistribution<2> e(variant(v));
    auto dr = shiftOnce(f, e);
    const double cosine = dr[c].dot(disp) / (dr[c].norm() * disp.norm());
    std::cout << "displaced 0.22 d0, " << variantName(v) << ": |dr| = " << dr[c].norm()
              << " d0, cos(dr, displacement) = " << cosine << "\n";
    BOOST_TEST(cosine < -0.9);
    BOOST_TEST(dr[c].norm() < disp.norm());  // does not overshoot the lattice site
  }
}

BOOST_AUTO_TEST_CASE(perturbed_periodic_lattice_relaxes_2d) {
  // +-0.1 d0 random perturbation of a 20x20 periodic lattice, shifted 40 times (C 0.2).
  // Measured std(<rho>/rho0), 0.0324 initially, after 40 shifts: OPS kernel 0.00265
  // (factor 12.2; the minimum 0.0023 is reached near 20 shifts, after which the Rp
  // anti-clumping repulsion slowly rearranges the lattice), OPS concentration 0.00428
  // (7.6), DPS 0.00425 (7.6); OPS corrected GROWS to 0.103 (factor 0.32, see
  // ShiftingDistribution.hpp). Asserted: factor > 5 for the stable variants, growth
  // for the literal corrected one.
  for (int v = 0; v < kVariants; ++v) {
    Fixture<2> f;
    rng().seed(7);
    periodicLattice(f, 20, 0.1);
    f.update();
    const double before = f.densityStd();
    ShiftingDistribution<2> e(variant(v));
    const double after = relax(f, e, 40);
    std::cout << variantName(v) << " 2D: std(rho) " << before << " -> " << after << " (factor " << before / after
              << ")\n";
    if (v == 1)
      BOOST_TEST(after > before);
    else
      BOOST_TEST(before / after > 5);
  }
}

BOOST_AUTO_TEST_CASE(perturbed_periodic_lattice_relaxes_3d) {
  // 8^3 periodic lattice, +-0.1 d0, OPS kernel 20 times: measured 0.0242 -> 0.00200 (12.1).
  Fixture<3> f;
  rng().seed(11);
  periodicLattice(f, 8, 0.1);
  f.update();
  const double before = f.densityStd();
  ShiftingDistribution<3> e(ops(Gradient::kernel));
  const double after = relax(f, e, 20);
  std::cout << "OPS kernel 3D: std(rho) " << before << " -> " << after << " (factor " << before / after << ")\n";
  BOOST_TEST(before / after > 5);
}

BOOST_AUTO_TEST_CASE(free_surface_and_vicinity_shifts_are_tangential) {
  // Disordered block, free top row with normal (0,1), vicinity band below: the shift of
  // every free and vicinity particle has no normal component (to round-off).
  for (int v = 0; v < kVariants; ++v) {
    Fixture<2> f;
    rng().seed(3);
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    forBox<2>({0, 0, 0}, {15, 9, 0}, [&](const std::array<int, 3>& idx) {
      const SurfaceClass c = idx[1] == 9 ? SurfaceClass::free : idx[1] >= 7 ? SurfaceClass::vicinity
                                                                            : SurfaceClass::interior;
      const std::size_t i = f.add(latticePoint<2>(idx, 1.0) + Vec<2>(u(rng()), u(rng())), ParticleType::fluid, c);
      if (c != SurfaceClass::interior) f.s.particles.normal[i] = Vec<2>(0, 1);
    });
    f.s.periodic.periodic = {true, false};
    f.s.periodic.lo = Vec<2>(-0.5, 0);
    f.s.periodic.hi = Vec<2>(15.5, 0);
    f.update();
    ShiftingDistribution<2> e(variant(v));
    auto dr = shiftOnce(f, e);
    double maxNormal = 0, maxTangent = 0;
    for (std::size_t i = 0; i < f.s.size(); ++i) {
      if (f.s.surfaceClass(i) == SurfaceClass::interior) continue;
      maxNormal = std::max(maxNormal, std::abs(dr[i].y()));
      maxTangent = std::max(maxTangent, std::abs(dr[i].x()));
    }
    BOOST_TEST(maxNormal == 0.0);  // (I - n n) with n = (0,1) zeroes y exactly
    BOOST_TEST(maxTangent > 1e-3);  // but the particles are shifted
  }
}

// The tangential projection (eq. 11) on a detected free surface: a lattice slab periodic
// in x, 14 rows, the second rows nudged by +-0.05 d0 in x (alternating) so that the
// shifts are not zero; classes, gradC and normals from the solver's detector. Free particles and vicinity particles whose support reaches past
// the surface (|sum V grad W| h >= projectionThreshold) move only along the surface;
// deeper vicinity particles, whose detector normal is ill-defined, shift like interior ones.
BOOST_AUTO_TEST_CASE(projection_only_where_the_normal_is_defined) {
  Fixture<2> f;
  forBox<2>({0, 0, 0}, {23, 13, 0}, [&](const std::array<int, 3>& idx) {
    const double nudge = (idx[1] == 1 || idx[1] == 12) ? 0.05 * ((idx[0] % 2) ? 1 : -1) : 0.0;
    f.add(latticePoint<2>(idx, 1.0) + Vec<2>(nudge, 0), ParticleType::fluid, SurfaceClass::interior);
  });
  f.s.periodic.periodic = {true, false};
  f.s.periodic.lo = Vec<2>(-0.5, 0);
  f.s.periodic.hi = Vec<2>(23.5, 0);
  f.update();
  FreeSurfaceDetector<2>(FreeSurfaceParameters::read(nullptr, 2)).detect(f.s);
  // Measured |gradC| h by row: 0.56 (free), 0.053, 0.021 (vicinity), 0.0016 (interior
  // row 3), 1e-16 deeper. A particle just inside the vicinity radius whose support barely
  // reaches the surface, as in a disordered flow, is made here by scaling the gradient
  // of the rows two below the surfaces (vicinity) to 0.4 of the threshold.
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const long row = std::lround(f.s.particles.position[i].y());
    if (row == 2 || row == 11) f.s.gradC[i] *= 0.4 * 0.01 / (f.s.gradC[i].norm() * f.s.h);
  }
  auto shifts = [&](double threshold) {
    DistributionParameters p;
    p.projectionThreshold = threshold;
    std::vector<Vec<2>> dr(f.s.size(), Vec<2>::Zero());
    ShiftingDistribution<2>(p).addShift(f.s, dr);
    return dr;
  };
  const auto dr = shifts(0.01), all = shifts(0.0), none = shifts(1e300);
  long projected = 0, free_ = 0, deep = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const SurfaceClass c = f.s.surfaceClass(i);
    const Vec<2>& n = f.s.particles.normal[i];
    const bool strong = f.s.gradC[i].norm() * f.s.h >= 0.01;
    if (c == SurfaceClass::free || c == SurfaceClass::splash) {
      ++free_;
      BOOST_TEST(std::abs(dr[i].dot(n)) < 1e-15);
    } else if (c == SurfaceClass::vicinity && strong) {
      ++projected;
      BOOST_TEST(std::abs(dr[i].dot(n)) < 1e-15);
      BOOST_TEST((dr[i] - all[i]).norm() == 0.0);
    } else if (c == SurfaceClass::vicinity) {
      ++deep;
      BOOST_TEST((dr[i] - none[i]).norm() == 0.0);  // the unprojected shift
      BOOST_TEST((dr[i] - all[i]).norm() > 0.0);
    } else {
      BOOST_TEST((dr[i] - all[i]).norm() == 0.0);
    }
  }
  std::cout << "slab: " << free_ << " free, " << projected << " projected vicinity, " << deep
            << " vicinity shifted like interior\n";
  BOOST_TEST(free_ == 48);
  BOOST_TEST(projected == 48);
  BOOST_TEST(deep == 48);
}
