// Tests of the particle generator (system/particlesDict, docs/design.md 1.2;
// docs/method.md 11 for the wall layers): particle counts and positions of fluid
// boxes, circles, spheres and wall boxes worked out by hand, removal of fluid
// that overlaps walls (checked against a brute-force search), each initial
// velocity type against its formula, the periodic box, and the input errors.
#define BOOST_TEST_MODULE particles_generator
#include <boost/test/unit_test.hpp>

#include "particles/ParticleGenerator.hpp"
#include "../support/ErrorOf.hpp"
#include <cmath>
#include <limits>

using namespace shizuku;

namespace {

template <int D> GeneratedParticles<D> generate(const std::string& text) {
  return generateParticles<D>(Dictionary::fromString(text, "case/system/particlesDict"));
}

template <int D> std::string errorOf(const std::string& text) {
  return test::errorOf([&] { generate<D>(text); });
}

#define CHECK_ERROR(D, text, ...) CHECK_MESSAGE(errorOf<D>(text), __VA_ARGS__)

template <int D> std::size_t countType(const ParticleSet<D>& s, ParticleType t) {
  std::size_t n = 0;
  for (auto ty : s.type) n += ty == std::uint8_t(t);
  return n;
}

template <int D> Vec<D> lowest(const std::vector<Vec<D>>& x, std::size_t b, std::size_t e) {
  Vec<D> m = Vec<D>::Constant(std::numeric_limits<double>::max());
  for (std::size_t i = b; i < e; ++i) m = m.cwiseMin(x[i]);
  return m;
}
template <int D> Vec<D> highest(const std::vector<Vec<D>>& x, std::size_t b, std::size_t e) {
  Vec<D> m = Vec<D>::Constant(-std::numeric_limits<double>::max());
  for (std::size_t i = b; i < e; ++i) m = m.cwiseMax(x[i]);
  return m;
}

const std::string kDamBreak = R"(
spacing 0.01;
regions
{
    column { type fluid; shape box; min (0 0); max (0.8 0.5); }
    tank   { type wall;  shape box; min (0 0); max (2 3); open (top); }
}
)";

}  // namespace

// Positions are computed as min + (i + 1/2) d0 in double precision: 1e-12 m
// covers the round-off of those two operations (measured: <= 2e-16 here).
constexpr double kPos = 1e-12;

BOOST_AUTO_TEST_CASE(rotating_patch_box_and_rigid_rotation) {
  const auto g = generate<2>(R"(
spacing 1 [cm];
regions
{
    patch
    {
        type     fluid;
        shape    box;   min (-50 -50) [cm];   max (50 50) [cm];
        velocity { type rigidRotation; omega 1; centre (0 0); }
    }
}
)");
  const ParticleSet<2>& s = g.set;
  BOOST_TEST(s.size() == 10000u);
  BOOST_TEST(countType(s, ParticleType::fluid) == 10000u);
  BOOST_TEST(s.spacing == 0.01);
  BOOST_TEST(!g.periodic.any());
  const Vec<2> lo = lowest(s.position, 0, s.size()), hi = highest(s.position, 0, s.size());
  BOOST_TEST(lo[0] == -0.495, boost::test_tools::tolerance(kPos));
  BOOST_TEST(lo[1] == -0.495, boost::test_tools::tolerance(kPos));
  BOOST_TEST(hi[0] == 0.495, boost::test_tools::tolerance(kPos));
  BOOST_TEST(hi[1] == 0.495, boost::test_tools::tolerance(kPos));
  // x fastest: particle 1 is one spacing to the right of particle 0, particle 100 one above
  BOOST_TEST((s.position[1] - s.position[0] - Vec<2>(0.01, 0)).norm() < kPos);
  BOOST_TEST((s.position[100] - s.position[0] - Vec<2>(0, 0.01)).norm() < kPos);
  double maxErr = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec<2>& x = s.position[i];
    maxErr = std::max(maxErr, (s.velocity[i] - Vec<2>(-x[1], x[0])).norm());
    BOOST_TEST(s.id[i] == std::int64_t(i));
    BOOST_TEST(s.pressure[i] == 0.0);
    BOOST_TEST(s.density[i] == 0.0);
    BOOST_TEST(s.surface[i] == 0);
  }
  BOOST_TEST(maxErr == 0.0);  // the same two products, evaluated exactly the same way
  // counter-clockwise for omega > 0: on the +x axis the velocity points to +y
  std::size_t right = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.position[i][0] > 0.49 && std::abs(s.position[i][1]) < 0.01) right = i;
  BOOST_TEST(s.velocity[right][1] > 0.49);
}

BOOST_AUTO_TEST_CASE(dam_break_tank_open_top) {
  const auto g = generate<2>(kDamBreak);
  const ParticleSet<2>& s = g.set;
  // Fluid: 0.8 / 0.01 = 80 columns times 0.5 / 0.01 = 50 rows = 4000.
  // Walls: the tank surface is 2.0 x 3.0 m = 200 x 300 cells, 3 layers outside,
  // top open. Bottom: 3 rows of 3 + 200 + 3 = 206 particles = 618 (corners included);
  // left and right: 3 columns each over the 300 rows up to the open top = 2 * 900 = 1800.
  // Total 618 + 1800 = 2418 (= 206 * 303 - 200 * 300).
  BOOST_TEST(countType(s, ParticleType::fluid) == 4000u);
  BOOST_TEST(countType(s, ParticleType::wall) == 2418u);
  BOOST_TEST(s.size() == 6418u);
  for (std::size_t i = 0; i < s.size(); ++i) BOOST_TEST(s.isFluid(i) == (i < 4000));  // fluid first
  const Vec<2> flo = lowest(s.position, 0, 4000), fhi = highest(s.position, 0, 4000);
  BOOST_TEST(flo[0] == 0.005, boost::test_tools::tolerance(kPos));
  BOOST_TEST(fhi[0] == 0.795, boost::test_tools::tolerance(kPos));
  BOOST_TEST(fhi[1] == 0.495, boost::test_tools::tolerance(kPos));
  const Vec<2> wlo = lowest(s.position, 4000, s.size()), whi = highest(s.position, 4000, s.size());
  BOOST_TEST(wlo[0] == -0.025, boost::test_tools::tolerance(kPos));
  BOOST_TEST(wlo[1] == -0.025, boost::test_tools::tolerance(kPos));
  BOOST_TEST(whi[0] == 2.025, boost::test_tools::tolerance(kPos));
  BOOST_TEST(whi[1] == 2.995, boost::test_tools::tolerance(kPos));  // side walls end at the open top
  for (std::size_t i = 4000; i < s.size(); ++i) {
    BOOST_TEST(s.velocity[i].norm() == 0.0);
    const Vec<2>& x = s.position[i];
    const bool inside = x[0] > 0 && x[0] < 2 && x[1] > 0 && x[1] < 3;
    BOOST_TEST(!inside);
  }
  // the first fluid row and the first wall row are one spacing apart, the wall line halfway
  double closest = 1e9;
  for (std::size_t i = 0; i < 4000; ++i)
    for (std::size_t j = 4000; j < s.size(); ++j) closest = std::min(closest, (s.position[i] - s.position[j]).norm());
  BOOST_TEST(closest == 0.01, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(wall_layers_and_open_faces) {
  // closed 2D box 10 x 5 cells, 2 layers: (10 + 4) * (5 + 4) - 10 * 5 = 76
  auto closed = generate<2>(R"(spacing 1; regions { f { type fluid; shape box; min (0 0); max (1 1); }
      w { type wall; shape box; min (0 0); max (10 5); layers 2; } })");
  BOOST_TEST(countType(closed.set, ParticleType::wall) == 76u);
  // open left and top, 1 layer: x columns 10 + 1 (right), y rows 1 (bottom) + 5: 11 * 6 - 50 = 16
  auto open = generate<2>(R"(spacing 1; regions { f { type fluid; shape box; min (0 0); max (1 1); }
      w { type wall; shape box; min (0 0); max (10 5); layers 1; open (left top); } })");
  BOOST_TEST(countType(open.set, ParticleType::wall) == 16u);
  const ParticleSet<2>& s = open.set;
  const Vec<2> lo = lowest(s.position, 1, s.size()), hi = highest(s.position, 1, s.size());
  BOOST_TEST(lo[0] == 0.5);   // no layer on the left: the bottom wall starts at the box edge
  BOOST_TEST(lo[1] == -0.5);
  BOOST_TEST(hi[0] == 10.5);
  BOOST_TEST(hi[1] == 4.5);
  // two walls sharing layers do not double particles: the second box's layers
  // coincide with part of the first one's (4 x 1 box below a 4 x 1 box, 1 layer):
  // the rings share the row y = 1.5, so the union is the 6 x 5 lattice (rows y = -0.5 .. 3.5)
  // minus the two 4 x 1 interiors = 30 - 8 = 22 (without merging: 14 + 14 = 28)
  auto stacked = generate<2>(R"(spacing 1; regions { f { type fluid; shape box; min (1 0); max (2 1); }
      a { type wall; shape box; min (0 0); max (4 1); layers 1; }
      b { type wall; shape box; min (0 2); max (4 3); layers 1; } })");
  BOOST_TEST(countType(stacked.set, ParticleType::wall) == 22u);
}

BOOST_AUTO_TEST_CASE(box_not_a_multiple_of_the_spacing) {
  // 0.255 / 0.01 = 25.5: round -> 26 intervals of 0.255/26 from min to max, no empty strip
  const auto g = generate<2>("spacing 0.01; regions { f { type fluid; shape box; min (0 0); max (0.255 0.01); } }");
  BOOST_TEST(g.set.size() == 26u);
  BOOST_TEST(lowest(g.set.position, 0, 26)[0] == 0.5 * 0.255 / 26, boost::test_tools::tolerance(kPos));
  BOOST_TEST(highest(g.set.position, 0, 26)[0] == 0.255 - 0.5 * 0.255 / 26, boost::test_tools::tolerance(kPos));
  // 0.252 / 0.01 = 25.2: 25 intervals of 0.01008
  BOOST_TEST(generate<2>("spacing 0.01; regions { f { type fluid; shape box; min (0 0); max (0.252 0.01); } }")
                 .set.size() == 25u);
  // 0.3 / 0.1 = 2.9999999999999996 in floating point: still 3 cells at d0
  const auto w = generate<2>("spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (0.3 0.1); } }");
  BOOST_TEST(w.set.size() == 3u);
  BOOST_TEST(highest(w.set.position, 0, 3)[0] == 0.25, boost::test_tools::tolerance(kPos));
}

namespace {
// Water filling a tank of (n + r) d0 across (x, and z in 3D) and 6 d0 deep, walls 3 layers,
// d0 = 1: the outer fluid columns must sit d0/2 (1 +- 1/(2m)) from the wall surfaces on both
// sides (m = round(n + r)) and no two particles, fluid or wall, closer than 0.5 d0 (brute force).
template <int D>
void checkFluidAgainstNonWholeWalls(double width) {
  auto v = [&](double x, double y) {
    return "(" + std::to_string(x) + " " + std::to_string(y) + (D == 3 ? " " + std::to_string(x) : "") + ")";
  };
  const auto g = generate<D>("spacing 1; regions { f { type fluid; shape box; min " + v(0, 0) + "; max " +
                             v(width, 6) + "; }\n t { type wall; shape box; min " + v(0, 0) + "; max " +
                             v(width, 8) + "; open (top); } }");
  const auto& x = g.set.position;
  const std::size_t nf = countType(g.set, ParticleType::fluid);
  const double m = std::max(1.0, std::round(width)), slack = 0.25 / m + 1e-9;
  BOOST_TEST_CONTEXT(D << "D tank " << width << " d0 wide") {
    for (int k = 0; k < D; k += 2) {
      BOOST_TEST(std::abs(lowest(x, 0, nf)[k] - 0.5) <= slack);
      BOOST_TEST(std::abs(width - highest(x, 0, nf)[k] - 0.5) <= slack);
    }
    BOOST_TEST(nf == std::size_t(std::pow(m, D - 1) * 6));
    double closest = 1e9;
    for (std::size_t i = 0; i < nf; ++i)
      for (std::size_t j = i + 1; j < x.size(); ++j) closest = std::min(closest, (x[i] - x[j]).norm());
    BOOST_TEST(closest >= 0.5 - 1e-9);
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(fluid_box_fills_a_tank_of_any_size_to_both_walls) {
  for (double r : {0.0, 0.01, 0.1, 0.25, 0.3, 0.49, 0.5, 0.51, 0.75, 0.9, 0.99}) {
    checkFluidAgainstNonWholeWalls<2>(12 + r);
    checkFluidAgainstNonWholeWalls<3>(5 + r);
  }
  checkFluidAgainstNonWholeWalls<2>(1.4);  // one column, 0.7 d0 from each wall
  checkFluidAgainstNonWholeWalls<2>(1.6);  // two columns of 0.8 d0
}

BOOST_AUTO_TEST_CASE(circle_and_sphere_counts) {
  // Disc of radius 5 d0 on the lattice centre + (i + 1/2) d0: per quadrant, points
  // (a, b) in {0.5 .. 4.5}^2 with a^2 + b^2 < 25: a = 0.5: 5, 1.5: 5, 2.5: 4, 3.5: 4,
  // 4.5: 2 -> 20, times 4 = 80 (area 78.5 d0^2).
  for (const char* centre : {"(0 0)", "(1.3 -2.1)"}) {
    const auto g = generate<2>(std::string("spacing 1; regions { drop { type fluid; shape circle; centre ") + centre +
                               "; radius 5; } }");
    BOOST_TEST(g.set.size() == 80u);
    Vec<2> mean = Vec<2>::Zero();
    double rmax = 0;
    Vec<2> cc = std::string(centre) == "(0 0)" ? Vec<2>(0, 0) : Vec<2>(1.3, -2.1);
    for (const auto& x : g.set.position) {
      mean += x / 80.0;
      rmax = std::max(rmax, (x - cc).norm());
    }
    BOOST_TEST((mean - cc).norm() < 1e-12);  // symmetric about the centre
    BOOST_TEST(rmax < 5.0);                  // strictly inside
  }
  // Sphere of radius 2.5 d0: per octant, (a, b, c) in {0.5, 1.5}^3 except (1.5, 1.5, 1.5)
  // (sum of squares 6.75 > 6.25); any 2.5 gives >= 6.75. 7 * 8 = 56 (volume 65.4 d0^3).
  const auto s = generate<3>("spacing 1; regions { ball { type fluid; shape circle; centre (0 0 0); radius 2.5; } }");
  BOOST_TEST(s.set.size() == 56u);
  // A radius through lattice points: 0.5^2 + 0.5^2 = 0.5, radius sqrt(0.5) keeps none of
  // the four nearest points (strictly inside only) -> the region is empty, an error.
  CHECK_ERROR(2, "spacing 1; regions { tiny { type fluid; shape circle; centre (0 0); radius 0.7071067811865476; } }",
              "keyword 'tiny'", "holds no particle");
}

BOOST_AUTO_TEST_CASE(box_3d_in_closed_tank) {
  // tank 10^3 cells, 2 layers: 14^3 - 10^3 = 1744 walls; fluid half of it: 5 * 10 * 10 = 500
  const auto g = generate<3>(R"(
spacing 0.01;
regions
{
    water { type fluid; shape box; min (0 0 0); max (0.05 0.1 0.1); velocity { type uniform; value (1 2 3); } }
    tank  { type wall; shape box; min (0 0 0); max (0.1 0.1 0.1); layers 2; }
}
)");
  BOOST_TEST(countType(g.set, ParticleType::fluid) == 500u);
  BOOST_TEST(countType(g.set, ParticleType::wall) == 1744u);
  for (std::size_t i = 0; i < 500; ++i) BOOST_TEST((g.set.velocity[i] - Vec<3>(1, 2, 3)).norm() == 0.0);
  const Vec<3> hi = highest(g.set.position, 0, 500);
  BOOST_TEST(hi[0] == 0.045, boost::test_tools::tolerance(kPos));
  BOOST_TEST(hi[2] == 0.095, boost::test_tools::tolerance(kPos));
  // open top (+y) in 3D: 14 * 12 * 14 - 10 * 10 * 10 = 1352; open front/back (-z +z): 14 * 14 * 10 - 1000 = 960
  auto walls3 = [](const std::string& open) {
    return countType(generate<3>("spacing 0.01; regions { f { type fluid; shape box; min (0 0 0); max (0.01 0.01 0.01); }"
                                 " t { type wall; shape box; min (0 0 0); max (0.1 0.1 0.1); layers 2; open " +
                                 open + "; } }").set,
                     ParticleType::wall);
  };
  BOOST_TEST(walls3("(top)") == 1352u);
  BOOST_TEST(walls3("(front back)") == 960u);
}

// A solid wall box (an obstacle) on the floor of a tank: its layers lie inside it, the
// first s/2 behind each face (s = its lattice spacing, d0 on a whole number of spacings),
// its core deeper than `layers` is empty, no fluid lies inside it, and the fluid count is
// the tank's minus the block's cells. Counts by hand.
template <int D>
void checkSolidBox(const std::string& blockMax, const Vec<D>& hi, const std::array<long, D>& cells,
                   std::size_t fluidExpected) {
  const std::string z = D == 3 ? " 0" : "", zMax = D == 3 ? " 0.3" : "";
  const auto g = generate<D>("spacing 0.01; regions {\n"
                             " water { type fluid; shape box; min (0 0" + z + "); max (0.6 0.3" + zMax + "); }\n"
                             " tank { type wall; shape box; min (0 0" + z + "); max (0.6 0.5" + zMax + "); open (top); }\n"
                             " block { type wall; shape box; min (0.2 0" + z + "); max " + blockMax +
                             "; layers 3; solid yes; }\n}\n");
  const auto& x = g.set.position;
  Vec<D> blo = Vec<D>::Zero();
  blo[0] = 0.2;
  std::size_t inBlock = 0, fluid = 0;
  Vec<D> first = Vec<D>::Constant(1e9), last = Vec<D>::Constant(-1e9);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const bool inside = ((x[i] - blo).array() > 0).all() && ((hi - x[i]).array() > 0).all();
    if (g.set.isFluid(i)) {
      ++fluid;
      BOOST_TEST(!inside);
    } else if (inside) {
      ++inBlock;
      first = first.cwiseMin(x[i]);
      last = last.cwiseMax(x[i]);
    }
  }
  double all = 1, core = 1;
  for (int k = 0; k < D; ++k) {
    all *= double(cells[k]);
    core *= double(std::max(0L, cells[k] - 6));
    const double s = (hi[k] - blo[k]) / double(cells[k]);
    BOOST_TEST(std::abs(first[k] - (blo[k] + s / 2)) < 1e-12);
    BOOST_TEST(std::abs(last[k] - (hi[k] - s / 2)) < 1e-12);
  }
  BOOST_TEST(inBlock == std::size_t(all - core));
  BOOST_TEST(fluid == fluidExpected);
  BOOST_REQUIRE(g.walls.size() == 2u);
  BOOST_TEST(g.walls[1].solid);
  BOOST_TEST((g.walls[1].outerMin - blo).norm() == 0.0);
  BOOST_TEST((g.walls[1].outerMax - hi).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(solid_box_obstacle_2d_and_3d) {
  // Whole: 0.2 x 0.12 (20 x 12 cells): 240 - 14 x 6 = 156 wall particles; fluid 60 x 30
  // minus 20 x 12. Not whole: 0.213 x 0.1071 (22 and 11 intervals of s < d0), the fluid
  // cells it covers: x in (0.2, 0.413): 21 columns (0.205 .. 0.405), y < 0.1071: 11 rows.
  checkSolidBox<2>("(0.4 0.12)", Vec<2>(0.4, 0.12), {20, 12}, 60 * 30 - 20 * 12);
  checkSolidBox<2>("(0.413 0.1071)", Vec<2>(0.413, 0.1071), {22, 11}, 60 * 30 - 21 * 11);
  // 3D: 0.2 x 0.1 x 0.1 (20 x 10 x 10 cells; core 14 x 4 x 4).
  checkSolidBox<3>("(0.4 0.1 0.1)", Vec<3>(0.4, 0.1, 0.1), {20, 10, 10}, 60 * 30 * 30 - 20 * 10 * 10);
  CHECK_ERROR(2, "spacing 0.01; regions { w { type fluid; shape box; min (0 0); max (1 1); }\n"
                 " b { type wall; shape box; min (0.2 0); max (0.4 0.1); solid yes; open (top); } }",
              "particlesDict:2", "open", "solid");
}

BOOST_AUTO_TEST_CASE(fluid_overlapping_walls_is_removed) {
  // A column reaching through the left wall's 3 layers: x centres -0.025 .. 0.845 (88);
  // the 3 columns with x < 0 lie in the wall's layer region: 85 * 50 = 4250 remain.
  auto g = generate<2>(R"(
spacing 0.01;
regions
{
    column { type fluid; shape box; min (-0.03 0); max (0.85 0.5); }
    tank   { type wall;  shape box; min (0 0); max (2 3); open (top); }
}
)");
  BOOST_TEST(countType(g.set, ParticleType::fluid) == 4250u);
  BOOST_TEST(lowest(g.set.position, 0, 4250)[0] == 0.005, boost::test_tools::tolerance(kPos));
  // An off-lattice column reaching into the layers of a small tank on every side (but
  // not beyond them, which is an error): compare with a brute-force check of the rule
  // (not inside the layer region, no wall particle closer than d0/2).
  const double d0 = 0.1;
  auto h = generate<2>(R"(
spacing 0.1;
regions
{
    blob { type fluid; shape box; min (-0.237 -0.263); max (1.21 0.74); }
    tank { type wall;  shape box; min (0 0); max (1 0.5); layers 3; }
}
)");
  const std::size_t nf = countType(h.set, ParticleType::fluid);
  std::size_t expected = 0;
  for (int j = 0; j < int(std::floor((0.74 + 0.263) / d0)); ++j)
    for (int i = 0; i < int(std::floor((1.21 + 0.237) / d0)); ++i) {
      const Vec<2> x(-0.237 + (i + 0.5) * d0, -0.263 + (j + 0.5) * d0);
      const bool inOuter = x[0] > -0.3 && x[0] < 1.3 && x[1] > -0.3 && x[1] < 0.8;
      const bool inInner = x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 0.5;
      bool near = false;
      for (std::size_t w = nf; w < h.set.size(); ++w) near = near || (h.set.position[w] - x).norm() < 0.5 * d0;
      if (!(inOuter && !inInner) && !near) ++expected;
    }
  BOOST_TEST(nf == expected);
  BOOST_TEST(nf > 0u);
  for (std::size_t i = 0; i < nf; ++i)
    for (std::size_t w = nf; w < h.set.size(); ++w) BOOST_TEST((h.set.position[i] - h.set.position[w]).norm() >= 0.5 * d0);
}

BOOST_AUTO_TEST_CASE(velocity_types_match_their_formulas) {
  // uniform, with a unit
  auto u = generate<2>("spacing 1 [cm]; regions { f { type fluid; shape box; min (0 0); max (0.1 0.1);"
                       " velocity { type uniform; value (3 -4) [cm/s]; } } }");
  for (const auto& v : u.set.velocity) BOOST_TEST((v - Vec<2>(0.03, -0.04)).norm() < 1e-15);
  // rigid rotation about an off-origin centre, clockwise (omega < 0)
  auto r = generate<2>("spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (1 1);"
                       " velocity { type rigidRotation; omega -2; centre (0.3 0.4); } } }");
  for (std::size_t i = 0; i < r.set.size(); ++i) {
    const Vec<2>& x = r.set.position[i];
    BOOST_TEST((r.set.velocity[i] - Vec<2>(2 * (x[1] - 0.4), -2 * (x[0] - 0.3))).norm() < 1e-14);
  }
  // 3D rigid rotation: U = omega x (x - c), written out component by component
  auto r3 = generate<3>("spacing 0.25; regions { f { type fluid; shape box; min (0 0 0); max (1 1 1);"
                        " velocity { type rigidRotation; omega (1 -2 3); centre (0.5 0 0); } } }");
  BOOST_TEST(r3.set.size() == 64u);
  for (std::size_t i = 0; i < r3.set.size(); ++i) {
    const Vec<3> d = r3.set.position[i] - Vec<3>(0.5, 0, 0);
    const Vec<3> expect(-2 * d[2] - 3 * d[1], 3 * d[0] - 1 * d[2], 1 * d[1] + 2 * d[0]);
    BOOST_TEST((r3.set.velocity[i] - expect).norm() < 1e-14);
  }
  // linear: U = G (x - c), G row by row
  auto l = generate<2>("spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (1 1);"
                       " velocity { type linear; gradient ((1 2) (3 4)); centre (0.5 0.5); } } }");
  for (std::size_t i = 0; i < l.set.size(); ++i) {
    const Vec<2> d = l.set.position[i] - Vec<2>(0.5, 0.5);
    BOOST_TEST((l.set.velocity[i] - Vec<2>(d[0] + 2 * d[1], 3 * d[0] + 4 * d[1])).norm() < 1e-14);
  }
  // expression (Taylor-Green); muParser and libm agree to round-off (measured 1e-16, allow 1e-13)
  auto e = generate<2>(R"dict(spacing 0.05; regions { f { type fluid; shape box; min (0 0); max (1 1);
      velocity { type expression; value ("sin(2*pi*x)*cos(2*pi*y)" "-cos(2*pi*x)*sin(2*pi*y)"); } } })dict");
  BOOST_TEST(e.set.size() == 400u);
  double err = 0;
  for (std::size_t i = 0; i < e.set.size(); ++i) {
    const double x = e.set.position[i][0], y = e.set.position[i][1];
    const Vec<2> expect(std::sin(2 * M_PI * x) * std::cos(2 * M_PI * y), -std::cos(2 * M_PI * x) * std::sin(2 * M_PI * y));
    err = std::max(err, (e.set.velocity[i] - expect).norm());
  }
  BOOST_TEST(err < 1e-13);
  // 3D expression using z
  auto e3 = generate<3>(R"dict(spacing 0.5; regions { f { type fluid; shape box; min (0 0 0); max (1 1 1);
      velocity { type expression; value ("z" "2*x" "x*y*z"); } } })dict");
  for (std::size_t i = 0; i < e3.set.size(); ++i) {
    const Vec<3>& x = e3.set.position[i];
    BOOST_TEST((e3.set.velocity[i] - Vec<3>(x[2], 2 * x[0], x[0] * x[1] * x[2])).norm() < 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(expression_errors) {
  const std::string head = "spacing 0.1;\nregions\n{\n  f\n  {\n    type fluid; shape box; min (0 0); max (1 1);\n";
  CHECK_ERROR(2, head + "    velocity { type expression;\n      value (\"sin(2*pi*x\" \"0\"); }\n  }\n}\n",
              "case/system/particlesDict:8:7: keyword 'value'", "muParser", "sin(2*pi*x");
  CHECK_ERROR(2, head + "    velocity { type expression;\n      value (\"q*x\" \"0\"); }\n  }\n}\n",
              "particlesDict:8:7: keyword 'value'", "muParser", "\"q\"");
  CHECK_ERROR(2, head + "    velocity { type expression;\n      value (\"x\"); }\n  }\n}\n",
              "particlesDict:8:7: keyword 'value'", "expected 2 expressions", "found 1");
  CHECK_ERROR(2, head + "    velocity { type expression;\n      value (\"1/(x-x)\" \"0\"); }\n  }\n}\n",
              "particlesDict:8:7: keyword 'value'", "(inf 0)");
  CHECK_ERROR(2, head + "    velocity { type rigidRotaton; }\n  }\n}\n", "particlesDict:7:16: keyword 'type'",
              "did you mean 'rigidRotation'?");
}

BOOST_AUTO_TEST_CASE(overlapping_fluid_regions) {
  CHECK_ERROR(2, R"(spacing 0.1;
regions
{
  lower { type fluid; shape box; min (0 0); max (1 1); }
  upper { type fluid; shape box; min (0.5 0.9); max (1 2); }
})",
              "particlesDict:5:3: keyword 'upper'", "fluid region 'upper' overlaps fluid region 'lower'",
              "particlesDict:4:3");
  CHECK_ERROR(2, R"(spacing 0.1; regions { box { type fluid; shape box; min (0 0); max (1 1); }
      drop { type fluid; shape circle; centre (1.2 0.5); radius 0.25; } })",
              "fluid region 'drop' overlaps fluid region 'box'");
  CHECK_ERROR(2, R"(spacing 0.1; regions { a { type fluid; shape circle; centre (0 0); radius 1; }
      b { type fluid; shape circle; centre (1.9 0); radius 1; } })",
              "'b' overlaps fluid region 'a'");
  // touching regions are fine: 10 * 10 + 10 * 10 particles, and a drop beside the box
  auto g = generate<2>(R"(spacing 0.1; regions { a { type fluid; shape box; min (0 0); max (1 1); }
      b { type fluid; shape box; min (0 1); max (1 2); }
      drop { type fluid; shape circle; centre (1.5 0.5); radius 0.5; } })");
  BOOST_TEST(countType(g.set, ParticleType::fluid) == 200u + 80u);  // the disc: radius 5 d0, 80 (see above)
}

BOOST_AUTO_TEST_CASE(periodic_box) {
  auto g = generate<2>(R"(spacing 0.1;
periodic { min (0 0); max (1 1); directions (x); }
regions { f { type fluid; shape box; min (0 0); max (1 1); } })");
  BOOST_TEST(g.periodic.periodic[0]);
  BOOST_TEST(!g.periodic.periodic[1]);
  BOOST_TEST(g.periodic.hi[0] == 1.0);
  BOOST_TEST(g.periodic.lo[1] == 0.0);
  auto all = generate<3>(R"(spacing 0.5; periodic { min (0 0 0); max (1 1 1); }
regions { f { type fluid; shape box; min (0 0 0); max (1 1 1); } })");
  BOOST_TEST((all.periodic.periodic[0] && all.periodic.periodic[1] && all.periodic.periodic[2]));
  BOOST_TEST(all.set.size() == 8u);
  CHECK_ERROR(2, "spacing 0.3; periodic { min (0 0); max (1 1); } regions { f { type fluid; shape box; min (0 0); max (0.9 0.9); } }",
              "keyword 'max'", "periodic length in x", "not a whole number of spacings");
  CHECK_ERROR(2, "spacing 0.1; periodic { min (0 0); max (1 1); directions (x z); } regions { f { type fluid; shape box; min (0 0); max (1 1); } }",
              "keyword 'directions'", "'z' is not a direction");
  CHECK_ERROR(2, "spacing 0.1; periodic { min (0 0); max (1 1); } regions { f { type fluid; shape box; min (0 0); max (1.5 1); } }",
              "keyword 'f'", "outside the periodic box in x");
}

BOOST_AUTO_TEST_CASE(input_errors) {
  const std::string box = "shape box; min (0 0); max (1 1);";
  CHECK_ERROR(2, "spacing 0; regions { f { type fluid; " + box + " } }", "keyword 'spacing'", "0 must be greater than 0 m");
  CHECK_ERROR(2, "spacing 1 [s]; regions { f { type fluid; " + box + " } }", "keyword 'spacing'",
              "unit [s] has dimension [s] but a length [m] is expected");
  CHECK_ERROR(2, "regions { f { type fluid; " + box + " } }", "keyword 'spacing': missing");
  CHECK_ERROR(2, "spacing 0.1; regions { w { type wall; " + box + " } }", "no fluid region");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; shape box; min (0.1 0.1); max (0.9 0.9); }\n"
                 "  w { type wall; shape box; min (0 0); max (1 1); } f2 { type fluid; shape box; min (-0.2 0); max (0 1); } }",
              "keyword 'f2'", "lies entirely inside walls");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " veloctiy { type uniform; value (0 0); } } }",
              "unknown keyword 'veloctiy'", "did you mean 'velocity'?");
  // a required keyword that is missing points at the misspelt one
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; shpe box; min (0 0); max (1 1); } }", "keyword 'shape': missing",
              "'shpe' (line 1) looks like a misspelling of it");
  CHECK_ERROR(2, "spacing 0.1; spacng 0.2; regions { f { type fluid; " + box + " } }",
              "unknown keyword 'spacng'", "did you mean 'spacing'?");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type liquid; " + box + " } }", "keyword 'type'", "'liquid' is not one of: fluid | wall");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (1 -1); } }",
              "keyword 'max'", "must exceed min");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (1 1 1); } }",
              "keyword 'max'", "2 components", "found 3");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " layers 2; } }", "keyword 'layers'",
              "only wall regions");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape box; min (0 0); max (2 2); velocity { type uniform; value (1 0); } } }",
              "keyword 'velocity'", "comes from its motion");
  // motion: only wall regions move
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " motion { type oscillating; amplitude (0.1 0); period 1; } } }",
              "keyword 'motion'", "only wall regions");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape box; min (0 0); max (2 2); motion 3; } }",
              "keyword 'motion'", "expected a sub-dictionary");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape box; min (0 0); max (2 2); open (tpo); } }",
              "keyword 'open'", "'tpo' is not a face", "did you mean 'top'?");
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape box; min (0 0); max (2 2); open (front); } }",
              "'front' is not a face");
  // a wall box of 20.5 x 20 spacings is built (test_particles_wallLattice checks its lattice)
  BOOST_TEST(errorOf<2>("spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape box; min (0 0); max (2.05 2); } }")
                 .empty());
  // a wall circle is a solid disc (test_particles_solidShapes): it has no open faces
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; " + box + " }\n w { type wall; shape circle; centre (0 0); radius 1; "
                 "open (top); } }",
              "keyword 'open'", "a circle wall is a solid body");
  CHECK_ERROR(2, "spacing 0.1; regions { f 1; }", "keyword 'f'", "expected a sub-dictionary");
  CHECK_ERROR(3, "dimension 2; spacing 0.1; regions { f { type fluid; shape box; min (0 0 0); max (1 1 1); } }",
              "keyword 'dimension'", "is 2 but the particles are being built in 3D");
  BOOST_TEST(generate<2>("dimension 2; spacing 0.5; regions { f { type fluid; " + box + " } }").set.size() == 4u);
  CHECK_ERROR(2, "spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (0.05 1); } }",
              "keyword 'max'", "thinner than one spacing");
}
