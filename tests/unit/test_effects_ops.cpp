// Tests of the distribution shift (OPS eqs. 11-13, DPS eq. 14; docs/method.md 6, 7):
// zero shift on a uniform lattice (also next to walls), the sign of the shift of a
// displaced particle, relaxation of a perturbed periodic lattice, and the
// tangential projection on free-surface and vicinity particles (2D and 3D: no component
// along n on a slab with n = e_D, and (I - n n^T) times the unprojected shift exactly, to
// round-off, on a ball with the detector's normals in every direction), and the frame of a
// free particle beside a wall that rises above the water (a still tank is a fixed point).
#define BOOST_TEST_MODULE effects_ops
#include <boost/test/unit_test.hpp>
#include "effects/ShiftCap.hpp"
#include "effects/ShiftingDistribution.hpp"
#include "surface/FreeSurface.hpp"
#include "surface/SurfaceFit.hpp"
#include "test_surface_shapes.hpp"
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

namespace {

// Disordered block periodic along the surface (16 x 10 in 2D, 10 x 10 x 10 in 3D), free top
// row with normal e_D, vicinity band of two rows below: the shift of every free and vicinity
// particle has no e_D component (exactly: (I - n n) dr with n = e_D zeroes it), but they
// are shifted along the surface.
template <int D>
void checkTangentialSlab() {
  const int width = D == 2 ? 16 : 10, top = 9;
  for (int v = 0; v < kVariants; ++v) {
    Fixture<D> f;
    rng().seed(3);
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    forSlab<D>(width, 0, top, [&](const std::array<int, 3>& idx) {
      const SurfaceClass c = idx[D - 1] == top ? SurfaceClass::free : idx[D - 1] >= top - 2 ? SurfaceClass::vicinity
                                                                                             : SurfaceClass::interior;
      Vec<D> x = latticePoint<D>(idx, 1.0);
      for (int a = 0; a < D; ++a) x[a] += u(rng());
      const std::size_t i = f.add(x, ParticleType::fluid, c);
      if (c != SurfaceClass::interior) f.s.particles.normal[i] = Vec<D>::Unit(D - 1);
    });
    f.setPeriodicAlongSurface(width);
    f.update();
    ShiftingDistribution<D> e(variant(v));
    auto dr = shiftOnce(f, e);
    double maxNormal = 0, maxTangent = 0;
    for (std::size_t i = 0; i < f.s.size(); ++i) {
      if (f.s.surfaceClass(i) == SurfaceClass::interior) continue;
      maxNormal = std::max(maxNormal, std::abs(dr[i][D - 1]));
      maxTangent = std::max(maxTangent, dr[i].head(D - 1).norm());
    }
    BOOST_TEST(maxNormal == 0.0, D << "D " << variantName(v));
    BOOST_TEST(maxTangent > 1e-3, D << "D " << variantName(v));
  }
}

// Lattice ball of radius R (disc in 2D), each coordinate perturbed by U(-0.05, 0.05) d0,
// classes and normals from the solver's detector: normals in every direction of the
// lattice. Known answer (eq. 11): free, splash and vicinity particles with a defined
// normal (|gradC| h >= projectionThreshold 0.01) are shifted by (I - n n^T) dr0, where dr0
// is the shift the same particle gets as an interior one; every other particle by dr0.
template <int D>
void checkTangentialBall(double R) {
  for (int v = 0; v < kVariants; ++v) {
    Fixture<D> f;
    rng().seed(5);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (const BodySite& b : bodySites<D>(R)) {
      Vec<D> x = latticePoint<D>(b.idx, 1.0);
      for (int a = 0; a < D; ++a) x[a] += u(rng());
      f.add(x);
    }
    f.update();
    FreeSurfaceDetector<D>(FreeSurfaceParameters::read(nullptr)).detect(f.s);
    ShiftingDistribution<D> e(variant(v));
    const auto dr = shiftOnce(f, e);
    Fixture<D> g = f;  // the same state with every particle interior: no projection
    std::fill(g.s.particles.surface.begin(), g.s.particles.surface.end(), std::uint8_t(SurfaceClass::interior));
    const auto dr0 = shiftOnce(g, e);
    long projected = 0, unprojectedDiffer = 0;
    double worst = 0, tangent = 0;  // worst: |dr - expected| and |dr . n| relative to |dr0|
    for (std::size_t i = 0; i < f.s.size(); ++i) {
      const Vec<D>& n = f.s.particles.normal[i];
      if (f.s.surfaceClass(i) == SurfaceClass::interior || f.s.gradC[i].norm() * f.s.h < 0.01) {
        unprojectedDiffer += (dr[i] - dr0[i]).norm() > 0;  // the same arithmetic: bitwise equal
        continue;
      }
      ++projected;
      const double scale = std::max(dr0[i].norm(), 1e-300);
      worst = std::max(worst, (dr[i] - (dr0[i] - n.dot(dr0[i]) * n)).norm() / scale);
      worst = std::max(worst, std::abs(dr[i].dot(n)) / scale);
      tangent = std::max(tangent, dr[i].norm());
    }
    std::cout << D << "D ball R = " << R << ", " << variantName(v) << ": " << projected
              << " projected, max |dr - (I - n n) dr0| / |dr0| " << worst << ", max projected |dr| " << tangent
              << " d0\n";
    // Round-off of the projection: measured at most 4e-15 (OPS corrected, |dr0| up to 2.3 d0).
    BOOST_TEST(worst < 1e-13, D << "D " << variantName(v));
    BOOST_TEST(unprojectedDiffer == 0);
    BOOST_TEST(projected > 0);
    BOOST_TEST(tangent > 1e-3);
  }
}

// A still tank whose side walls rise above the water (docs/method.md 6, "beside a dry wall"):
// fluid lattice 8 wide (8 x 8 in 3D) and 6 deep on three wall layers, the side walls 4 rows
// higher than the water; classes, normals and the surface fit from the solver's detector and
// fit. Known answer: the lattice is the equilibrium, so no fluid particle is shifted (round-off).
// The frame of before (the detector's normal and every wall particle, here by leaving the fit
// out) lifts the top corner particles and pushes them along the surface toward the walls.
template <int D>
void checkTankBesideDryWalls() {
  const int W = 8, H = 6;
  Fixture<D> f;
  std::array<int, 3> lo{-3, -3, -3}, hi{W + 2, H + 3, W + 2};
  forBox<D>(lo, hi, [&](const std::array<int, 3>& idx) {
    const bool within = idx[0] >= 0 && idx[0] < W && (D == 2 || (idx[2] >= 0 && idx[2] < W));
    if (within && idx[1] >= H) return;  // air
    f.add(latticePoint<D>(idx, 1.0), within && idx[1] >= 0 ? ParticleType::fluid : ParticleType::wall);
  });
  f.update();
  FreeSurfaceDetector<D>(FreeSurfaceParameters::read(nullptr)).detect(f.s);
  computeSurfaceFit(f.s);
  ShiftingDistribution<D> e(ops(Gradient::kernel));
  double worst = 0;
  for (const Vec<D>& d : shiftOnce(f, e)) worst = std::max(worst, d.norm());
  f.s.fitDistance.clear();  // the frame without the fit: the detector's normal, every wall particle
  const auto before = shiftOnce(f, e);
  double lift = INFINITY, towardWall = INFINITY;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const Vec<D>& x = f.s.particles.position[i];
    if (!f.s.isFluid(i) || x[1] != H - 1) continue;
    bool corner = true;
    for (int a = 0; a < D; a += 2) corner &= x[a] == 0;
    if (!corner) continue;
    lift = before[i][1];
    for (int a = 0; a < D; a += 2) towardWall = std::min(towardWall, -before[i][a]);
  }
  std::cout << D << "D tank beside dry walls: max |dr| " << worst << " d0; without the fit the corner particle is lifted "
            << lift << " d0 and moved " << towardWall << " d0 toward each wall\n";
  // Measured 2.6e-11 (2D) and 1.9e-11 d0 (3D): the fitted normal comes from an eigenvector solve
  // exact to about 1e-11, against a normal gradient that the projection removes. Without the
  // fit: lifted 9.5e-4 and 1.0e-3 d0, toward the walls 3.5e-3 and 1.9e-3 d0 in one shift.
  BOOST_TEST(worst < 1e-9);
  BOOST_TEST(lift > 5e-4);
  BOOST_TEST(towardWall > 5e-4);
}

}  // namespace

BOOST_AUTO_TEST_CASE(still_tank_beside_dry_walls_gets_no_shift_2d) { checkTankBesideDryWalls<2>(); }

BOOST_AUTO_TEST_CASE(still_tank_beside_dry_walls_gets_no_shift_3d) { checkTankBesideDryWalls<3>(); }

BOOST_AUTO_TEST_CASE(free_surface_and_vicinity_shifts_are_tangential_2d) { checkTangentialSlab<2>(); }

BOOST_AUTO_TEST_CASE(free_surface_and_vicinity_shifts_are_tangential_3d) { checkTangentialSlab<3>(); }

BOOST_AUTO_TEST_CASE(ball_shifts_are_projected_on_the_tangent_plane_2d) { checkTangentialBall<2>(12); }

BOOST_AUTO_TEST_CASE(ball_shifts_are_projected_on_the_tangent_plane_3d) { checkTangentialBall<3>(8); }

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
  FreeSurfaceDetector<2>(FreeSurfaceParameters::read(nullptr)).detect(f.s);
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
