// The wall particles' surface normals from their regions' geometry (boundaries/WallNormals,
// docs/method.md 11, eq. 11d), in 2D and 3D: behind a container's face the face's inward
// normal, behind its edges and corners the unit diagonal toward the surface box; inside a
// solid box the outward normal of its nearest face (the sum of the tied faces' normals on
// its diagonals), a face lying on the floor excepted; in a ball's layers the radial direction; every wall particle has one, no
// fluid particle does; a moving wall's normal turns with it.
#define BOOST_TEST_MODULE boundaries_wallNormals
#include <boost/test/unit_test.hpp>

#include "../support/TempCase.hpp"
#include "boundaries/MovingWalls.hpp"
#include "boundaries/WallNormals.hpp"
#include "particles/ParticleGenerator.hpp"
#include <cmath>

using namespace shizuku;
using test::vec;

namespace {

template <int D>
GeneratedParticles<D> generate(const std::string& text) {
  return generateParticles<D>(Dictionary::fromString(text, "case/system/particlesDict"));
}

// The unit vector toward the box [lo, hi] from x outside it (zero inside).
template <int D>
Vec<D> towardBox(const Vec<D>& x, double lo, double hi) {
  Vec<D> n;
  for (int k = 0; k < D; ++k) n[k] = std::clamp(x[k], lo, hi) - x[k];
  return n.norm() > 0 ? Vec<D>(n.normalized()) : n;
}

// A tank [0, 1]^D with three layers, open at the top, holding a solid box obstacle
// [0.4, 0.6]^D lifted off the floor (y from 0.3), and a ball of radius 0.1 at (0.2, 0.7, ..).
template <int D>
void normalsFollowTheGeometry() {
  const double d0 = 0.02;
  const auto g = generate<D>("spacing 0.02;\nregions {\n"
                             " water { type fluid; shape box; min " + vec<D>(0, 0, 0) + "; max " + vec<D>(1, 0.2, 1) + "; }\n"
                             " tank { type wall; shape box; min " + vec<D>(0, 0, 0) + "; max " + vec<D>(1, 1, 1) +
                             "; layers 3; open (top); }\n"
                             " block { type wall; shape box; solid yes; min " + vec<D>(0.4, 0.3, 0.4) + "; max " +
                             vec<D>(0.6, 0.5, 0.6) + "; layers 3; }\n"
                             " ball { type wall; shape circle; centre " + vec<D>(0.2, 0.7, 0.5) +
                             "; radius 0.1; layers 3; }\n"
                             " step { type wall; shape box; solid yes; min " + vec<D>(0.7, 0, 0.4) + "; max " +
                             vec<D>(0.9, 0.1, 0.6) + "; layers 3; }\n}\n");
  ParticleSet<D> P = g.set;
  auto walls = g.walls;
  markCoveredFaces(walls);  // the step's bottom lies on the floor
  assignWallNormals(P, walls);
  BOOST_REQUIRE_EQUAL(P.wallNormal.size(), P.size());
  std::size_t tank = 0, block = 0, ball = 0;
  double tankErr = 0, blockErr = 0, ballErr = 0;
  Vec<D> centre = Vec<D>::Zero();
  centre[0] = 0.2;
  centre[1] = 0.7;
  if (D == 3) centre[2] = 0.5;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<D>& x = P.position[i];
    const Vec<D>& n = P.wallNormal[i];
    if (!P.isWall(i)) {
      BOOST_TEST(n.norm() == 0.0);
      continue;
    }
    BOOST_TEST(std::abs(n.norm() - 1) < 1e-12);
    const bool inTank = (x.array() < 0).any() || (x.array() > 1).any();
    // The solid boxes: the block [0.4, 0.6] x [0.3, 0.5] (x [0.4, 0.6]) and the step
    // [0.7, 0.9] x [0, 0.1] (x [0.4, 0.6]) whose bottom face is covered by the floor.
    struct Solid { double lo[3], hi[3]; bool bottomCovered; };
    const Solid solids[2] = {{{0.4, 0.3, 0.4}, {0.6, 0.5, 0.6}, false}, {{0.7, 0, 0.4}, {0.9, 0.1, 0.6}, true}};
    const Solid* in = nullptr;
    for (const auto& b : solids) {
      bool inside = true;
      for (int k = 0; k < D; ++k) inside &= x[k] > b.lo[k] && x[k] < b.hi[k];
      if (inside) in = &b;
    }
    if (inTank) {
      ++tank;
      tankErr = std::max(tankErr, (n - towardBox<D>(x, 0, 1)).norm());
    } else if (in) {
      // The outward normal of the nearest uncovered face, tied faces summed.
      double depth = INFINITY;
      for (int k = 0; k < D; ++k) {
        if (!(k == 1 && in->bottomCovered)) depth = std::min(depth, x[k] - in->lo[k]);
        depth = std::min(depth, in->hi[k] - x[k]);
      }
      Vec<D> m = Vec<D>::Zero();
      for (int k = 0; k < D; ++k) {
        if (!(k == 1 && in->bottomCovered) && x[k] - in->lo[k] <= depth + 1e-9) m[k] -= 1;
        if (in->hi[k] - x[k] <= depth + 1e-9) m[k] += 1;
      }
      ++block;
      blockErr = std::max(blockErr, (n - m.normalized()).norm());
      if (in->bottomCovered) BOOST_TEST(n.y() >= 0.0);  // never into the floor
    } else {
      ++ball;
      ballErr = std::max(ballErr, (n - (x - centre).normalized()).norm());
    }
  }
  BOOST_TEST_MESSAGE(D << "D: " << tank << " tank, " << block << " solid box, " << ball
                       << " ball particles; largest normal errors " << tankErr << ", " << blockErr << ", " << ballErr);
  BOOST_TEST(tank > 0u);
  BOOST_TEST(block > 0u);
  BOOST_TEST(ball > 0u);
  BOOST_TEST(tankErr < 1e-12);
  BOOST_TEST(blockErr < 1e-12);
  // Central differences of the ball's exact signed distance: round-off over 2e-3 d0.
  BOOST_TEST(ballErr < 1e-6);
  (void)d0;
}

// A tank rolling about its floor's centre by 30 t degrees, placed at t = 0.2, 0.5 and 1:
// every wall particle's normal is its rest normal turned by the tank's rotation at each.
void rollingTankTurnsItsNormals() {
  const auto g = generate<2>("spacing 0.02;\nregions {\n"
                             " water { type fluid; shape box; min (0 0); max (1 0.2); }\n"
                             " tank { type wall; shape box; min (0 0); max (1 1); layers 3; open (top);\n"
                             "        motion { type rotation; centre (0.5 0); angle \"30*t\"; } }\n}\n");
  ParticleSet<2> P = g.set;
  assignWallNormals(P, g.walls);
  const auto rest = P.wallNormal;
  std::vector<std::pair<Vec<2>, Vec<2>>> boxes;
  std::vector<std::string> names;
  for (const auto& w : g.walls)
    if (w.motion >= 0) {
      boxes.push_back({w.outerMin, w.outerMax});
      names.push_back(w.name);
    }
  MovingWalls<2> walls(g.motions, names, boxes);
  double err = 0;
  for (double t : {0.2, 0.5, 1.0}) {  // placed three times: the turns compose
    walls.place(P, t);
    const double a = 30 * t * M_PI / 180;
    Mat<2> R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.isWall(i)) err = std::max(err, (P.wallNormal[i] - R * rest[i]).norm());
  }
  BOOST_TEST_MESSAGE("rolling tank: largest departure of a normal from the turned rest normal " << err);
  BOOST_TEST(err < 1e-12);
}

// A weir built as two boxes (tutorials/weir): the approach's floor box, whose right face is
// the weir's upstream face, and the crest's box, whose bottom face is the crest. Their
// layers meet at the crest's upstream edge, a convex edge of the wall: the particles as
// deep behind the face as behind the crest take the diagonal, the others their face's
// normal (turned to the water's side where it is used).
void weirEdgeTakesTheDiagonal() {
  const auto g = generate<2>("spacing 0.005;\nregions {\n"
                             " water { type fluid; shape box; min (0 0); max (0.3 0.1); }\n"
                             " approach { type wall; shape box; min (-0.02 0); max (0.35 0.05); layers 3; open (left top); }\n"
                             " crestFloor { type wall; shape box; min (0.35 0.05); max (0.65 0.3); layers 3;"
                             " open (left right top); }\n}\n");
  ParticleSet<2> P = g.set;
  auto walls = g.walls;
  markCoveredFaces(walls);
  assignWallNormals(P, walls);
  int checked = 0;
  double err = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2>& x = P.position[i];
    if (!P.isWall(i) || x.x() < 0.35 || x.x() > 0.365 || x.y() < 0.035 || x.y() > 0.05) continue;
    const double behindFace = x.x() - 0.35, belowCrest = 0.05 - x.y();
    const Vec<2> expected = std::abs(behindFace - belowCrest) < 1e-9 ? Vec<2>(-1, 1).normalized()
                            : behindFace < belowCrest                ? Vec<2>(-1, 0)
                                                                     : Vec<2>(0, 1);
    // Sign aside (the approach's normals point into its box, the crest's up).
    err = std::max(err, std::min((P.wallNormal[i] - expected).norm(), (P.wallNormal[i] + expected).norm()));
    ++checked;
  }
  BOOST_TEST_MESSAGE("weir edge: " << checked << " particles, largest normal error " << err);
  BOOST_TEST(checked == 9);
  BOOST_TEST(err < 1e-12);
}

}  // namespace

BOOST_AUTO_TEST_CASE(wall_normals_follow_the_geometry_2d) { normalsFollowTheGeometry<2>(); }
BOOST_AUTO_TEST_CASE(wall_normals_follow_the_geometry_3d) { normalsFollowTheGeometry<3>(); }
BOOST_AUTO_TEST_CASE(a_moving_wall_turns_its_normals) { rollingTankTurnsItsNormals(); }
BOOST_AUTO_TEST_CASE(where_two_walls_meet_at_an_edge_the_normal_is_its_diagonal) { weirEdgeTakesTheDiagonal(); }
