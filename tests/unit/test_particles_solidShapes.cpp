// Curved and STL regions of system/particlesDict (ParticleGenerator.hpp, ShapeRegion.hpp;
// docs/boundaries.md, "Curved and STL solids"), in 2D and 3D where the shape exists:
// phi of a ball and a cylinder by hand; the triangulated surface's inside test and
// distance against a box and an octahedron in closed form (rays through vertices and along
// edges included); the voxel shortcut of an STL solid against its exact test; fluid cylinders counted by hand and against a
// brute-force inside test; the layers of solid discs, balls and cylinders (caps included)
// against the lattice points of the shell found by brute force; fluid kept outside a solid
// ball and removed inside; STL cubes (ASCII and binary) giving the particles of the
// equivalent box; scale, rotate and translate moving a part as stated; a closed STL sphere
// (UV mesh) against its face planes; and the errors (open, empty, missing, unreadable,
// millimetres without scale, 2D, keys that do not apply).
#define BOOST_TEST_MODULE particles_solidShapes
#include <boost/test/unit_test.hpp>

#include "particles/BallShape.hpp"
#include "particles/CylinderShape.hpp"
#include "particles/ParticleGenerator.hpp"
#include "particles/StlShape.hpp"
#include "particles/TriangleSurface.hpp"
#include "../support/ErrorOf.hpp"
#include "../support/StlFiles.hpp"
#include "../support/TempCase.hpp"
#include <algorithm>
#include <functional>
#include <random>
#include <set>

using namespace shizuku;

namespace {

template <int D>
GeneratedParticles<D> generateIn(const std::string& caseDir, const std::string& text) {
  return generateParticles<D>(Dictionary::fromString(text, caseDir + "/system/particlesDict"));
}

template <int D>
std::vector<Vec<D>> pointsOf(const GeneratedParticles<D>& g, ParticleType t) {
  std::vector<Vec<D>> x;
  for (std::size_t i = 0; i < g.set.size(); ++i)
    if (g.set.type[i] == std::uint8_t(t)) x.push_back(g.set.position[i]);
  return x;
}

template <int D>
std::vector<Vec<D>> sortedPoints(std::vector<Vec<D>> x) {
  std::sort(x.begin(), x.end(), [](const Vec<D>& a, const Vec<D>& b) {
    return std::lexicographical_compare(a.data(), a.data() + D, b.data(), b.data() + D);
  });
  return x;
}

// Where a brute-force test puts a lattice point: inside the set, outside it, or within
// round-off of its edge (either is right).
enum class Expect { in, out, either };

// Every lattice point anchor + (i + 1/2) d0 with lo <= i < hi: `expect` says whether it is
// one of `points`; every point of `points` is a lattice point of that range. Returns the
// number of lattice points expected in.
template <int D>
std::size_t checkLattice(const std::vector<Vec<D>>& points, const Vec<D>& anchor, double d0, long lo, long hi,
                         const std::function<Expect(const Vec<D>&)>& expect) {
  std::set<std::array<long, D>> have;
  for (const auto& x : points) {
    std::array<long, D> i;
    for (int k = 0; k < D; ++k) {
      i[k] = std::lround((x[k] - anchor[k]) / d0 - 0.5);
      BOOST_TEST(std::abs(x[k] - (anchor[k] + (double(i[k]) + 0.5) * d0)) < 1e-12);  // on the lattice
      BOOST_TEST((i[k] >= lo && i[k] < hi));
    }
    have.insert(i);
  }
  std::size_t in = 0, wrong = 0;
  std::array<long, D> i;
  i.fill(lo);
  for (;;) {
    Vec<D> x;
    for (int k = 0; k < D; ++k) x[k] = anchor[k] + (double(i[k]) + 0.5) * d0;
    const Expect e = expect(x);
    const bool present = have.count(i) > 0;
    in += e == Expect::in;
    if ((e == Expect::in && !present) || (e == Expect::out && present)) ++wrong;
    int k = 0;
    for (; k < D; ++k) {
      if (++i[k] < hi) break;
      i[k] = lo;
    }
    if (k == D) break;
  }
  BOOST_TEST(wrong == 0u);
  return in;
}

// The shell -depth <= phi < 0 of a body, with a margin (in d0) for round-off.
Expect shell(double phi, double depth, double d0, double margin = 1e-7) {
  const double m = margin * d0;
  if (phi < -m && phi > -depth + m) return Expect::in;
  if (phi > m || phi < -depth - m) return Expect::out;
  return Expect::either;
}

const char* kFarFluid3 = " water { type fluid; shape box; min (5 5 5); max (5.02 5.02 5.02); }\n";
const char* kFarFluid2 = " water { type fluid; shape box; min (5 5); max (5.02 5.02); }\n";

}  // namespace

BOOST_AUTO_TEST_CASE(phi_of_ball_and_cylinder_by_hand) {
  const BallShape<2> disc(Vec<2>(1, 2), 0.5);
  BOOST_TEST(disc.phi(Vec<2>(1, 2)) == -0.5);
  BOOST_TEST(disc.phi(Vec<2>(1, 3)) == 0.5);
  BOOST_TEST(std::abs(disc.phi(Vec<2>(1.3, 2.4))) < 1e-15);
  BOOST_TEST((disc.lower() - Vec<2>(0.5, 1.5)).norm() == 0.0);
  const BallShape<3> ball(Vec<3>(0, 0, 0), 2);
  BOOST_TEST(ball.phi(Vec<3>(1, 0, 0)) == -1.0);
  BOOST_TEST(ball.shellVolume(1) == 4.0 / 3.0 * M_PI * 7, boost::test_tools::tolerance(1e-14));

  // Axis along z from 0 to 2, radius 1.
  const CylinderShape c(Vec<3>(0, 0, 0), Vec<3>(0, 0, 2), 1);
  BOOST_TEST(c.phi(Vec<3>(0, 0, 1)) == -1.0);                 // centre: R - r = t = L - t = 1
  BOOST_TEST(c.phi(Vec<3>(0.5, 0, 0.2)) == -0.2, boost::test_tools::tolerance(1e-14));  // nearest: the cap
  BOOST_TEST(c.phi(Vec<3>(0.9, 0, 1)) == -0.1, boost::test_tools::tolerance(1e-14));    // nearest: the side
  BOOST_TEST(c.phi(Vec<3>(2, 0, 1)) == 1.0);                  // beside it
  BOOST_TEST(c.phi(Vec<3>(0, 0, 3)) == 1.0);                  // above the cap
  BOOST_TEST(c.phi(Vec<3>(2, 0, 3)) == std::sqrt(2.0), boost::test_tools::tolerance(1e-14));  // past the rim
  BOOST_TEST((c.lower() - Vec<3>(-1, -1, 0)).norm() == 0.0);
  BOOST_TEST((c.upper() - Vec<3>(1, 1, 2)).norm() == 0.0);
  // Tilted in the xy plane: the caps reach R/sqrt(2) along x and y, R along z.
  const Vec<3> a = Vec<3>(1, 1, 0).normalized();
  const CylinderShape t(Vec<3>(1, 1, 1), Vec<3>(1, 1, 1) + 2 * a, 1);
  BOOST_TEST(t.phi(Vec<3>(1, 1, 1) + a + Vec<3>(0, 0, 0.5)) == -0.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(t.lower()[0] == 1 - std::sqrt(0.5), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(t.upper()[2] == 2.0, boost::test_tools::tolerance(1e-14));
  // rowSpan never cuts off a point inside (a sweep of rows across the tilted cylinder)
  for (double y = -0.5; y < 3; y += 0.05)
    for (double z = -0.2; z < 2.2; z += 0.05) {
      double lo = 0, hi = 0;
      const bool any = t.rowSpan(Vec<3>(0, y, z), 0.01, lo, hi);
      for (double x = -1; x < 4; x += 0.01)
        if (t.phi(Vec<3>(x, y, z)) < 0) BOOST_TEST((any && x >= lo && x <= hi));
    }
}

BOOST_AUTO_TEST_CASE(triangle_surface_inside_and_distance) {
  // The box [0, 1]^3 of 12 triangles: inside, the distance (searched within 0.5) and whether
  // a triangle lies within 0.1, against the box's own distance: outside
  // |max(|x - m| - 1/2, 0)|, inside 1/2 - max |x_k - m_k| (m its centre).
  const auto cube = test::boxMesh(Vec<3>(0, 0, 0), Vec<3>(1, 1, 1));
  const TriangleSurface box(cube.v, cube.t, 0.25);
  BOOST_TEST(box.volume() == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(box.area() == 6.0, boost::test_tools::tolerance(1e-14));
  std::mt19937 random(19);
  std::uniform_real_distribution<double> u(-0.4, 1.4);
  std::size_t inside = 0, wrongSide = 0;
  double worst = 0;
  for (int n = 0; n < 20000; ++n) {
    // every third point on a row through the faces' diagonals or a lattice of tenths
    Vec<3> x(u(random), u(random), u(random));
    if (n % 3 == 1) x[2] = x[1];
    if (n % 3 == 2) x = (x * 10).array().round() / 10 + 0.05;
    const Vec<3> d = (x.array() - 0.5).abs() - 0.5;
    const double exact = d.maxCoeff() > 0 ? d.cwiseMax(0.0).norm() : -d.maxCoeff();
    if (std::abs(d.maxCoeff()) < 1e-9) continue;  // on the surface
    inside += d.maxCoeff() < 0;
    wrongSide += box.inside(x) != (d.maxCoeff() < 0);
    worst = std::max(worst, std::abs(box.distance(x, 0.5) - std::min(exact, 0.5)));
    if (std::abs(exact - 0.1) > 1e-12) wrongSide += box.anyWithin(x, 0.1) != (exact <= 0.1);
  }
  BOOST_TEST(inside > 1000u);
  BOOST_TEST(wrongSide == 0u);
  BOOST_TEST(worst < 1e-12);
  // The octahedron |x| + |y| + |z| < 1: the rows along x through (0, 0) meet it at two
  // vertices, the rows (0, t) along edges; inside and the inner distance (1 - |x|_1)/sqrt 3.
  test::Mesh octahedron;
  for (int k = 0; k < 3; ++k)
    for (double s : {1.0, -1.0}) octahedron.v.push_back(s * Vec<3>::Unit(k));
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        std::array<int, 3> t{sx, sy, sz};
        if ((octahedron.v[sy] - octahedron.v[sx]).cross(octahedron.v[sz] - octahedron.v[sx]).dot(octahedron.v[sx]) < 0)
          std::swap(t[1], t[2]);  // outward
        octahedron.t.push_back(t);
      }
  const TriangleSurface oct(octahedron.v, octahedron.t, 0.3);
  BOOST_TEST(oct.volume() == 4.0 / 3.0, boost::test_tools::tolerance(1e-14));
  wrongSide = 0;
  worst = 0;
  for (int n = 0; n < 20000; ++n) {
    Vec<3> x(u(random) - 0.5, u(random) - 0.5, u(random) - 0.5);
    x *= 1.4;
    if (n % 4 == 1) x[1] = x[2] = 0;        // through the vertices (+-1, 0, 0)
    if (n % 4 == 2) x[1] = 0;               // along the edges in the plane y = 0
    if (n % 4 == 3) x[2] = std::abs(x[1]);  // over the faces' shared edges' projections
    const double l1 = x.lpNorm<1>();
    if (std::abs(l1 - 1) < 1e-9) continue;
    wrongSide += oct.inside(x) != (l1 < 1);
    if (l1 < 1) worst = std::max(worst, std::abs(oct.distance(x, 2) - (1 - l1) / std::sqrt(3.0)));
  }
  BOOST_TEST(wrongSide == 0u);
  BOOST_TEST(worst < 1e-12);
  // A closed surface is crossed an even number of times along any whole row, also along
  // rows through the projections of its edges (points of an edge in (y, z), to round-off):
  // the two triangles of an edge must agree on the side of such a row.
  const auto sphere = test::uvSphere(Vec<3>(0.013, 0.027, -0.011), 0.1, 7, 11);
  const TriangleSurface ball(sphere.v, sphere.t, 0.02);
  std::size_t odd = 0, rows = 0;
  std::vector<double> xs;
  for (const auto& t : sphere.t)
    for (int e = 0; e < 3; ++e) {
      const Vec<3>&a = sphere.v[std::size_t(t[std::size_t(e)])], &b = sphere.v[std::size_t(t[std::size_t((e + 1) % 3)])];
      for (double f = 0.05; f < 1; f += 0.1) {
        ball.crossings(a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), xs);
        odd += xs.size() % 2;
        ++rows;
      }
    }
  BOOST_TEST(rows == 3 * 10 * sphere.t.size());
  BOOST_TEST(odd == 0u);
}

BOOST_AUTO_TEST_CASE(voxel_shortcut_agrees_with_the_exact_test) {
  // deeperThan with the phi voxels (a solid wall's, PhiGrid.hpp) and without them, at
  // random points of the bounding box and beyond, for the depths the generator (round-off)
  // and the leak detector (d0/2) ask about and two more.
  const auto sphere = test::uvSphere(Vec<3>(0.013, 0.027, -0.011), 0.1, 12, 24);
  const double d0 = 0.01;
  const StlShape exact(TriangleSurface(sphere.v, sphere.t, 4 * d0), "ball.stl", 4 * d0);
  const StlShape voxels(TriangleSurface(sphere.v, sphere.t, 4 * d0), "ball.stl", 4 * d0, d0);
  BOOST_TEST(voxels.hasGrid());
  BOOST_TEST(!exact.hasGrid());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-0.13, 0.13);
  std::size_t differ = 0, deep = 0;
  for (int n = 0; n < 40000; ++n) {
    const Vec<3> x = Vec<3>(0.013, 0.027, -0.011) + Vec<3>(u(random), u(random), u(random));
    for (double depth : {1e-9 * d0, 0.5 * d0, 2 * d0, 3.5 * d0}) {
      const bool e = exact.deeperThan(x, depth);
      differ += e != voxels.deeperThan(x, depth);
      deep += e;
    }
  }
  BOOST_TEST(deep > 10000u);
  BOOST_TEST(differ == 0u);
}

BOOST_AUTO_TEST_CASE(fluid_cylinder_by_hand_and_by_brute_force) {
  // Radius 2 d0 on the lattice point1 + (i + 1/2) d0: per layer the points (a, b) with
  // a^2 + b^2 < 4: (+-0.5, +-0.5) and (+-1.5, +-0.5), (+-0.5, +-1.5): 12; 5 layers: 60.
  for (const char* p1 : {"(0 0 0)", "(0.3 -0.2 1)"}) {
    const std::string p = p1, q = p == "(0 0 0)" ? "(0 0 5)" : "(0.3 -0.2 6)";
    const auto g = generateIn<3>("case", "spacing 1; regions { pier { type fluid; shape cylinder; point1 " + p +
                                             "; point2 " + q + "; radius 2; } }");
    BOOST_TEST(g.set.size() == 60u);
  }
  // Tilted: every lattice point strictly inside (0 < t < L, r < R, by its own formula) and
  // no other.
  const Vec<3> p1(0.1, 0.2, 0.3), p2(0.5, 0.35, 0.6);
  const double R = 0.07, d0 = 0.01, L = (p2 - p1).norm();
  const auto g = generateIn<3>("case", "spacing 0.01; regions { jet { type fluid; shape cylinder; point1 (0.1 0.2 0.3); "
                                       "point2 (0.5 0.35 0.6); radius 0.07; } }");
  const Vec<3> a = (p2 - p1) / L;
  const std::size_t in = checkLattice<3>(g.set.position, p1, d0, -20, 70, [&](const Vec<3>& x) {
    const double t = (x - p1).dot(a), r = (x - p1 - t * a).norm();
    return shell(std::max({r - R, -t, t - L}), 1e9, d0);
  });
  BOOST_TEST(in == g.set.size());
  BOOST_TEST(double(in) == M_PI * R * R * L / (d0 * d0 * d0), boost::test_tools::tolerance(0.02));
}

// A solid disc (2D) or ball (3D), 3 layers: its wall particles are the lattice points
// centre + (i + 1/2) d0 with R - 3 d0 <= |x - c| < R, all of them.
template <int D>
void checkSolidBall() {
  Vec<D> c;
  c[0] = 0.013;
  c[1] = -0.021;
  if (D == 3) c[D - 1] = 0.007;
  const double R = D == 2 ? 0.1 : 0.08, d0 = 0.01;
  const std::string centre = D == 2 ? "(0.013 -0.021)" : "(0.013 -0.021 0.007)";
  const auto g = generateIn<D>("case", std::string("spacing 0.01; regions {\n") + (D == 2 ? kFarFluid2 : kFarFluid3) +
                                           " ball { type wall; shape " + (D == 2 ? "circle" : "sphere") +
                                           "; centre " + centre + "; radius " + std::to_string(R) + "; layers 3; }\n}");
  const auto walls = pointsOf(g, ParticleType::wall);
  const std::size_t in = checkLattice<D>(walls, c, d0, -12, 12, [&](const Vec<D>& x) {
    return shell((x - c).norm() - R, 3 * d0, d0);
  });
  BOOST_TEST(in == walls.size());
  for (const auto& x : walls) {
    BOOST_TEST((x - c).norm() < R);
    BOOST_TEST((x - c).norm() >= R - 3 * d0);
  }
  BOOST_REQUIRE(g.walls.size() == 1u);
  BOOST_TEST(g.walls[0].solid);
  BOOST_TEST(bool(g.walls[0].body));
  BOOST_TEST((g.walls[0].outerMin - (c.array() - R).matrix()).norm() < 1e-15);
}

BOOST_AUTO_TEST_CASE(solid_disc_and_ball_layers) {
  checkSolidBall<2>();
  checkSolidBall<3>();
}

BOOST_AUTO_TEST_CASE(solid_cylinder_layers_and_caps) {
  // Along z, R = 5 d0, L = 10 d0, 2 layers: the two cap layers at each end hold every point
  // of the disc (r < R: 80 points, as the fluid disc of radius 5 d0 in 2D), the six layers
  // between them the ring R - 2 d0 <= r < R: 80 - 32 (r < 3 d0: 4 x (3 + 3 + 2)) = 48.
  const auto g = generateIn<3>("case", std::string("spacing 1; regions {\n") +
                                           " water { type fluid; shape box; min (50 50 50); max (52 52 52); }\n"
                                           " pier { type wall; shape cylinder; point1 (0 0 0); point2 (0 0 10); "
                                           "radius 5; layers 2; }\n}");
  const auto walls = pointsOf(g, ParticleType::wall);
  std::array<std::size_t, 10> perLayer{};
  for (const auto& x : walls) ++perLayer[std::size_t(std::lround(x[2] - 0.5))];
  for (int k = 0; k < 10; ++k) BOOST_TEST(perLayer[std::size_t(k)] == (k < 2 || k >= 8 ? 80u : 48u));
  BOOST_TEST(walls.size() == 4 * 80u + 6 * 48u);
  // Tilted, against the shell of its own formula -min(R - r, t, L - t).
  const Vec<3> p1(0.02, -0.01, 0.03), p2(0.2, 0.1, 0.25);
  const double R = 0.06, d0 = 0.01, L = (p2 - p1).norm();
  const Vec<3> a = (p2 - p1) / L;
  const auto t = generateIn<3>("case", std::string("spacing 0.01; regions {\n") + kFarFluid3 +
                                           " pier { type wall; shape cylinder; point1 (0.02 -0.01 0.03); "
                                           "point2 (0.2 0.1 0.25); radius 0.06; layers 3; }\n}");
  const auto tilted = pointsOf(t, ParticleType::wall);
  const std::size_t in = checkLattice<3>(tilted, p1, d0, -12, 40, [&](const Vec<3>& x) {
    const double s = (x - p1).dot(a), r = (x - p1 - s * a).norm();
    return shell(std::max({r - R, -s, s - L}), 3 * d0, d0);  // inside: -min(R - r, t, L - t)
  });
  BOOST_TEST(in == tilted.size());
}

// A tank filled with fluid around a solid ball (disc) whose lattice is offset from the
// fluid's: no fluid inside it; every box lattice point outside it and at least d0/2 from
// every wall particle is fluid.
template <int D>
void checkFluidAroundBall() {
  const std::string z = D == 3 ? " 0" : "", zc = D == 3 ? " 0.1981" : "", zm = D == 3 ? " 0.4" : "";
  const auto g = generateIn<D>("case", "spacing 0.01; regions {\n"
                                       " water { type fluid; shape box; min (0 0" + z + "); max (0.4 0.3" + zm + "); }\n"
                                       " tank { type wall; shape box; min (0 0" + z + "); max (0.4 0.5" + zm + "); open (top); }\n"
                                       " ball { type wall; shape circle; centre (0.2037 0.1513" + zc + "); radius 0.083; }\n}");
  Vec<D> c;
  c[0] = 0.2037;
  c[1] = 0.1513;
  if (D == 3) c[D - 1] = 0.1981;
  const double R = 0.083, d0 = 0.01;
  const auto fluid = pointsOf(g, ParticleType::fluid);
  std::vector<Vec<D>> ballWalls;
  for (const auto& x : pointsOf(g, ParticleType::wall))
    if ((x - c).norm() < R) ballWalls.push_back(x);
  BOOST_TEST(!ballWalls.empty());
  std::size_t removedOutside = 0;
  const std::size_t in = checkLattice<D>(fluid, Vec<D>::Zero(), d0, 0, 40, [&](const Vec<D>& x) {
    if (x[1] > 0.3) return Expect::out;  // above the water box
    const double phi = (x - c).norm() - R;
    if (std::abs(phi) < 1e-9 * d0) return Expect::either;
    if (phi < 0) return Expect::out;
    if (phi > d0) return Expect::in;
    for (const auto& w : ballWalls) {
      const double r = (x - w).norm();
      if (std::abs(r - 0.5 * d0) < 1e-9 * d0) return Expect::either;
      if (r < 0.5 * d0) {
        ++removedOutside;
        return Expect::out;
      }
    }
    return Expect::in;
  });
  BOOST_TEST(in == fluid.size());
  BOOST_TEST(removedOutside > 0u);  // the spacing rule did act outside the surface
}

BOOST_AUTO_TEST_CASE(fluid_outside_a_solid_ball_kept_inside_removed) {
  checkFluidAroundBall<2>();
  checkFluidAroundBall<3>();
}

BOOST_AUTO_TEST_CASE(stl_cube_gives_the_box) {
  // A unit cube of 12 triangles, scaled to 0.3 m and moved to (0.1 0.2 0.3): fluid inside it
  // is the fluid box (0.1 0.2 0.3)..(0.4 0.5 0.6), particle for particle in the same order; as
  // a wall it is the solid box's 30^3 - 24^3 = 13176 layer particles. The lattice rows on
  // the faces' diagonals (y - 0.2 = z - 0.3) meet the triangles' shared edges exactly.
  test::TempCase c("stlCube");
  const auto cube = test::boxMesh(Vec<3>(0, 0, 0), Vec<3>(1, 1, 1));
  std::filesystem::create_directories(c.dir() + "/constant/triSurface");
  test::writeAsciiStl(c.dir() + "/constant/triSurface/ascii.stl", cube);
  test::writeBinaryStl(c.dir() + "/constant/triSurface/binary.stl", cube);
  const auto box = generateIn<3>(c.dir(), "spacing 0.01; regions { b { type fluid; shape box; min (0.1 0.2 0.3); "
                                          "max (0.4 0.5 0.6); } }");
  const auto solidBox = generateIn<3>(c.dir(), std::string("spacing 0.01; regions {\n") + kFarFluid3 +
                                                   " b { type wall; shape box; min (0.1 0.2 0.3); max (0.4 0.5 0.6); "
                                                   "solid yes; layers 3; }\n}");
  BOOST_TEST(box.set.size() == 27000u);
  BOOST_TEST(pointsOf(solidBox, ParticleType::wall).size() == 13176u);
  for (const char* file : {"ascii.stl", "binary.stl"}) {
    const std::string stl = std::string("shape stl; file \"constant/triSurface/") + file +
                            "\"; scale 0.3; translate (0.1 0.2 0.3);";
    const auto fluid = generateIn<3>(c.dir(), "spacing 0.01; regions { b { type fluid; " + stl + " } }");
    BOOST_TEST((fluid.set.position == box.set.position));
    const auto wall = generateIn<3>(c.dir(), std::string("spacing 0.01; regions {\n") + kFarFluid3 +
                                                 " b { type wall; " + stl + " layers 3; }\n}");
    BOOST_TEST((sortedPoints(pointsOf(wall, ParticleType::wall)) == sortedPoints(pointsOf(solidBox, ParticleType::wall))));
    BOOST_TEST(wall.walls[0].body->kind() == std::string("STL surface 'constant/triSurface/") + file + "'");
  }
}

BOOST_AUTO_TEST_CASE(stl_scale_rotate_translate) {
  // A 2 x 1 x 1 block drawn in decimetres, scale 0.1, rotated +90 degrees about z (x -> y,
  // y -> -x), then moved by (0.5 0.2 0.1): the box x in [0.4, 0.5], y in [0.2, 0.4], z in
  // [0.1, 0.2]. Radians, a clockwise turn or the scale applied after the shift put it elsewhere.
  test::TempCase c("stlMove");
  test::writeAsciiStl(c.dir() + "/block.stl", test::boxMesh(Vec<3>(0, 0, 0), Vec<3>(2, 1, 1)));
  const auto moved = generateIn<3>(c.dir(), "spacing 0.01; regions { b { type fluid; shape stl; file block.stl; "
                                            "scale 0.1; rotate { axis (0 0 2); angle 90; } translate (0.5 0.2 0.1); } }");
  const auto box = generateIn<3>(c.dir(), "spacing 0.01; regions { b { type fluid; shape box; min (0.4 0.2 0.1); "
                                          "max (0.5 0.4 0.2); } }");
  BOOST_REQUIRE(moved.set.size() == box.set.size());
  BOOST_TEST(box.set.size() == 2000u);
  double worst = 0;
  for (std::size_t i = 0; i < box.set.size(); ++i)
    worst = std::max(worst, (moved.set.position[i] - box.set.position[i]).norm());
  BOOST_TEST(worst < 1e-12);
  // An absolute path is taken as it is (here the same file).
  const auto absolute = generateIn<3>("elsewhere", "spacing 0.01; regions { b { type fluid; shape stl; file \"" + c.dir() +
                                                       "/block.stl\"; scale 0.1; } }");
  BOOST_TEST(absolute.set.size() == 2000u);
}

BOOST_AUTO_TEST_CASE(stl_sphere_against_its_face_planes) {
  // A closed UV sphere of radius 0.1 (12 rings of 24, 528 triangles), binary: inside a
  // convex polyhedron means below every face plane, and the depth of an inside point is its
  // least distance to a face plane. Fluid fills the lattice from the corner of its bounding
  // box; a wall's 2 layers are the points at depth up to 2 d0.
  test::TempCase c("stlSphere");
  const auto sphere = test::uvSphere(Vec<3>(0.013, 0.027, -0.011), 0.1, 12, 24);
  test::writeBinaryStl(c.dir() + "/ball.stl", sphere);
  std::vector<std::pair<Vec<3>, Vec<3>>> planes;  // a point and the outward normal
  Vec<3> lo = Vec<3>::Constant(1e9);
  for (const auto& v : sphere.v) lo = lo.cwiseMin(v);
  const Vec<3> centre(0.013, 0.027, -0.011);
  for (const auto& t : sphere.t) {
    Vec<3> n = test::normalOf(sphere, t);
    if (n.dot(sphere.v[std::size_t(t[0])] - centre) < 0) n = -n;
    planes.emplace_back(sphere.v[std::size_t(t[0])], n);
  }
  for (const auto& v : sphere.v)
    for (const auto& [p, n] : planes) BOOST_REQUIRE(n.dot(v - p) < 1e-7);  // convex (to float round-off)
  auto phi = [&](const Vec<3>& x) {
    double most = -1e9;
    for (const auto& [p, n] : planes) most = std::max(most, n.dot(x - p));
    return most;
  };
  const double d0 = 0.01;
  const auto fluid = generateIn<3>(c.dir(), "spacing 0.01; regions { b { type fluid; shape stl; file ball.stl; } }");
  const std::size_t in = checkLattice<3>(fluid.set.position, lo, d0, -2, 24,
                                         [&](const Vec<3>& x) { return shell(phi(x), 1e9, d0, 1e-6); });
  BOOST_TEST(in == fluid.set.size());
  BOOST_TEST(double(in) == 4.0 / 3.0 * M_PI * 1000, boost::test_tools::tolerance(0.05));
  const auto wall = generateIn<3>(c.dir(), std::string("spacing 0.01; regions {\n") + kFarFluid3 +
                                               " b { type wall; shape stl; file ball.stl; layers 2; }\n}");
  const auto layers = pointsOf(wall, ParticleType::wall);
  const std::size_t shellIn =
      checkLattice<3>(layers, lo, d0, -2, 24, [&](const Vec<3>& x) { return shell(phi(x), 2 * d0, d0, 1e-6); });
  BOOST_TEST(shellIn == layers.size());
}

BOOST_AUTO_TEST_CASE(stl_errors_name_the_file) {
  test::TempCase c("stlErrors");
  auto cube = test::boxMesh(Vec<3>(0, 0, 0), Vec<3>(1, 1, 1));
  const std::string dir = c.dir() + "/constant/triSurface/";
  std::filesystem::create_directories(dir);
  auto open = cube;
  open.t.pop_back();
  test::writeBinaryStl(dir + "open.stl", open);
  c.file("constant/triSurface/empty.stl", "");
  c.file("constant/triSurface/text.stl", "this is not an STL file\n");
  test::writeAsciiStl(dir + "cut.stl", cube);
  std::filesystem::resize_file(dir + "cut.stl", std::filesystem::file_size(dir + "cut.stl") / 2);  // cut mid-facet
  test::writeAsciiStl(dir + "mm.stl", test::boxMesh(Vec<3>(0, 0, 0), Vec<3>(600, 500, 450)));
  auto errorFor = [&](const std::string& file, const std::string& extra = "") {
    return test::errorOf([&] {
      generateIn<3>(c.dir(), "spacing 0.004;\nregions\n{\n part { type fluid; shape stl; file \"constant/triSurface/" +
                                 file + "\";" + extra + " }\n}\n");
    });
  };
  const std::string where = "particlesDict:4:";
  CHECK_MESSAGE(errorFor("open.stl"), where, "keyword 'file'", dir + "open.stl", "not closed", "3 open edge(s)");
  CHECK_MESSAGE(errorFor("empty.stl"), where, dir + "empty.stl", "is empty");
  CHECK_MESSAGE(errorFor("missing.stl"), where, dir + "missing.stl", "does not exist");
  CHECK_MESSAGE(errorFor("text.stl"), where, dir + "text.stl", "no triangle", "(VTK: ", "Expecting 'solid'");
  CHECK_MESSAGE(errorFor("cut.stl"), where, dir + "cut.stl", "(VTK: ", "Premature EOF");
  BOOST_TEST(errorFor("text.stl").size() < 600u);  // VTK's first line only, not its pipeline dump
  CHECK_MESSAGE(errorFor("mm.stl"), where, dir + "mm.stl", "wrong units", "scale 0.001");
  BOOST_TEST(errorFor("mm.stl", " scale 0.0001;").empty());  // 6 x 5 x 4.5 cm: fine
  CHECK_MESSAGE(errorFor("mm.stl", " scale 1e-6;"), dir + "mm.stl", "less than 2 spacings", "wrong units");
  CHECK_MESSAGE(errorFor("mm.stl", " scale 0.0001; rotate { axis (0 0 0); angle 90; }"), "keyword 'axis'", "no direction");
  CHECK_MESSAGE(errorFor("mm.stl", " scale 0.0001; rotate { axis (0 0 1); angle 90 [rad]; }"), "keyword 'angle'", "degrees");
}

BOOST_AUTO_TEST_CASE(shape_errors) {
  auto error2 = [](const std::string& region) {
    return test::errorOf([&] { generateIn<2>("case", std::string("spacing 0.01; regions {\n") + kFarFluid2 + region + "\n}"); });
  };
  auto error3 = [](const std::string& region) {
    return test::errorOf([&] { generateIn<3>("case", std::string("spacing 0.01; regions {\n") + kFarFluid3 + region + "\n}"); });
  };
  CHECK_MESSAGE(error2(" p { type wall; shape cylinder; point1 (0 0); point2 (0 1); radius 0.1; }"), "particlesDict:3",
                "keyword 'shape'", "3D body", "shape circle");
  CHECK_MESSAGE(error2(" p { type fluid; shape stl; file a.stl; }"), "keyword 'shape'", "3D body");
  CHECK_MESSAGE(error3(" p { type wall; shape sphere; centre (0 0 0); radius 0.1; open (top); }"), "keyword 'open'",
                "no open faces");
  CHECK_MESSAGE(error3(" p { type wall; shape sphere; centre (0 0 0); radius 0.1; solid no; }"), "keyword 'solid'",
                "always a solid body");
  CHECK_MESSAGE(error3(" p { type wall; shape cylinder; point1 (0 0 0); point2 (0 0 0); radius 0.1; }"),
                "keyword 'point2'", "no length");
  CHECK_MESSAGE(error3(" p { type fluid; shape cylinder; point1 (1 1 1); point2 (1 1 2); radius 0.1; layers 2; }"),
                "keyword 'layers'");
  // An STL key on another shape is unknown (checkAllRead).
  CHECK_MESSAGE(error3(" p { type wall; shape sphere; centre (0 0 0); radius 0.1; scale 2; }"), "scale");
  // Two fluid regions, one a cylinder through the other: an overlap, found on the particles.
  CHECK_MESSAGE(test::errorOf([] {
                  generateIn<3>("case", "spacing 0.01; regions { a { type fluid; shape box; min (0 0 0); max (0.2 0.2 0.2); }\n"
                                        " b { type fluid; shape cylinder; point1 (0.1 0.1 0.15); point2 (0.1 0.1 0.4); "
                                        "radius 0.05; } }");
                }),
                "fluid region 'b' overlaps fluid region 'a'");
  // Side by side, touching: no overlap.
  BOOST_TEST(test::errorOf([] {
               generateIn<3>("case", "spacing 0.01; regions { a { type fluid; shape box; min (0 0 0); max (0.2 0.2 0.2); }\n"
                                     " b { type fluid; shape cylinder; point1 (0.1 0.1 0.2); point2 (0.1 0.1 0.4); "
                                     "radius 0.05; } }");
             }).empty());
}
