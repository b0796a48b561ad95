// Fluid sliding along a vertical wall (docs/method.md 11, the wall row, eq. 11a): the wall
// row cancels the velocity normal to the wall, never the velocity along it, and carries
// no weight of a lone particle beside a vertical wall. A lone particle beside the left wall
// of a tank, moving down along it at 1 m/s, must fall freely: with the whole relative
// velocity in the row the wall particles below it took a high pressure and those above
// it a low one and the pair stopped it (as it held particles at the top of the Martin &
// Moyce column on the wall); with gravity's whole hydrostatic extrapolation the wall
// below it carried its weight and it kept 1 m/s (a particle thrown up a wall climbed it
// at constant speed). The same particle moving into the floor must still be stopped
// before the wall line (the reason the velocity term exists).
#define BOOST_TEST_MODULE isph_wallSlide
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "isph/Simulation.hpp"

using namespace shizuku;

namespace {
constexpr double kG = 9.81, kDt = 1e-3, kD0 = 0.02;

// A tank 0.4 m wide (x, and z in 3D), 0.6 m high, open at the top, holding one fluid
// particle at (x, y, x) with velocity u (x = 0: beside the left wall, in 3D also the
// front wall); no viscosity, no shifting, gravity along -y.
template <int D>
void writeCase(test::TempCase& c, double x, double y, const std::string& u) {
  auto vec = [](double a, double b, double z) {
    return "(" + std::to_string(a) + " " + std::to_string(b) + (D == 3 ? " " + std::to_string(z) : "") + ")";
  };
  c.file("system/controlDict", "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1000;\n");
  c.file("system/particlesDict", "spacing 0.02;\nregions {\n drop { type fluid; shape box; min " + vec(x, y, x) +
                                     "; max " + vec(x + kD0, y + kD0, x + kD0) + "; velocity { type uniform; value " + u + "; }" +
                                     " }\n tank { type wall; shape box; min " + vec(0, 0, 0) + "; max " +
                                     vec(0.4, 0.6, 0.4) + "; layers 3; open (top); }\n}\n");
  c.file("system/sphSchemes", "derivatives SPH2;\n");
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  c.file("constant/g", std::string("value ") + (D == 2 ? "(0 -9.81)" : "(0 -9.81 0)") + ";\n");
}

// The lone particle's position and velocity after `steps` steps of kDt.
template <int D>
std::pair<Vec<D>, Vec<D>> stateAfter(double x, double y, const std::string& u, int steps) {
  test::TempCase c("wallSlide");
  writeCase<D>(c, x, y, u);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  sim.analyse();
  for (int k = 0; k < steps; ++k) {
    sim.step(kDt);
    sim.analyse();
  }
  const auto& s = sim.state();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) return {s.particles.position[i], s.particles.velocity[i]};
  BOOST_FAIL("no fluid particle left");
  return {};
}

template <int D>
void slidesFreely() {
  const int steps = 50;
  const std::string down = D == 2 ? "(0 -1)" : "(0 -1 0)";
  const Vec<D> u = stateAfter<D>(0.0, 0.4, down, steps).second;
  BOOST_TEST_MESSAGE(D << "D: u_y " << u.y() << " m/s after " << steps * kDt << " s (free fall: " << -1 - kG * steps * kDt
                        << ")");
  // Free fall, -1 - g t = -1.4905 m/s: not braked, and not carried (to 0.5 % of g t; the
  // measured difference is 1.4e-4 m/s, the viscous-free particle feels only the wall's
  // velocity-Neumann term, zero for motion along it).
  BOOST_TEST(std::abs(u.y() - (-1 - kG * steps * kDt)) < 0.005 * kG * steps * kDt);
  BOOST_TEST(std::abs(u.x()) < 0.05);
}

template <int D>
void stoppedByTheFloor() {
  // At y = d0/2 over the middle of the floor, moving into it at 1 m/s: the first step takes
  // that velocity away (without the term it crosses the wall line in 10 ms), and it stays.
  const std::string down = D == 2 ? "(0 -1)" : "(0 -1 0)";
  for (int steps : {1, 60}) {
    const auto [x, u] = stateAfter<D>(0.2, 0.0, down, steps);
    BOOST_TEST_MESSAGE(D << "D into the floor, " << steps << " steps: y " << x.y() << " m, u_y " << u.y() << " m/s");
    BOOST_TEST(std::abs(u.y()) < 1e-3);
    BOOST_TEST(x.y() > 0.0);
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(lone_particle_sliding_down_a_vertical_wall_is_not_braked_2d) { slidesFreely<2>(); }
BOOST_AUTO_TEST_CASE(lone_particle_sliding_down_a_vertical_wall_is_not_braked_3d) { slidesFreely<3>(); }
BOOST_AUTO_TEST_CASE(particle_moving_into_the_floor_is_stopped_2d) { stoppedByTheFloor<2>(); }
BOOST_AUTO_TEST_CASE(particle_moving_into_the_floor_is_stopped_3d) { stoppedByTheFloor<3>(); }
