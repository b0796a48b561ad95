// The domain, the wall-leak detector and the in-place removal of particles
// (docs/boundaries.md, "Domain, outflow and leaks"), in 2D and 3D: the default domain of a
// wall box is its outer box extended beyond each open face by its size; a controlDict
// domain is read and checked (min >= max, fluid outside: InputError naming the keyword);
// no walls: unbounded; a particle inside a wall's layers past d0/2, or through a closed
// face's layers in one step, is a leak, one through an open face or a periodic wrap is
// not; a particle inside a curved or STL solid (a disc, a ball, a cylinder, an STL cube)
// past d0/2 is a leak through its surface, one d0/4 inside is not; a solid box on the floor
// leaks fluid squeezed under its bottom row (that face is covered); solid walls alone leave
// the domain unbounded and a body widens a container's domain by its bounding box;
// removeMarked compacts every present field in order without reallocating.
#define BOOST_TEST_MODULE boundaries_domain
#include <boost/test/unit_test.hpp>

#include "boundaries/Domain.hpp"
#include "boundaries/LeakDetector.hpp"
#include "core/Dictionary.hpp"
#include "particles/BallShape.hpp"
#include "particles/CylinderShape.hpp"
#include "particles/StlShape.hpp"
#include "../support/StlFiles.hpp"

using namespace shizuku;

namespace {

// A tank [0, 1] x [0, 0.5] (x [0, 0.2] in 3D), three layers of d0 = 0.01, open at the top.
template <int D>
WallBox<D> tank() {
  WallBox<D> w;
  w.name = "tank";
  w.d0 = 0.01;
  w.layers = 3;
  w.min.setZero();
  w.max.setConstant(0.2);
  w.max[0] = 1;
  w.max[1] = 0.5;
  w.open[3] = true;  // +y
  w.outerMin = w.min - Vec<D>::Constant(0.03);
  w.outerMax = w.max + Vec<D>::Constant(0.03);
  w.outerMax[1] = w.max[1];
  return w;
}

template <int D>
ParticleSet<D> fluidAt(const std::vector<Vec<D>>& x) {
  ParticleSet<D> p;
  p.position = x;
  p.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    p.type[i] = std::uint8_t(ParticleType::fluid);
    p.id[i] = std::int64_t(10 + i);
  }
  return p;
}

template <int D>
Vec<D> at(double x, double y) {
  Vec<D> v = Vec<D>::Constant(0.1);
  v[0] = x;
  v[1] = y;
  return v;
}

template <int D>
void checkDefaultDomain() {
  const Dictionary none = Dictionary::fromString("", "controlDict");
  const auto p = fluidAt<D>({at<D>(0.5, 0.2)});
  const Domain<D> d = Domain<D>::read(none, {tank<D>()}, p);
  BOOST_TEST(d.bounded());
  // Closed faces: the outer box; open top: 0.5 + its size 0.53.
  BOOST_TEST(d.min()[0] == -0.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(d.max()[0] == 1.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(d.min()[1] == -0.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(d.max()[1] == 1.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(d.contains(at<D>(0.5, 1.0)));     // spray above the open top: in
  BOOST_TEST(!d.contains(at<D>(1.05, 0.3)));   // fell outside the tank: out
  BOOST_TEST(d.side(at<D>(1.05, 0.3)) == "right (+x)");
  BOOST_TEST(!Domain<D>::read(none, {}, p).bounded());  // no walls
}

template <int D>
void checkControlDictDomain() {
  const auto p = fluidAt<D>({at<D>(0.5, 0.2)});
  const std::string v = D == 2 ? "" : " 0";
  const Dictionary ok = Dictionary::fromString("domain { min (-1 -1" + v + "); max (2 3" + (D == 2 ? "" : " 1") + "); }", "cd");
  const Domain<D> d = Domain<D>::read(ok, {tank<D>()}, p);
  BOOST_TEST(d.max()[1] == 3);
  auto fails = [&](const std::string& text, const std::string& what) {
    const Dictionary bad = Dictionary::fromString(text, "cd");
    try {
      Domain<D>::read(bad, {}, p);
      BOOST_ERROR("no InputError for " + text);
    } catch (const InputError& e) {
      BOOST_TEST(std::string(e.what()).find(what) != std::string::npos, e.what());
    }
  };
  fails("domain { min (0 1" + v + "); max (1 0" + v + "); }", "keyword 'max': the domain's max must exceed");
  fails("domain { min (-1 -1" + v + "); max (1 0.1" + (D == 2 ? "" : " 1") + "); }", "does not hold the fluid: particle id 10");
}

template <int D>
void checkLeaks() {
  const LeakDetector<D> det({tank<D>()});
  const PeriodicBox<D> noPeriodic;
  // 0: in the water; 1: in the right wall 0.004 past its surface (less than d0/2: no leak);
  // 2: 0.006 past it (a leak, inside); 3: jumped from inside through the whole right wall;
  // 4: flew out over the open top and beyond the right wall (no closed face crossed);
  // 5: inside the bottom layers.
  const std::vector<Vec<D>> before = {at<D>(0.5, 0.2), at<D>(0.99, 0.2), at<D>(0.99, 0.2), at<D>(0.99, 0.2),
                                      at<D>(0.99, 0.6), at<D>(0.5, 0.01)};
  const std::vector<Vec<D>> after = {at<D>(0.51, 0.2), at<D>(1.004, 0.2), at<D>(1.006, 0.2), at<D>(1.05, 0.2),
                                     at<D>(1.05, 0.55), at<D>(0.5, -0.01)};
  const auto p = fluidAt<D>(after);
  std::vector<Leak> leaks;
  leaks.reserve(8);
  const auto* data = leaks.data();
  det.find(p, before, noPeriodic, leaks);
  BOOST_REQUIRE(leaks.size() == 3u);
  BOOST_TEST(leaks[0].particle == 2);
  BOOST_TEST(!leaks[0].crossed);
  BOOST_TEST(leaks[0].face == 1);
  BOOST_TEST(leaks[1].particle == 3);
  BOOST_TEST(leaks[1].crossed);
  BOOST_TEST(det.describe(leaks[1]) == "wall 'tank', face right (+x)");
  BOOST_TEST(leaks[2].particle == 5);
  BOOST_TEST(leaks[2].face == 2);
  BOOST_TEST(leaks.data() == data);  // no reallocation
  // A periodic wrap in x across the right wall is no crossing.
  PeriodicBox<D> px;
  px.periodic[0] = true;
  px.lo.setZero();
  px.hi.setConstant(1.1);
  det.find(fluidAt<D>({at<D>(0.01, 0.2)}), {at<D>(1.09, 0.2)}, px, leaks);
  BOOST_TEST(leaks.empty());

  // An obstacle (a wall box on the floor, layers outside its surface, open bottom): water
  // flowing over it skirts the outer corner of its layers. 0: just inside the outer box's
  // corner region above and beside it (0.03 past both faces, less than d0/2 inside the
  // outer box along x): no leak; 1: in its top layers, mid-face: a leak; 2: in its side
  // layers: a leak.
  WallBox<D> block = tank<D>();
  block.name = "block";
  block.min = at<D>(0.4, 0.0);
  block.max = at<D>(0.6, 0.1);
  if (D == 3) { block.min[2] = 0; block.max[2] = 0.2; }
  block.open = {};
  block.open[2] = true;  // -y (on the floor)
  block.outerMin = block.min - Vec<D>::Constant(0.03);
  block.outerMax = block.max + Vec<D>::Constant(0.03);
  block.outerMin[1] = block.min[1];
  const LeakDetector<D> obstacle({block});
  const std::vector<Vec<D>> near = {at<D>(0.6299, 0.1299), at<D>(0.5, 0.115), at<D>(0.615, 0.05)};
  obstacle.find(fluidAt<D>(near), near, noPeriodic, leaks);
  BOOST_REQUIRE(leaks.size() == 2u);
  BOOST_TEST(leaks[0].particle == 1);
  BOOST_TEST(leaks[0].face == 3);
  BOOST_TEST(leaks[1].particle == 2);
  BOOST_TEST(leaks[1].face == 1);

  // The same block as a solid wall box (`solid yes`, layers inside it): 0:
  // above it; 1: 0.4 d0 inside its top face (short of the first layer): no leak; 2: 0.6
  // d0 inside its top face: a leak through the top; 3: 0.6 d0 inside its +x face (nearer
  // than the top): a leak through +x. Nothing is found from a move alone.
  WallBox<D> solid = block;
  solid.open = {};
  solid.outerMin = solid.min;
  solid.outerMax = solid.max;
  solid.solid = true;
  const LeakDetector<D> body({solid});
  const std::vector<Vec<D>> in = {at<D>(0.5, 0.115), at<D>(0.5, 0.096), at<D>(0.5, 0.094), at<D>(0.594, 0.05)};
  body.find(fluidAt<D>(in), std::vector<Vec<D>>(4, at<D>(0.5, 0.2)), noPeriodic, leaks);
  BOOST_REQUIRE(leaks.size() == 2u);
  BOOST_TEST(leaks[0].particle == 2);
  BOOST_TEST(leaks[0].face == 3);
  BOOST_TEST(leaks[1].particle == 3);
  BOOST_TEST(leaks[1].face == 1);

  // The solid block standing on the tank's floor: its bottom face lies against the floor's
  // layers, so fluid squeezed under the block's bottom row (0.4 d0 above the floor, mid
  // block) is a leak, reported on the nearest face fluid can reach (the top, 0.096 away).
  // A particle 0.4 d0 inside the block's side face at the same height is not (it may stand
  // at the foot of the face), nor is the squeezed one with the block alone (no floor: the
  // bottom is a face like the others).
  const LeakDetector<D> onFloor({tank<D>(), solid});
  const std::vector<Vec<D>> foot = {at<D>(0.5, 0.004), at<D>(0.596, 0.004)};
  onFloor.find(fluidAt<D>(foot), foot, noPeriodic, leaks);
  BOOST_REQUIRE(leaks.size() == 1u);
  BOOST_TEST(leaks[0].particle == 0);
  BOOST_TEST(leaks[0].wall == 1);
  BOOST_TEST(leaks[0].face == 3);
  BOOST_TEST(onFloor.walls()[1].covered[2]);
  BOOST_TEST(!onFloor.walls()[1].covered[3]);
  body.find(fluidAt<D>(foot), foot, noPeriodic, leaks);
  BOOST_TEST(leaks.empty());
}

// A wall holding a curved or STL solid (as the generator hands it on).
template <int D>
WallBox<D> bodyWall(const std::string& name, std::shared_ptr<const SolidShape<D>> body) {
  WallBox<D> w;
  w.name = name;
  w.d0 = 0.01;
  w.layers = 3;
  w.solid = true;
  w.min = w.outerMin = body->lower();
  w.max = w.outerMax = body->upper();
  w.body = std::move(body);
  return w;
}

// Along `inward` (a unit vector) from the surface point `surface`: 0.6 d0 deep is a leak
// through the body's surface, 0.25 d0 deep and 0.25 d0 outside are not.
template <int D>
void checkBodyLeak(const WallBox<D>& w, const Vec<D>& surface, const Vec<D>& inward, const std::string& kind) {
  const LeakDetector<D> det({w});
  const std::vector<Vec<D>> x = {surface - 0.0025 * inward, surface + 0.0025 * inward, surface + 0.006 * inward};
  std::vector<Leak> leaks;
  det.find(fluidAt<D>(x), x, PeriodicBox<D>(), leaks);
  BOOST_REQUIRE(leaks.size() == 1u);
  BOOST_TEST(leaks[0].particle == 2);
  BOOST_TEST(leaks[0].face == kBodySurface);
  BOOST_TEST(!leaks[0].crossed);
  BOOST_TEST(det.describe(leaks[0]) == "wall '" + w.name + "' (" + kind + ")");
  BOOST_TEST(std::string(faceLabel(leaks[0].face)).rfind("surface", 0) == 0u);
}

BOOST_AUTO_TEST_CASE(leaksThroughCurvedAndStlSolids) {
  const Vec<2> c2(0.5, 0.5);
  checkBodyLeak<2>(bodyWall<2>("disc", std::make_shared<BallShape<2>>(c2, 0.1)), c2 + Vec<2>(0.06, 0.08),
                   Vec<2>(-0.6, -0.8), "solid disc");
  const Vec<3> c3(0.5, 0.5, 0.5);
  checkBodyLeak<3>(bodyWall<3>("ball", std::make_shared<BallShape<3>>(c3, 0.1)), c3 + Vec<3>(0, 0, 0.1),
                   Vec<3>(0, 0, -1), "solid ball");
  // A cylinder along (1 1 0)/sqrt 2: through its side, and through a cap.
  const Vec<3> a = Vec<3>(1, 1, 0).normalized();
  const auto pier = bodyWall<3>("pier", std::make_shared<CylinderShape>(c3, c3 + 0.4 * a, 0.1));
  checkBodyLeak<3>(pier, c3 + 0.2 * a + Vec<3>(0, 0, 0.1), Vec<3>(0, 0, -1), "solid cylinder");
  checkBodyLeak<3>(pier, c3 + 0.4 * a, -a, "solid cylinder");
  // An STL cube (12 triangles) 0.2 m across: through its top face.
  const auto cube = test::boxMesh(Vec<3>(0.4, 0.4, 0.4), Vec<3>(0.6, 0.6, 0.6));
  const auto stl = std::make_shared<StlShape>(TriangleSurface(cube.v, cube.t, 0.04), "cube.stl", 0.04);
  checkBodyLeak<3>(bodyWall<3>("cube", stl), Vec<3>(0.53, 0.47, 0.6), Vec<3>(0, 0, -1), "STL surface 'cube.stl'");
  // The same with its phi voxels (a solid wall's, as the generator builds it).
  const auto voxels = std::make_shared<StlShape>(TriangleSurface(cube.v, cube.t, 0.04), "cube.stl", 0.04, 0.01);
  checkBodyLeak<3>(bodyWall<3>("cube", voxels), Vec<3>(0.53, 0.47, 0.6), Vec<3>(0, 0, -1), "STL surface 'cube.stl'");
}

BOOST_AUTO_TEST_CASE(domainOfSolids) {
  const Dictionary none = Dictionary::fromString("", "controlDict");
  const auto p = fluidAt<2>({at<2>(0.5, 0.2)});
  const auto disc = bodyWall<2>("disc", std::make_shared<BallShape<2>>(Vec<2>(1.2, 0.2), 0.1));
  BOOST_TEST(!Domain<2>::read(none, {disc}, p).bounded());  // solids alone hold no fluid
  const Domain<2> d = Domain<2>::read(none, {tank<2>(), disc}, p);
  BOOST_TEST(d.max()[0] == 1.3, boost::test_tools::tolerance(1e-12));  // the disc sticks out of the tank
  BOOST_TEST(d.min()[0] == -0.03, boost::test_tools::tolerance(1e-12));
}

template <int D>
void checkRemoval() {
  auto p = fluidAt<D>({at<D>(0, 0), at<D>(1, 0), at<D>(2, 0), at<D>(3, 0), at<D>(4, 0)});
  p.shift.assign(5, Vec<D>::Zero());
  for (int i = 0; i < 5; ++i) {
    p.pressure[std::size_t(i)] = i;
    p.shift[std::size_t(i)][0] = i;
  }
  const auto* x = p.position.data();
  const std::size_t cap = p.position.capacity();
  BOOST_TEST(p.removeMarked({0, 1, 0, 1, 0}) == 3u);
  BOOST_TEST(p.position.data() == x);
  BOOST_TEST(p.position.capacity() == cap);
  BOOST_TEST(p.id == (std::vector<std::int64_t>{10, 12, 14}));
  BOOST_TEST(p.pressure == (std::vector<double>{0, 2, 4}));
  BOOST_TEST(p.shift[2][0] == 4);
  BOOST_TEST(p.position[1][0] == 2);
  BOOST_TEST(p.velocity.size() == 3u);
  BOOST_TEST(p.normal.empty());  // absent fields stay absent
}

}  // namespace

BOOST_AUTO_TEST_CASE(defaultDomain2D) { checkDefaultDomain<2>(); }
BOOST_AUTO_TEST_CASE(defaultDomain3D) { checkDefaultDomain<3>(); }
BOOST_AUTO_TEST_CASE(controlDictDomain2D) { checkControlDictDomain<2>(); }
BOOST_AUTO_TEST_CASE(controlDictDomain3D) { checkControlDictDomain<3>(); }
BOOST_AUTO_TEST_CASE(leaks2D) { checkLeaks<2>(); }
BOOST_AUTO_TEST_CASE(leaks3D) { checkLeaks<3>(); }
BOOST_AUTO_TEST_CASE(removal2D) { checkRemoval<2>(); }
BOOST_AUTO_TEST_CASE(removal3D) { checkRemoval<3>(); }
