// The adaptive time step's Courant limit dt = maxCo h / max|u| (docs/method.md 4.3), on a
// flow whose speed is known at every step: a fully periodic box of fluid moving uniformly
// (no wall, no gravity, no viscosity: u stays (2, 0) exactly, so every step is CFL-limited).
// And the shift's passes (docs/method.md 6, eq. 10b) such steps take.
#define BOOST_TEST_MODULE isph_timeStep
#include <boost/test/unit_test.hpp>
#include "../support/RestartRuns.hpp"
#include "isph/RunLog.hpp"

using namespace shizuku;

namespace {

// d0 = 0.02 m, h = 1.2 d0 = 0.024 m, |u| = 2 m/s, to t = 0.024 s.
void uniformStream(test::TempCase& c, double maxCo, const std::string& schemes) {
  c.file("system/controlDict",
         "endTime 0.024; deltaT 0.01; adjustTimeStep yes; maxCo " + std::to_string(maxCo) + "; maxDeltaT 1;\n"
         "writeControl timeStep; writeInterval 1000; progressInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing 0.02;\nperiodic { min (0 0); max (0.4 0.4); directions (x y); }\n"
         "regions {\n water { type fluid; shape box; min (0 0); max (0.4 0.4);\n"
         "   velocity { type uniform; value (2 0); } }\n}\n");
  c.file("system/sphSchemes", "derivatives SPH2;\n" + schemes);
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000;\n");
}

}  // namespace

BOOST_AUTO_TEST_CASE(uniform_stream_takes_courant_limited_steps) {
  // maxCo 0.2: dt = 0.0024 s, so the run to 0.024 s takes exactly 10 steps (a doubled
  // limit would take 5, a halved one 20).
  test::TempCase c("uniformStream");
  uniformStream(c, 0.2, "");
  const auto sim = test::runQuietly<2>(c);
  BOOST_TEST_REQUIRE(sim->state().h == 0.024, boost::test_tools::tolerance(1e-12));
  double umax = 0;
  for (std::size_t i = 0; i < sim->state().size(); ++i)
    umax = std::max(umax, sim->state().particles.velocity[i].norm());
  BOOST_TEST(umax == 2.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sim->state().step == 10);
  BOOST_TEST(sim->state().time == 0.024, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sim->state().dt == 0.0024, boost::test_tools::tolerance(1e-6));
}

// With OPS shifting: at maxCo 0.2 one pass a step; at maxCo 0.5 every step has Co = 0.5,
// three passes, and the progress line says so.
BOOST_AUTO_TEST_CASE(large_steps_shift_in_passes) {
  for (const double maxCo : {0.2, 0.5}) {
    test::TempCase c("uniformStreamShifted");
    uniformStream(c, maxCo, "shifting { distribution { type OPS; } }\n");
    const auto sim = test::runQuietly<2>(c);
    const int expected = maxCo > 0.2 ? 3 : 1;
    const std::string line = progressLine(ProgressInfo{}, sim->lastStep());
    BOOST_TEST(sim->lastStep().shiftPasses == expected, "maxCo " << maxCo);
    BOOST_TEST((line.find("shift passes") != std::string::npos) == (expected > 1), line);
    if (expected > 1) BOOST_TEST(line.find("shift passes 3") != std::string::npos, line);
  }
}
