// Limits of the particle generator (ParticleGenerator.hpp): maxParticles is
// checked before anything is allocated (per region, in total, and exactly
// after filling), a caller's cap lowers it, coordinates far from the origin
// are refused, and fluid outside every wall, or partly outside the walls'
// interior, is an error. Counts are worked out by hand.
#define BOOST_TEST_MODULE particles_limits
#include <boost/test/unit_test.hpp>

#include "particles/ParticleGenerator.hpp"
#include <chrono>
#include <iostream>
#include <sstream>

using namespace shizuku;

namespace {

template <int D> GeneratedParticles<D> generate(const std::string& text, double cap = 0) {
  return generateParticles<D>(Dictionary::fromString(text, "case/system/particlesDict"), cap);
}

template <int D> std::string errorOf(const std::string& text, double cap = 0) {
  try {
    generate<D>(text, cap);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// What the generator logs to standard output while making `text`.
std::string logOf(const std::string& text) {
  std::ostringstream captured;
  std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
  try {
    generate<2>(text);
  } catch (...) {
    std::cout.rdbuf(old);
    throw;
  }
  std::cout.rdbuf(old);
  return captured.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(fluid_box_over_the_limit_is_refused_before_allocating) {
  // 1 m / 1e-6 m = 1e6 cells per direction: 1e12 particles, refused at once
  // (allocating them would need tens of terabytes).
  const std::string m = errorOf<2>("spacing 1e-6; regions { f { type fluid; shape box; min (0 0); max (1 1); } }");
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "case/system/particlesDict:1:"));
  BOOST_TEST(contains(m, "keyword 'f': fluid region 'f' would hold 1000000000000 particles, more than maxParticles 10000000"));
  // The same in 3D: 1e18.
  BOOST_TEST(contains(errorOf<3>("spacing 1e-6; regions { f { type fluid; shape box; min (0 0 0); max (1 1 1); } }"),
                      "would hold 1e18 particles"));
}

BOOST_AUTO_TEST_CASE(max_particles_keyword_is_an_exact_bound_for_boxes) {
  // 10 x 10 cells = 100 particles: 100 is allowed, 99 is not.
  const std::string box = "spacing 0.1; regions { f { type fluid; shape box; min (0 0); max (1 1); } }";
  BOOST_TEST(generate<2>("maxParticles 100; " + box).set.size() == 100u);
  BOOST_TEST(contains(errorOf<2>("maxParticles 99; " + box), "would hold 100 particles, more than maxParticles 99"));
  // A caller's cap lowers the limit but never raises it.
  BOOST_TEST(contains(errorOf<2>(box, 50), "more than maxParticles 50"));
  BOOST_TEST(contains(errorOf<2>("maxParticles 99; " + box, 1000), "more than maxParticles 99"));
  BOOST_TEST(generate<2>(box, 100).set.size() == 100u);
  // Out of range values.
  BOOST_TEST(contains(errorOf<2>("maxParticles 0; " + box), "keyword 'maxParticles': 0 is below the smallest allowed 1"));
  BOOST_TEST(contains(errorOf<2>("maxParticles 3e9; " + box),
                      "keyword 'maxParticles': 3e9 is above the largest allowed 2147483647"));
}

BOOST_AUTO_TEST_CASE(walls_and_totals_count_against_the_limit) {
  // Closed wall box 10 x 5 cells, 2 layers: (10 + 4) * (9) - 50 = 76 wall particles; one fluid particle.
  const std::string c = "spacing 1; regions { f { type fluid; shape box; min (0 0); max (1 1); }"
                        " w { type wall; shape box; min (0 0); max (10 5); layers 2; } }";
  BOOST_TEST(generate<2>("maxParticles 77; " + c).set.size() == 77u);
  BOOST_TEST(contains(errorOf<2>("maxParticles 76; " + c), "keyword 'regions': the regions would hold 77 particles"));
  BOOST_TEST(contains(errorOf<2>("maxParticles 75; " + c), "keyword 'w': wall region 'w' would hold 76 particles"));
  // Absurd layers are refused before the lattice loop runs.
  BOOST_TEST(contains(errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (0 0); max (1 1); }"
                                 " w { type wall; shape box; min (0 0); max (10 5); layers 2000000000; } }"),
                      "wall region 'w' would hold"));
}

BOOST_AUTO_TEST_CASE(circle_estimate_and_exact_count) {
  // A disc of radius 5 d0 holds 80 lattice points (test_particles_generator); its
  // area estimate is 25 pi = 78.5: a limit of 79 passes the estimate and is caught
  // by the exact count, a limit of 78 by the estimate.
  const std::string disc = "spacing 1; regions { d { type fluid; shape circle; centre (0 0); radius 5; } }";
  BOOST_TEST(generate<2>("maxParticles 80; " + disc).set.size() == 80u);
  BOOST_TEST(contains(errorOf<2>("maxParticles 79; " + disc), "the regions hold 80 particles, more than maxParticles 79"));
  BOOST_TEST(contains(errorOf<2>("maxParticles 78; " + disc), "fluid region 'd' would hold 79 particles"));
}

BOOST_AUTO_TEST_CASE(coordinates_far_from_the_origin_are_refused) {
  BOOST_TEST(contains(errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (1e300 0); max (2e300 1); } }"),
                      "keyword 'min': 1e300 m is beyond the physically sane magnitude 1e12 m"));
  BOOST_TEST(contains(errorOf<2>("spacing 1e-6; regions { f { type fluid; shape box; min (1e9 0); max (2e9 1); } }"),
                      "keyword 'min': (1e9 0) lies more than 1e12 spacings"));
  BOOST_TEST(contains(errorOf<2>("spacing 1; regions { f { type fluid; shape circle; centre (0 -1e13); radius 3; } }"),
                      "keyword 'centre'"));
  BOOST_TEST(contains(errorOf<2>("spacing 1; regions { f { type fluid; shape circle; centre (0 0); radius 1e13; } }"),
                      "keyword 'radius'"));
  BOOST_TEST(contains(errorOf<2>("spacing 1; periodic { min (0 0); max (1e14 1); }"
                                 " regions { f { type fluid; shape box; min (0 0); max (1 1); } }"),
                      "keyword 'max'"));
  // Up to 1e12 spacings is accepted (and the lattice there is exact: 10 cells).
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (999999999990 0); max (1e12 1); } }")
                 .set.size() == 10u);
}

BOOST_AUTO_TEST_CASE(fluid_outside_every_wall_is_an_error) {
  const std::string tank = " t { type wall; shape box; min (0 0); max (10 10); layers 2; open (top); } }";
  const std::string m = errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (20 0); max (25 5); }" + tank);
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "keyword 'f': fluid region 'f' lies outside every wall ('t')"));
  // Above an open top is inside the container: a drop falling into the tank.
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (2 20); max (4 22); }" + tank).set.size() > 4u);
  // Above a closed lid is outside.
  BOOST_TEST(contains(errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (2 20); max (4 22); }"
                                 " t { type wall; shape box; min (0 0); max (10 10); layers 2; } }"),
                      "lies outside every wall"));
  // Without walls any place is fine.
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (20 0); max (25 5); } }").set.size() == 25u);
}

BOOST_AUTO_TEST_CASE(fluid_outside_the_walls_interior_is_an_error) {
  // Fluid x in (0, 20) against a tank of width 10 with 2 layers: columns x = 0.5 .. 9.5
  // inside (10 x 5 = 50 particles), 10.5, 11.5 in the layers (removed), 12.5 .. 19.5
  // beyond the right face (8 x 5 = 40).
  const std::string tank = " t { type wall; shape box; min (0 0); max (10 10); layers 2; open (top); } }";
  const std::string m = errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (0 0); max (20 5); }" + tank);
  BOOST_TEST_INFO(m);
  BOOST_TEST(contains(m, "case/system/particlesDict:1:"));
  BOOST_TEST(contains(m, "keyword 'f': fluid region 'f' reaches outside wall 't': 40 of its 90 fluid particles lie "
                         "outside the interior of every wall (40 beyond the right face (x > 10 m))"));
  // Each particle outside is counted at the first face it lies beyond (x before y): a
  // 9 x 9 box from (-4 -4) over the corner of a closed tank with 1 layer: 11 particles in
  // the layer are removed, 25 lie inside, 30 beyond the left face (x < 0; 27 of them with
  // x <= -1.5, 3 at x = -0.5 below the layer), 15 beyond the bottom face (0 < x < 5).
  const std::string corner = errorOf<2>("spacing 1; regions { f { type fluid; shape box; min (-4 -4); max (5 5); }"
                                        " t { type wall; shape box; min (0 0); max (10 10); layers 1; } }");
  BOOST_TEST_INFO(corner);
  BOOST_TEST(contains(corner, "45 of its 70 fluid particles lie outside the interior of every wall (30 beyond the "
                              "left face (x < 0 m), 15 beyond the bottom face (y < 0 m))"));
  // A particle on the surface of a wall belongs to its closed interior; so does one
  // above an open face; a second wall's interior counts as well.
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (0.5 0); max (10.5 5); }"
                         " t { type wall; shape box; min (0 0); max (10 10); layers 2; open (top); } }").set.size() > 0u);
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (2 20); max (4 22); }" + tank).set.size() > 4u);
  BOOST_TEST(generate<2>("spacing 1; regions { f { type fluid; shape box; min (0 0); max (30 5); }"
                         " a { type wall; shape box; min (0 0); max (15 10); layers 1; open (right top); }"
                         " b { type wall; shape box; min (15 0); max (30 10); layers 1; open (left top); } }")
                 .set.size() > 150u);
  BOOST_TEST(logOf("spacing 1; regions { f { type fluid; shape box; min (0 0); max (10 5); }" + tank).empty());
}
