// The adaptive time step's Courant limit dt = maxCo h / max|u| (docs/method.md 4.3), on a
// flow whose speed is known at every step: a fully periodic box of fluid moving uniformly
// (no wall, no gravity, no viscosity: u stays (2, 0) exactly, so every step is CFL-limited).
#define BOOST_TEST_MODULE isph_timeStep
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "core/Log.hpp"
#include "isph/Simulation.hpp"

using namespace shizuku;

BOOST_AUTO_TEST_CASE(uniform_stream_takes_courant_limited_steps) {
  // d0 = 0.02 m, h = 1.2 d0 = 0.024 m, |u| = 2 m/s, maxCo 0.2: dt = 0.0024 s, so the run
  // to 0.024 s takes exactly 10 steps (a doubled limit would take 5, a halved one 20).
  test::TempCase c("uniformStream");
  c.file("system/controlDict",
         "endTime 0.024; deltaT 0.01; adjustTimeStep yes; maxCo 0.2; maxDeltaT 1;\n"
         "writeControl timeStep; writeInterval 1000; progressInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing 0.02;\nperiodic { min (0 0); max (0.4 0.4); directions (x y); }\n"
         "regions {\n water { type fluid; shape box; min (0 0); max (0.4 0.4);\n"
         "   velocity { type uniform; value (2 0); } }\n}\n");
  c.file("system/sphSchemes", "derivatives SPH2;\n");
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000;\n");
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  Simulation<2> sim(c.dir(), opt);
  BOOST_TEST_REQUIRE(sim.state().h == 0.024, boost::test_tools::tolerance(1e-12));
  const int status = sim.run();
  Log::get().quiet = false;
  BOOST_TEST_REQUIRE(status == 0);
  double umax = 0;
  for (std::size_t i = 0; i < sim.state().size(); ++i) umax = std::max(umax, sim.state().particles.velocity[i].norm());
  BOOST_TEST(umax == 2.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sim.state().step == 10);
  BOOST_TEST(sim.state().time == 0.024, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sim.state().dt == 0.0024, boost::test_tools::tolerance(1e-6));
}
