// Fluid sliding along a vertical wall (docs/method.md 11, the wall row, eq. 11a): the wall
// row cancels the velocity normal to the wall, never the velocity along it, and carries
// no weight of a lone particle beside a vertical wall. A lone particle beside the left wall
// of a tank, moving down along it at 1 m/s, must fall freely: with the whole relative
// velocity in the row the wall particles below it took a high pressure and those above
// it a low one and the pair stopped it (as it held particles at the top of the Martin &
// Moyce column on the wall); with gravity's whole hydrostatic extrapolation the wall
// below it carried its weight and it kept 1 m/s (a particle thrown up a wall climbed it
// at constant speed). The same particle moving into the floor must still be stopped
// before the wall line (the reason the velocity term exists). A body of water that fills a
// tank's width and falls onto its floor as a whole is stopped by the same term: confined by
// the side walls, incompressible water has no other way to move, so the projection's
// exact answer is rest after one step, with the impulsive pressure rho v (H - y) / dt.
// The same block thrown up from rest leaves the floor (eq. 11b): the floor's wall rows take
// ambient pressure, not below it, and the block flies freely. Taking the bound's value as the
// row's right-hand side (-sum W p^n_f / sum W, the previous step's fluid pressure) instead
// gave the floor the change of the fluid's pressure over the step: the hydrostatic pressure
// the block had at rest, with the sign reversed, which held its bottom row back.
#define BOOST_TEST_MODULE isph_wallSlide
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "isph/Simulation.hpp"

using namespace shizuku;
using test::vec;

namespace {
constexpr double kG = 9.81, kDt = 1e-3, kD0 = 0.02;

// The case around `regions` (the body of particlesDict's regions dictionary) at spacing d0:
// no viscosity, no shifting, gravity along -y, a direct pressure solve.
template <int D>
void writeCase(test::TempCase& c, double d0, const std::string& regions) {
  c.file("system/controlDict", "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1000;\n");
  c.file("system/particlesDict", "spacing " + std::to_string(d0) + ";\nregions {\n" + regions + "}\n");
  c.file("system/sphSchemes", "derivatives SPH2;\n");
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  c.file("constant/g", std::string("value ") + (D == 2 ? "(0 -9.81)" : "(0 -9.81 0)") + ";\n");
}

// A tank 0.4 m wide (x, and z in 3D), 0.6 m high, open at the top, holding one fluid
// particle at (x, y, x) with velocity u (x = 0: beside the left wall, in 3D also the
// front wall).
template <int D>
void writeDropCase(test::TempCase& c, double x, double y, const std::string& u) {
  writeCase<D>(c, kD0,
               " drop { type fluid; shape box; min " + vec<D>(x, y, x) + "; max " + vec<D>(x + kD0, y + kD0, x + kD0) +
                   "; velocity { type uniform; value " + u + "; } }\n tank { type wall; shape box; min " +
                   vec<D>(0, 0, 0) + "; max " + vec<D>(0.4, 0.6, 0.4) + "; layers 3; open (top); }\n");
}

// A block filling the tank's width, `rows` deep, every particle moving down at 1 m/s.
template <int D>
void writeBlockCase(test::TempCase& c, int rows, double d0) {
  const double width = 10 * d0;
  writeCase<D>(c, d0,
               " block { type fluid; shape box; min " + vec<D>(0, 0, 0) + "; max " + vec<D>(width, rows * d0, width) +
                   "; velocity { type uniform; value " + (D == 2 ? "(0 -1)" : "(0 -1 0)") + "; } }\n" +
                   " tank { type wall; shape box; min " + vec<D>(0, 0, 0) + "; max " +
                   vec<D>(width, 2 * rows * d0, width) + "; layers 3; open (top); }\n");
}

// What `measure` returns for the simulation of the block case (rows deep, spacing d0),
// without function objects.
template <int D, class Measure>
auto onBlock(int rows, double d0, Measure measure) {
  test::TempCase c("wallBlock");
  writeBlockCase<D>(c, rows, d0);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  return measure(sim);
}

// The largest fluid speed after one step of kDt: {over the particles farther than the
// support 2.4 d0 from every side wall, over all}.
template <int D>
std::pair<double, double> blockSpeedsAfterOneStep(int rows, double d0) {
  return onBlock<D>(rows, d0, [&](Simulation<D>& sim) {
    sim.analyse();
    sim.step(kDt);
    const auto& s = sim.state();
    const double width = 10 * d0, margin = 2.4 * d0;
    double middle = 0, all = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!s.isFluid(i)) continue;
      const Vec<D>& r = s.particles.position[i];
      bool away = r.x() > margin && r.x() < width - margin;
      if (D == 3) away = away && r[D - 1] > margin && r[D - 1] < width - margin;
      const double speed = s.particles.velocity[i].norm();
      all = std::max(all, speed);
      if (away) middle = std::max(middle, speed);
    }
    return std::pair<double, double>{middle, all};
  });
}

// A block at rest on the floor for one step (hydrostatic pressure), then thrown up as a
// whole at 1 m/s for one more: {the lowest floor wall pressure, the largest departure of a
// fluid particle's velocity from free flight, (0, 1 - g dt)}.
template <int D>
std::pair<double, double> blockThrownUpFromTheFloor(int rows, double d0) {
  return onBlock<D>(rows, d0, [](Simulation<D>& sim) {
    auto& s = sim.state();
    auto setFluidVelocity = [&](const Vec<D>& u) {
      for (std::size_t i = 0; i < s.size(); ++i)
        if (s.isFluid(i)) s.particles.velocity[i] = u;
    };
    setFluidVelocity(Vec<D>::Zero());
    sim.analyse();
    sim.step(kDt);
    sim.analyse();
    Vec<D> up = Vec<D>::Zero();
    up.y() = 1.0;
    setFluidVelocity(up);
    sim.step(kDt);
    Vec<D> flight = up;
    flight.y() -= kG * kDt;
    double lowestFloor = 0, departure = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.isFluid(i)) departure = std::max(departure, (s.particles.velocity[i] - flight).norm());
      else if (s.particles.isWall(i) && s.particles.position[i].y() < 0)
        lowestFloor = std::min(lowestFloor, s.particles.pressure[i]);
    }
    return std::pair<double, double>{lowestFloor, departure};
  });
}

template <int D>
void blockLeavesTheFloor() {
  const int rows = D == 2 ? 8 : 5;
  const auto [lowestFloor, departure] = blockThrownUpFromTheFloor<D>(rows, kD0);
  const double rhoGH = 1000 * kG * rows * kD0;
  BOOST_TEST_MESSAGE(D << "D block thrown up from the floor at 1 m/s: lowest floor pressure " << lowestFloor / rhoGH
                       << " rho g H, largest departure from free flight " << departure << " m/s");
  // Measured: 0 and 0.002 m/s (2D), 0 and 0.003 m/s (3D); with the bound's value as the
  // row's right-hand side -9.3 and -6.5 rho g H, 0.093 and 0.063 m/s.
  BOOST_TEST(lowestFloor >= -1e-9 * rhoGH);
  BOOST_TEST(departure < 0.05);
}

// The lone particle's position and velocity after `steps` steps of kDt.
template <int D>
std::pair<Vec<D>, Vec<D>> stateAfter(double x, double y, const std::string& u, int steps) {
  test::TempCase c("wallSlide");
  writeDropCase<D>(c, x, y, u);
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

template <int D>
void blockStoppedByTheFloor() {
  for (double d0 : {0.02, 0.01}) {
    const auto [middle, all] = blockSpeedsAfterOneStep<D>(D == 2 ? 8 : 5, d0);
    BOOST_TEST_MESSAGE(D << "D block falling onto the floor at 1 m/s, d0 " << d0 << ": largest speed after one step "
                         << middle << " m/s away from the side walls, " << all << " m/s beside them");
    // The exact answer is rest. Measured: 0.106 (2D) and 0.158 m/s (3D) at both spacings, the
    // problem being the same in units of d0 (the whole block keeps about 7 % of its speed,
    // the particles near the side walls spread sideways); beside the side walls 0.25 and
    // 0.37 m/s, where the wall normal a fluid particle sees tilts towards the corner. The
    // bound, a fifth of the speed, guards the wall row's velocity term for water under the
    // surface: with it on free and splash particles only and the walls impermeable in the
    // divergence instead (docs/validation.md, "Walls in the divergence"), 0.75 m/s in 2D and 3D.
    // With eq. 11b decided only from the previous step's pressure (zero before the impact),
    // the side walls beside the block took ambient pressure: 0.31 m/s in 2D.
    BOOST_TEST(middle < 0.2);
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(block_filling_the_tank_is_stopped_by_the_floor_2d) { blockStoppedByTheFloor<2>(); }
BOOST_AUTO_TEST_CASE(block_filling_the_tank_is_stopped_by_the_floor_3d) { blockStoppedByTheFloor<3>(); }
BOOST_AUTO_TEST_CASE(block_thrown_up_leaves_the_floor_at_ambient_pressure_2d) { blockLeavesTheFloor<2>(); }
BOOST_AUTO_TEST_CASE(block_thrown_up_leaves_the_floor_at_ambient_pressure_3d) { blockLeavesTheFloor<3>(); }
BOOST_AUTO_TEST_CASE(lone_particle_sliding_down_a_vertical_wall_is_not_braked_2d) { slidesFreely<2>(); }
BOOST_AUTO_TEST_CASE(lone_particle_sliding_down_a_vertical_wall_is_not_braked_3d) { slidesFreely<3>(); }
BOOST_AUTO_TEST_CASE(particle_moving_into_the_floor_is_stopped_2d) { stoppedByTheFloor<2>(); }
BOOST_AUTO_TEST_CASE(particle_moving_into_the_floor_is_stopped_3d) { stoppedByTheFloor<3>(); }
