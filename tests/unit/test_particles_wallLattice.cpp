// Wall boxes of any size (libsph/particles/WallLattice.hpp, docs/boundaries.md): on
// sweeps of box sizes whose residual runs from 0.01 d0 to 0.99 d0, in 2D and 3D, with
// closed and open faces, one and three layers:
//   - no gap wider than d0: neighbouring coordinates on each axis are at most d0 apart,
//     and every point of the wall's layer region lies within sqrt(D)/2 d0 of a wall
//     particle (the covering radius of the d0 lattice), checked by brute force on a
//     sample grid of the region;
//   - no two wall particles closer than 0.5 d0 (brute force over all pairs);
//   - a whole-number box gives exactly the lattice min + (i + 1/2) d0;
// and through the generator: the 4 m tank at d0 = 3 cm is built, with the warning.
#define BOOST_TEST_MODULE particles_wallLattice
#include <boost/test/unit_test.hpp>

#include "particles/ParticleGenerator.hpp"
#include "particles/WallLattice.hpp"
#include <cmath>
#include <iostream>
#include <sstream>

using namespace shizuku;

namespace {

constexpr double kRound = 1e-9;  // round-off, in units of d0

struct Box {
  std::vector<double> size;  // in units of d0
  int layers;
  std::vector<bool> open;    // -x +x -y +y (-z +z)
};

template <int D>
std::vector<Vec<D>> build(const Box& b, std::array<WallAxis, D>& axes) {
  for (int k = 0; k < D; ++k) axes[k] = wallAxis(0.0, b.size[k], 1.0, b.layers, b.open[2 * k], b.open[2 * k + 1]);
  std::vector<Vec<D>> p;
  wallBoxPoints<D>(axes, p);
  return p;
}

// Smallest distance between two particles.
template <int D>
double closestPair(const std::vector<Vec<D>>& p) {
  double m = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) m = std::min(m, (p[i] - p[j]).squaredNorm());
  return std::sqrt(m);
}

// Largest distance from a point of the layer region (sampled every `step` d0) to its
// nearest wall particle.
template <int D>
double largestHole(const Box& b, const std::vector<Vec<D>>& p, double step) {
  std::array<double, D> lo, hi;
  for (int k = 0; k < D; ++k) {
    lo[k] = b.open[2 * k] ? 0 : -b.layers;
    hi[k] = b.size[k] + (b.open[2 * k + 1] ? 0 : b.layers);
  }
  std::array<long, D> n, i{};
  for (int k = 0; k < D; ++k) n[k] = long(std::ceil((hi[k] - lo[k]) / step)) + 1;
  double worst = 0;
  for (;;) {
    Vec<D> x;
    bool inner = true;
    for (int k = 0; k < D; ++k) {
      x[k] = std::min(lo[k] + double(i[k]) * step, hi[k]);
      // the plane of an open face belongs to the opening, not to the layers
      inner = inner && (b.open[2 * k] ? x[k] >= 0 : x[k] > 0) && (b.open[2 * k + 1] ? x[k] <= b.size[k] : x[k] < b.size[k]);
    }
    if (!inner) {
      double d = 1e300;
      for (const auto& q : p) d = std::min(d, (q - x).squaredNorm());
      worst = std::max(worst, std::sqrt(d));
    }
    int k = 0;
    for (; k < D; ++k) {
      if (++i[k] < n[k]) break;
      i[k] = 0;
    }
    if (k == D) return worst;
  }
}

// The residuals of the sweep, in units of d0.
const std::vector<double> kResiduals = {0.01, 0.1, 0.25, 0.49, 0.5, 0.51, 0.75, 0.9, 0.99};

template <int D>
void checkBox(const Box& b, double sampleStep) {
  std::array<WallAxis, D> axes;
  const auto p = build<D>(b, axes);
  std::ostringstream name;
  for (double s : b.size) name << s << " ";
  BOOST_TEST_CONTEXT(D << "D box " << name.str() << "d0, " << b.layers << " layers") {
    for (int k = 0; k < D; ++k) {
      BOOST_TEST(axes[k].spacing <= 1.0 + kRound);
      for (std::size_t j = 1; j < axes[k].x.size(); ++j) {
        const double gap = axes[k].x[j] - axes[k].x[j - 1];
        BOOST_TEST(gap <= 1.0 + kRound);
        BOOST_TEST(gap >= 0.5 - kRound);
      }
    }
    BOOST_TEST(closestPair<D>(p) >= 0.5 - kRound);
    BOOST_TEST(largestHole<D>(b, p, sampleStep) <= std::sqrt(double(D)) / 2 + kRound);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(sweep_2d_no_gap_and_no_close_pair) {
  for (double n : {0.0, 1.0, 2.0, 5.0, 12.0})
    for (double r : kResiduals)
      for (int layers : {1, 3})
        for (bool openTop : {false, true}) {
          if (n + r < 0.5) continue;
          checkBox<2>({{n + r, 4 + r / 3}, layers, {false, false, false, openTop}}, 0.125);
          checkBox<2>({{3 + r / 2, n + r}, layers, {openTop, false, false, false}}, 0.125);
        }
}

BOOST_AUTO_TEST_CASE(sweep_3d_no_gap_and_no_close_pair) {
  for (double n : {1.0, 3.0})
    for (double r : kResiduals)
      for (bool openTop : {false, true})
        checkBox<3>({{n + r, 2 + r / 2, 3 - r / 3}, openTop ? 3 : 2, {false, false, false, openTop, false, false}}, 0.5);
}

BOOST_AUTO_TEST_CASE(whole_number_box_is_the_plain_lattice) {
  // 0.3 / 0.1 = 2.9999999999999996: whole; every coordinate is min + (i + 1/2) d0 exactly.
  const WallAxis a = wallAxis(0.0, 0.3, 0.1, 3, false, false);
  BOOST_TEST(a.whole);
  BOOST_TEST(a.intervals == 3);
  BOOST_TEST(a.x.size() == 9u);
  for (long i = 0; i < 9; ++i) BOOST_TEST(a.x[i] == 0.0 + (double(i - 3) + 0.5) * 0.1);
  // 4 m at 3 cm: 133.33 spacings -> 134 intervals of 4/134 m; layers at 3 cm behind each face
  const WallAxis t = wallAxis(0.0, 4.0, 0.03, 3, false, false);
  BOOST_TEST(!t.whole);
  BOOST_TEST(t.intervals == 134);
  BOOST_TEST(t.spacing == 4.0 / 134, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(t.x.front() == -0.075, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(t.x.back() == 4.075, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(t.x[t.innerBegin] == 2.0 / 134, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(generator_builds_a_4m_tank_at_3cm_with_a_warning) {
  std::ostringstream out;
  auto* old = std::cout.rdbuf(out.rdbuf());
  const auto g = generateParticles<2>(Dictionary::fromString(
      "spacing 0.03;\nregions {\n water { type fluid; shape box; min (0 0); max (4 1); }\n"
      " tank { type wall; shape box; min (0 0); max (4 2); layers 3; open (top); }\n}\n",
      "case/system/particlesDict"));
  std::cout.rdbuf(old);
  const std::string log = out.str();
  BOOST_TEST_INFO("log: " << log);
  BOOST_TEST(log.find("Warning: case/system/particlesDict:4:") != std::string::npos);
  BOOST_TEST(log.find("wall box 'tank': size 4 m in x is 133.33 spacings (d0 = 0.03 m); faces along x use spacing "
                      "0.02985074627 m (134 intervals)") != std::string::npos);
  BOOST_TEST(log.find("size 2 m in y is 66.667 spacings") != std::string::npos);
  // x: 3 + 134 + 3 coordinates, y: 3 + 67 (open top): 140 * 70 - 134 * 67 = 822 wall particles
  std::size_t walls = 0, fluid = 0;
  for (auto t : g.set.type) (t == std::uint8_t(ParticleType::wall) ? walls : fluid) += 1;
  BOOST_TEST(walls == 822u);
  BOOST_TEST(fluid == 133u * 33u);  // the fluid lattice is unchanged: floor(4/0.03) x floor(1/0.03)
}
