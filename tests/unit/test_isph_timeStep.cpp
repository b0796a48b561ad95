// The adaptive time step's Courant limit dt = maxCo h / max|u| (docs/method.md 4.3), on a
// flow whose speed is known at every step: a fully periodic box of fluid moving uniformly
// (no wall, no gravity, no viscosity: u stays (2, 0) exactly, so every step is CFL-limited).
// And the shift's passes (docs/method.md 6, eq. 10b) such steps take, and how the steps
// land on write times (RunControl::evenStepTo).
#define BOOST_TEST_MODULE isph_timeStep
#include <boost/test/unit_test.hpp>
#include "../support/RestartRuns.hpp"
#include "isph/RunLog.hpp"

using namespace shizuku;

namespace {

// d0 = 0.02 m, h = 1.2 d0 = 0.024 m, |u| = 2 m/s, to t = 0.024 s unless `writes` replaces the
// end and write keys.
void uniformStream(test::TempCase& c, double maxCo, const std::string& schemes,
                   const std::string& writes = "endTime 0.024; writeControl timeStep; writeInterval 1000;") {
  c.file("system/controlDict",
         writes + " deltaT 0.01; adjustTimeStep yes; maxCo " + std::to_string(maxCo) + "; maxDeltaT 1;\n"
         "progressInterval 1000;\n");
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

// Writes every 0.01 s with Courant-limited steps of 0.0024 s: each interval holds 4.17 such
// steps, so it is crossed in 5 equal steps of 0.002 s. Shortening only the last steps to land
// on the write time gave 2.4, 2.4, 2.4, 1.4 and 1.4 ms, and the pressure's part that scales
// with 1/dt spiked in the short steps at every write (docs/method.md 4.3).
BOOST_AUTO_TEST_CASE(write_times_are_reached_in_equal_steps) {
  test::TempCase c("uniformStreamWrites");
  uniformStream(c, 0.2, "", "endTime 0.03; writeControl adjustableRunTime; writeInterval 0.01;");
  const auto sim = test::runQuietly<2>(c);
  BOOST_TEST(sim->state().step == 15);
  BOOST_TEST(sim->state().time == 0.03, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sim->state().dt == 0.002, boost::test_tools::tolerance(1e-9));  // the last step, as every other
  for (const char* t : {"0.01", "0.02", "0.03"}) BOOST_TEST(std::filesystem::exists(c.dir() + "/" + t), t);
  // The rule itself: the fewest equal steps of at most dt; within 1e-6 of dt counts as dt.
  BOOST_TEST(RunControl::evenStepTo(1e-4, 3.5e-4) == 0.875e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(1e-4, 3e-4) == 1e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(1e-4, 3e-4 + 1e-12) == 1e-4, boost::test_tools::tolerance(1e-6));  // no sliver left
  BOOST_TEST(RunControl::evenStepTo(1e-4, 0.3e-4) == 0.3e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(1e-4, 0.0) == 1e-4);
  // A running plan of 1e-4 s steps, one step left, after the limit fell by 3 %: kept (the
  // strict rule would halve the last step); after it fell by 10 %: the time left is divided
  // again within the limit.
  BOOST_TEST(RunControl::evenStepTo(0.97e-4, 1e-4, 1e-4) == 1e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(0.97e-4, 1e-4) == 0.5e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(0.9e-4, 1e-4, 1e-4) == 0.5e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(RunControl::evenStepTo(0.97e-4, 3e-4, 1e-4) == 1e-4, boost::test_tools::tolerance(1e-12));
  // Not a plan: the previous step does not divide the time left.
  BOOST_TEST(RunControl::evenStepTo(0.97e-4, 2.9e-4, 1e-4) == 2.9e-4 / 3, boost::test_tools::tolerance(1e-12));
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
