// Neighbour search tests (NeighbourList.hpp): the cell-linked list equals the
// O(N^2) brute force on random 2D/3D sets, with and without periodic
// directions (minimum image across the boundary), no self pairs, rows sorted
// by j, identical for 1 and 2 threads, cellOrder a permutation sorted by cell,
// in 3D every combination of periodic directions against a minimum image computed here
// (not with PeriodicBox::difference), a pair through the corner of a 3D box,
// rebuilds reuse the buffers, bad periodic boxes are rejected; particles far
// from the rest (spray) change neither the pairs nor the grid's cell size.
#define BOOST_TEST_MODULE particles_neighbours
#include <boost/test/unit_test.hpp>

#include "particles/NeighbourList.hpp"
#include <algorithm>
#include <omp.h>
#include <random>

using namespace shizuku;

namespace {

template <int D>
std::vector<Vec<D>> randomPoints(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec<D>> x(n);
  for (auto& p : x)
    for (int a = 0; a < D; ++a) p[a] = u(gen);
  return x;
}

// Same pairs (exact j and offsets), rij and r equal to round-off.
template <int D>
void checkEqual(const NeighbourList<D>& a, const NeighbourList<D>& b) {
  BOOST_REQUIRE(a.offset == b.offset);
  BOOST_REQUIRE(a.j == b.j);
  double err = 0;
  for (std::size_t i = 0; i < a.numParticles(); ++i)
    for (Index p = a.begin(i); p < a.end(i); ++p) {
      err = std::max(err, (a.rij(i, p) - b.rij(i, p)).norm());
      err = std::max(err, std::abs(a.r(i, p) - b.r(i, p)));
    }
  // positions are O(1): wrapping before differencing changes the last bits only
  BOOST_TEST(err < 1e-14);
}

template <int D>
void checkRows(const NeighbourList<D>& nl, double radius) {
  for (std::size_t i = 0; i < nl.numParticles(); ++i)
    for (Index p = nl.begin(i); p < nl.end(i); ++p) {
      BOOST_TEST_REQUIRE(nl.j[p] != Index(i));
      BOOST_TEST_REQUIRE(nl.r(i, p) < radius);
      BOOST_TEST_REQUIRE(nl.r(i, p) > 0.0);
      if (p > nl.begin(i)) BOOST_TEST_REQUIRE(nl.j[p] > nl.j[p - 1]);
    }
}

template <int D>
void compareWithBruteForce(std::size_t n, double radius, const PeriodicBox<D>& box, unsigned seed) {
  auto x = randomPoints<D>(n, 0.0, 1.0, seed);
  NeighbourSearch<D> search(radius, box);
  NeighbourList<D> nl, ref;
  search.build(x, nl);
  bruteForceNeighbours(x, radius, box, ref);
  BOOST_TEST_MESSAGE("D=" << D << " n=" << n << " radius=" << radius << " pairs=" << nl.numPairs());
  BOOST_TEST(nl.numPairs() > n);  // the test is not vacuous
  checkEqual(nl, ref);
  checkRows(nl, radius);
}

}  // namespace

BOOST_AUTO_TEST_CASE(equals_brute_force_2d_3d) {
  compareWithBruteForce<2>(3000, 0.04, {}, 1);
  compareWithBruteForce<2>(500, 0.3, {}, 2);
  compareWithBruteForce<3>(3000, 0.12, {}, 3);
  compareWithBruteForce<3>(200, 0.7, {}, 4);  // a single cell in each direction
}

// A bulk of particles plus far ones: alone, in pairs within the radius, along
// every axis and on both sides, up to 1e12 m away. The pairs equal the brute
// force (clamping far particles into edge cells loses none), and the grid keeps
// cells of the search radius over the bulk instead of growing with the distance.
template <int D>
void farParticles(double distance) {
  const double radius = 0.04;
  auto x = randomPoints<D>(4000, 0.0, 1.0, 11);
  for (int a = 0; a < D; ++a)
    for (double side : {-1.0, 1.0}) {
      Vec<D> far = Vec<D>::Constant(0.5);
      far[a] += side * distance;
      x.push_back(far);
      far[(a + 1) % D] += 0.5 * radius;  // a neighbour of the far particle
      x.push_back(far);
      far[a] += 3 * radius;  // and one just out of reach of both
      x.push_back(far);
    }
  NeighbourSearch<D> search(radius);
  NeighbourList<D> nl, ref;
  search.build(x, nl);
  bruteForceNeighbours(x, radius, {}, ref);
  BOOST_TEST_MESSAGE("D=" << D << " far at " << distance << " m: " << search.numCells() << " cells of "
                          << search.cellSize(0) << " m");
  checkEqual(nl, ref);
  checkRows(nl, radius);
  for (int a = 0; a < D; ++a) BOOST_TEST(search.cellSize(a) == radius);
  BOOST_TEST(double(search.numCells()) <= std::pow(1.3 / radius + 2, D));
}

BOOST_AUTO_TEST_CASE(far_particles_keep_the_grid_and_the_pairs) {
  for (double distance : {10.0, 1e4, 1e12}) {
    farParticles<2>(distance);
    farParticles<3>(distance);
  }
}

BOOST_AUTO_TEST_CASE(periodic_equals_brute_force) {
  PeriodicBox<2> px;
  px.periodic = {true, false};
  px.lo = Vec<2>(0, 0);
  px.hi = Vec<2>(1, 1);
  compareWithBruteForce<2>(3000, 0.04, px, 5);
  PeriodicBox<2> pxy = px;
  pxy.periodic = {true, true};
  compareWithBruteForce<2>(3000, 0.04, pxy, 6);
  compareWithBruteForce<2>(800, 0.45, pxy, 7);  // 2 cells per periodic direction
  compareWithBruteForce<2>(800, 0.34, pxy, 8);  // 2 cells, L < 3 radius
  PeriodicBox<3> p3;
  p3.periodic = {true, false, true};
  p3.lo = Vec<3>::Zero();
  p3.hi = Vec<3>::Ones();
  compareWithBruteForce<3>(3000, 0.12, p3, 9);
  p3.periodic = {true, true, true};
  compareWithBruteForce<3>(1000, 0.4, p3, 10);
}

namespace {

// Minimum image computed independently of PeriodicBox::difference: per periodic direction
// the image n L (n = -2..2, inputs up to one length outside the box) nearest to zero.
Vec<3> minimumImage(const Vec<3>& a, const Vec<3>& b, const PeriodicBox<3>& box) {
  Vec<3> d = a - b;
  for (int k = 0; k < 3; ++k) {
    if (!box.periodic[k]) continue;
    const double L = box.hi[k] - box.lo[k];
    double best = d[k];
    for (int n = -2; n <= 2; ++n)
      if (std::abs(d[k] - n * L) < std::abs(best)) best = d[k] - n * L;
    d[k] = best;
  }
  return d;
}

// Random points in an offset, non-cubic box; in periodic directions one point in ten is
// moved a whole length out of the box (the search must wrap it). The pairs equal both the
// library's brute force and the independent minimum image: same j, r_ij to round-off.
void checkPeriodic3d(const std::array<bool, 3>& periodic, double radius, unsigned seed) {
  PeriodicBox<3> box;
  box.periodic = periodic;
  box.lo = Vec<3>(-1.3, 0.2, 2.0);
  box.hi = box.lo + Vec<3>(1.0, 0.8, 1.2);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<3>> x(700);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double L = box.hi[k] - box.lo[k];
      x[i][k] = box.lo[k] + L * u(gen);
      if (periodic[k] && i % 10 == 0) x[i][k] += (i % 20 == 0 ? L : -L);
    }
  NeighbourSearch<3> search(radius, box);
  NeighbourList<3> nl, ref;
  search.build(x, nl);
  bruteForceNeighbours(x, radius, box, ref);
  checkEqual(nl, ref);
  checkRows(nl, radius);
  long wrapped = 0, missing = 0;
  double err = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    Index p = nl.begin(i);
    for (std::size_t j = 0; j < x.size(); ++j) {
      const Vec<3> d = minimumImage(x[i], x[j], box);
      if (j == i || !(d.norm() < radius)) continue;
      while (p < nl.end(i) && nl.j[p] < Index(j)) ++p;
      if (p == nl.end(i) || nl.j[p] != Index(j)) { ++missing; continue; }
      err = std::max(err, (nl.rij(i, p) - d).norm());
      wrapped += (x[i] - x[j] - d).norm() > 0.5 * radius;
    }
  }
  BOOST_TEST_MESSAGE("periodic (" << periodic[0] << periodic[1] << periodic[2] << "), radius " << radius << ": "
                                  << nl.numPairs() << " pairs, " << wrapped << " across a boundary");
  BOOST_TEST(missing == 0);
  BOOST_TEST(err < 1e-14);
  BOOST_TEST(nl.numPairs() > x.size());  // not vacuous
  BOOST_TEST(wrapped > 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(periodic_3d_every_combination_equals_minimum_image) {
  // The seven combinations of one, two and three periodic directions; radius 0.15 (5 to 8
  // cells per direction) and 0.39 (2 cells along the 0.8 direction, 3 along 1.2).
  unsigned seed = 20;
  for (int mask = 1; mask < 8; ++mask) {
    const std::array<bool, 3> periodic{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
    checkPeriodic3d(periodic, 0.15, seed++);
    checkPeriodic3d(periodic, 0.39, seed++);
  }
}

BOOST_AUTO_TEST_CASE(pair_across_three_periodic_boundaries) {
  // Two particles at opposite corners of the box [(-1, 0, 2), (1, 1, 3.5)): with all three
  // directions periodic they are neighbours through the corner, r_ab = (0.02, 0.03, 0.04);
  // with only x periodic they are 1 and 1.5 apart in y and z: no pair.
  PeriodicBox<3> box;
  box.lo = Vec<3>(-1, 0, 2);
  box.hi = Vec<3>(1, 1, 3.5);
  const std::vector<Vec<3>> x = {box.lo + Vec<3>(0.01, 0.02, 0.03), box.hi - Vec<3>(0.01, 0.01, 0.01)};
  NeighbourList<3> nl;
  box.periodic = {true, true, true};
  NeighbourSearch<3>(0.1, box).build(x, nl);
  BOOST_REQUIRE(nl.numPairs() == 2u);
  BOOST_TEST((nl.rij(0, nl.begin(0)) - Vec<3>(0.02, 0.03, 0.04)).norm() < 1e-14);
  BOOST_TEST((nl.rij(1, nl.begin(1)) + Vec<3>(0.02, 0.03, 0.04)).norm() < 1e-14);
  BOOST_TEST(std::abs(nl.r(0, nl.begin(0)) - std::sqrt(0.0029)) < 1e-14);
  box.periodic = {true, false, false};
  NeighbourSearch<3>(0.1, box).build(x, nl);
  BOOST_TEST(nl.numPairs() == 0u);
}

BOOST_AUTO_TEST_CASE(pair_across_periodic_boundary) {
  PeriodicBox<2> box;
  box.periodic = {true, false};
  box.lo = Vec<2>(-1, 0);
  box.hi = Vec<2>(1, 1);
  // particle 2 lies outside the box: it is wrapped to x = -0.995
  std::vector<Vec<2>> x = {Vec<2>(-0.99, 0.5), Vec<2>(0.985, 0.5), Vec<2>(1.005, 0.52)};
  NeighbourSearch<2> search(0.05, box);
  NeighbourList<2> nl;
  search.build(x, nl);
  BOOST_REQUIRE(nl.numPairs() == 6u);
  // i = 0: j = 1 with r_01 = -0.99 - (0.985 - 2) = 0.025
  BOOST_TEST(nl.j[nl.begin(0)] == 1);
  BOOST_TEST(std::abs(nl.rij(0, nl.begin(0))[0] - 0.025) < 1e-14);
  BOOST_TEST(std::abs(nl.rij(0, nl.begin(0))[1]) < 1e-14);
  // i = 1: j = 2 at image x = 1.005 - 2 -> r_12 = (0.985 - 1.005, -0.02)
  BOOST_TEST(nl.j[nl.begin(1) + 1] == 2);
  BOOST_TEST(std::abs(nl.rij(1, nl.begin(1) + 1)[0] + 0.02) < 1e-14);
  BOOST_TEST(std::abs(nl.rij(1, nl.begin(1) + 1)[1] + 0.02) < 1e-14);
  // difference() and wrap()
  Vec<2> d = box.difference(x[0], x[1]);
  BOOST_TEST(std::abs(d[0] - 0.025) < 1e-14);
  Vec<2> w = x[2];
  box.wrap(w);
  BOOST_TEST(std::abs(w[0] + 0.995) < 1e-14);
  BOOST_TEST(w[1] == 0.52);
}

BOOST_AUTO_TEST_CASE(periodic_length_too_short) {
  PeriodicBox<2> box;
  box.periodic = {false, true};
  box.lo = Vec<2>(0, 0);
  box.hi = Vec<2>(1, 0.1);
  BOOST_CHECK_THROW(NeighbourSearch<2>(0.051, box), InputError);
  BOOST_CHECK_NO_THROW(NeighbourSearch<2>(0.05, box));
  BOOST_CHECK_THROW(NeighbourSearch<2>(0.0, PeriodicBox<2>{}), InputError);
}

// Rows are kept as 16-bit offsets into a cell's candidates only while no cell holds more
// than 65535 / 3^D particles (more could wrap them); a crowded cell makes the scan keep
// 32-bit positions. Both give the brute force's pairs. (The crowded case in 3D: a 2D cell
// would need 7282 particles, 26 million pairs; the code is the same for both.)
template <int D>
void crowdedCell(std::size_t crowd) {
  const double radius = 0.04;
  auto x = randomPoints<D>(1500, 0.0, 1.0, 21);
  auto cluster = randomPoints<D>(crowd, 0.505, 0.515, 22);  // inside one cell of side radius
  x.insert(x.end(), cluster.begin(), cluster.end());
  NeighbourSearch<D> search(radius);
  NeighbourList<D> nl, ref;
  search.build(x, nl);
  bruteForceNeighbours(x, radius, {}, ref);
  BOOST_TEST(search.usedOffsets() == (crowd * 27 <= 65535));
  checkEqual(nl, ref);
  checkRows(nl, radius);
}

BOOST_AUTO_TEST_CASE(crowded_cell_equals_brute_force) {
  crowdedCell<3>(2400);  // 27 x 2400 <= 65535: offsets
  crowdedCell<3>(2500);  // 27 x 2500 > 65535: positions
}

BOOST_AUTO_TEST_CASE(thread_count_independent_and_no_reallocation) {
  auto x = randomPoints<3>(20000, 0.0, 1.0, 11);
  NeighbourSearch<3> search(0.06);
  NeighbourList<3> a, b;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  search.build(x, a);
  omp_set_num_threads(2);
  search.build(x, b);
  omp_set_num_threads(saved);
  BOOST_TEST(a.offset == b.offset);
  BOOST_TEST(a.j == b.j);
  // a rebuild on moved particles of the same count keeps the buffers if they fit
  const auto* pj = b.j.data();
  for (auto& p : x) p *= 1.0001;  // slightly fewer pairs
  search.build(x, b);
  BOOST_TEST(b.numPairs() <= a.numPairs());
  BOOST_TEST(b.j.data() == pj);
}

BOOST_AUTO_TEST_CASE(non_finite_position) {
  std::vector<Vec<2>> x = {Vec<2>(0, 0), Vec<2>(std::nan(""), 0)};
  NeighbourSearch<2> search(0.1);
  NeighbourList<2> nl;
  BOOST_CHECK_THROW(search.build(x, nl), NumericalError);
}

BOOST_AUTO_TEST_CASE(cell_order_is_a_sorting_permutation) {
  auto x = randomPoints<2>(5000, -2.0, 3.0, 12);
  NeighbourSearch<2> search(0.1);
  auto perm = search.cellOrder(x);
  BOOST_REQUIRE(perm.size() == x.size());
  std::vector<Index> s = perm;
  std::sort(s.begin(), s.end());
  for (std::size_t k = 0; k < s.size(); ++k) BOOST_REQUIRE(s[k] == Index(k));
  // reordered particles: the search gives the same pairs, relabelled, and
  // consecutive particles are close (cell order): the mean index distance of
  // neighbours drops by orders of magnitude.
  std::vector<Vec<2>> y(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = x[perm[k]];
  NeighbourList<2> nx, ny;
  search.build(x, nx);
  search.build(y, ny);
  BOOST_REQUIRE(nx.numPairs() == ny.numPairs());
  double spreadX = 0, spreadY = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (Index p = nx.begin(i); p < nx.end(i); ++p) spreadX += std::abs(double(nx.j[p]) - double(i));
    for (Index p = ny.begin(i); p < ny.end(i); ++p) spreadY += std::abs(double(ny.j[p]) - double(i));
  }
  BOOST_TEST_MESSAGE("mean |i-j|: input order " << spreadX / nx.numPairs() << ", cell order "
                                                << spreadY / ny.numPairs());
  BOOST_TEST(spreadY < 0.1 * spreadX);
  // relabelled rows hold the same neighbours
  std::vector<Index> inv(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) inv[perm[k]] = Index(k);
  for (std::size_t k = 0; k < x.size(); k += 37) {
    std::vector<Index> a, b;
    for (Index p = ny.begin(k); p < ny.end(k); ++p) a.push_back(perm[ny.j[p]]);
    const std::size_t i = perm[k];
    for (Index p = nx.begin(i); p < nx.end(i); ++p) b.push_back(nx.j[p]);
    std::sort(a.begin(), a.end());
    BOOST_TEST_REQUIRE(a == b);
  }
}
