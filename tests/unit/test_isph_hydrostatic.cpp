// Still water in a tank (docs/method.md 4.2): with u* = g dt everywhere and the
// dummy walls showing the Shepard fluid velocity, the linear hydrostatic field
// p = rho g (y_top - y) satisfies every SPH(2) Laplacian row, every Dirichlet
// row and every Adami wall row exactly, so the first projection step must
// return it to round-off and leave u = 0 to round-off. Any deviation is a bug
// in the PPE assembly, the wall rows, the free-surface classes or the corrector.
#define BOOST_TEST_MODULE isph_hydrostatic
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "isph/Simulation.hpp"

using namespace shizuku;

namespace {
void writeTank(test::TempCase& c, const std::string& solver, const std::string& schemes) {
  c.file("system/controlDict", "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing 0.02;\nregions {\n water { type fluid; shape box; min (0 0); max (0.4 0.3); }\n"
         " tank { type wall; shape box; min (0 0); max (0.4 0.5); layers 3; open (top); }\n}\n");
  c.file("system/sphSchemes", schemes);
  c.file("system/sphSolution", "pressure { solver " + solver + "; tolerance 1e-12; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  c.file("constant/g", "value (0 -9.81);\n");
}
}  // namespace

BOOST_AUTO_TEST_CASE(first_step_returns_linear_hydrostatic_pressure) {
  for (const std::string solver : {"BiCGSTAB", "UMFPACK", "KLU", "SparseLU"}) {
    test::TempCase c("hydrostatic");
    writeTank(c, solver, "derivatives SPH2;\n");
    SimulationOptions opt;
    opt.functionObjects = false;
    Simulation<2> sim(c.dir(), opt);
    sim.analyse();
    const auto& s = sim.state();
    // Classes: the top row (and only it) is free surface.
    double yTop = -1;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s.isFluid(i)) yTop = std::max(yTop, s.particles.position[i].y());
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!s.isFluid(i)) continue;
      const bool top = std::abs(s.particles.position[i].y() - yTop) < 1e-9;
      BOOST_TEST_CONTEXT("particle " << i << " at " << s.particles.position[i].transpose()) {
        BOOST_TEST((s.surfaceClass(i) == SurfaceClass::free) == top);
      }
    }
    sim.step(1e-3);
    const double rho = 1000, g = 9.81;
    double maxErr = 0, maxU = 0, pScale = rho * g * yTop;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!s.isFluid(i)) continue;
      const double exact = rho * g * (yTop - s.particles.position[i].y());
      maxErr = std::max(maxErr, std::abs(s.particles.pressure[i] - exact));
      maxU = std::max(maxU, s.particles.velocity[i].norm());
    }
    BOOST_TEST_MESSAGE(solver << ": max pressure error " << maxErr / pScale << " (relative), max |u| " << maxU);
    // Round-off: the relative pressure error is ~1e-13 with every backend; 1e-9 leaves
    // room for the iterative tolerance (1e-12) times the condition number.
    BOOST_TEST(maxErr / pScale < 1e-9);
    BOOST_TEST(maxU < 1e-9 * g * 1e-3 * 1e3);
  }
}

BOOST_AUTO_TEST_CASE(still_water_stays_still) {
  test::TempCase c("still");
  writeTank(c, "BiCGSTAB", "derivatives SPH2;\n");
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<2> sim(c.dir(), opt);
  sim.analyse();
  for (int k = 0; k < 200; ++k) {
    sim.step(2e-3);
    sim.analyse();
  }
  double maxU = 0;
  const auto& s = sim.state();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) maxU = std::max(maxU, s.particles.velocity[i].norm());
  BOOST_TEST_MESSAGE("max |u| after 0.4 s: " << maxU);
  // Without shifting a perfect lattice stays a lattice: round-off only.
  BOOST_TEST(maxU < 1e-10);
}
