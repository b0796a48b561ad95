// Moving walls in the ISPH step (docs/method.md 11.1, docs/boundaries.md "Moving walls"):
//  - Galilean invariance: a tank translating at constant velocity U with its water moving
//    at U gives, particle by particle, the fixed tank's result shifted by U t (positions)
//    and U (velocities), with the same pressures. Every place a wall velocity enters (the
//    wall row's velocity term, the no-slip mirror, XSPH, the shift) sees only relative
//    velocities, so the two runs differ by round-off alone. A wall that moved without
//    showing its velocity (U_w = 0) would push on the water; one shown at the wrong time
//    level would too, as soon as it accelerates (the oscillating case below).
//  - The same with the tank and its water rising at U: a wall-pressure sensor reading the
//    fluid (faceValue fluid, the default) on the moving tank equals the fixed tank's, its
//    face point moving with the wall (the rest position's face point reads rho g U t off);
//    on a turned tank it reads a linear pressure field at the face point the rotation gives.
//  - A case without a motion builds nothing of it; one with a motion names it, keeps the
//    rest positions, and its time step respects the wall's speed.
//  - A restart from latestTime continues a rolling tank bit for bit.
#define BOOST_TEST_MODULE isph_movingWalls
#include <boost/test/unit_test.hpp>
#include "../support/RestartRuns.hpp"
#include "../support/TempCase.hpp"
#include "core/Log.hpp"
#include "functionObjects/WallPressure.hpp"
#include "isph/Simulation.hpp"
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace shizuku;
using test::vec;

namespace {

const char* kSchemes =
    "derivatives SPH2;\n"
    "shifting { distribution { type OPS; } volumeCorrection { C 0.1; } surfaceFitting { C 1e-4; } maxShift 0.1; }\n"
    "ads { } xsph { epsilon 0.5; }\n";

// A tank 0.3 m wide (and deep in 3D), water 0.12 m deep, d0 = 0.02 m, the water moving
// at `u` and the tank with `motion` (empty: fixed).
template <int D>
void writeCase(test::TempCase& c, const std::string& u, const std::string& motion, const std::string& control) {
  c.file("system/controlDict", control);
  c.file("system/particlesDict",
         "spacing 0.02;\nregions {\n water { type fluid; shape box; min " + vec<D>(0, 0, 0) + "; max " +
             vec<D>(0.3, 0.12, 0.3) + "; velocity { type uniform; value " + u + "; } }\n" +
             " tank { type wall; shape box; min " + vec<D>(0, 0, 0) + "; max " + vec<D>(0.3, 0.3, 0.3) +
             "; layers 3; open (top); " + motion + " }\n}\n");
  c.file("system/sphSchemes", kSchemes);
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 1e-6;\n");
  c.file("constant/g", std::string("value ") + (D == 2 ? "(0 -9.81)" : "(0 -9.81 0)") + ";\n");
}

template <int D>
void runSteps(Simulation<D>& sim, int steps, double dt) {
  sim.analyse();
  for (int k = 0; k < steps; ++k) {
    sim.step(dt);
    sim.analyse();
  }
}

// The tank of writeCase as the generator describes it; motion 0 when it moves.
template <int D>
WallBox<D> tankBox(bool moving) {
  WallBox<D> w;
  w.name = "tank";
  w.max = Vec<D>::Constant(0.3);
  w.open[3] = true;
  w.layers = 3;
  w.d0 = 0.02;
  w.outerMin = w.min - Vec<D>::Constant(0.06);
  w.outerMax = w.max + Vec<D>::Constant(0.06);
  w.outerMax[1] = 0.3;
  w.motion = moving ? 0 : -1;
  return w;
}

// Sensors reading the fluid on the right wall and on the floor: moving tank against fixed.
template <int D>
void sensorsAgree(Simulation<D>& a, Simulation<D>& b) {
  Vec<D> g = Vec<D>::Zero();
  g[1] = -9.81;
  for (const std::string& centre : {vec<D>(0.3, 0.05, 0.15), vec<D>(0.15, 0, 0.15)}) {
    const Dictionary dict = Dictionary::fromString("type wallPressure; wall tank; centre " + centre +
                                                   "; size 0.013; faceValue fluid;", "test");
    WallPressure<D> sa("a", dict, {tankBox<D>(false)}, g), sb("b", dict, {tankBox<D>(true)}, g);
    const double pa = sa.pressure(a.state()), pb = sb.pressure(b.state());
    BOOST_TEST_MESSAGE(D << "D sensor at " << centre << ": fixed " << pa << " Pa, moving " << pb << " Pa");
    // Round-off, as the pressures above; the rest position's face point is 471 Pa off.
    BOOST_TEST(std::abs(pa - pb) < 1e-9 * 1000 * 9.81 * 0.12);
  }
  // Without faceValue both read the fluid, the moving tank's as the fixed one's.
  const Dictionary byDefault = Dictionary::fromString("type wallPressure; wall tank; centre " +
                                                      vec<D>(0.3, 0.05, 0.15) + "; size 0.013;", "test");
  WallPressure<D> fixedDefault("f", byDefault, {tankBox<D>(false)}, g), movingDefault("m", byDefault, {tankBox<D>(true)}, g);
  BOOST_TEST(fixedDefault.describe().find("face value from the fluid") != std::string::npos);
  BOOST_TEST(movingDefault.describe().find("face value from the fluid") != std::string::npos);
  BOOST_TEST(std::abs(movingDefault.pressure(b.state()) - fixedDefault.pressure(a.state())) < 1e-9 * 1000 * 9.81 * 0.12);
}

// A tank turned by 10 degrees about (0.15, 0) (about z in 3D), its fluid given the pressure
// p_f = rho0 g . (r_f - x_s): the fluid reading carries it to the face point as the tank
// holds it now, so a sensor centred at C (on the right wall at rest) reads rho0 g . (x_C - x_s)
// with x_C = c + R(10 deg)(C - c), whichever rank or layer holds what. The rest face point
// would read rho0 |g| 0.026 m = 259 Pa off.
template <int D>
void sensorOnTurnedTank() {
  test::TempCase c("mwTurned");
  const std::string axis = D == 3 ? " axis (0 0 1);" : "";
  writeCase<D>(c, vec<D>(0, 0, 0), "motion { type rotation; centre " + vec<D>(0.15, 0, 0.15) + ";" + axis +
                                       " angle \"10\"; }", "endTime 1; deltaT 1e-3;\n");
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  Simulation<D> sim(c.dir(), opt);
  Log::get().quiet = false;
  sim.analyse();
  auto& s = sim.state();
  Vec<D> g = Vec<D>::Zero(), xs = Vec<D>::Zero(), centre = Vec<D>::Zero(), C = Vec<D>::Zero();
  g[1] = -9.81;
  xs[1] = 0.2;
  centre[0] = 0.15;
  C[0] = 0.3;
  C[1] = 0.05;
  if (D == 3) centre[2] = C[2] = 0.15;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) s.particles.pressure[i] = s.rho0 * g.dot(s.particles.position[i] - xs);
  const double a = 10 * M_PI / 180;
  Vec<D> xC = centre;
  xC[0] += std::cos(a) * (C[0] - centre[0]) - std::sin(a) * (C[1] - centre[1]);
  xC[1] += std::sin(a) * (C[0] - centre[0]) + std::cos(a) * (C[1] - centre[1]);
  const Dictionary dict = Dictionary::fromString("type wallPressure; wall tank; centre " + vec<D>(0.3, 0.05, 0.15) +
                                                 "; size 0.013;", "test");
  WallPressure<D> sensor("turned", dict, {tankBox<D>(true)}, g);
  const double expected = s.rho0 * g.dot(xC - xs), read = sensor.pressure(s);
  BOOST_TEST_MESSAGE(D << "D turned tank: sensor " << read << " Pa, expected " << expected << " Pa");
  BOOST_TEST(std::abs(read - expected) < 1e-9 * expected);
}

template <int D>
void galileanInvariance(int axis) {
  const double U = 0.8, dt = 1e-3;
  const int steps = 60;
  const std::string control = "endTime 1; deltaT 1e-3;\n";
  test::TempCase fixed("mwFixed"), moving("mwMoving");
  writeCase<D>(fixed, vec<D>(0, 0, 0), "", control);
  const std::string along = "\"0.8*t\"", still = "\"0\"";
  writeCase<D>(moving, axis == 0 ? vec<D>(U, 0, 0) : vec<D>(0, U, 0),
               "motion { type translation; displacement (" + (axis == 0 ? along : still) + " " +
                   (axis == 1 ? along : still) + (D == 3 ? " " + still : std::string()) + "); }",
               control);
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  Simulation<D> a(fixed.dir(), opt), b(moving.dir(), opt);
  Log::get().quiet = false;
  runSteps(a, steps, dt);
  runSteps(b, steps, dt);
  auto pa = a.state().particles, pb = b.state().particles;
  pa.sortById();
  pb.sortById();
  BOOST_TEST_REQUIRE(pa.size() == pb.size());
  Vec<D> shift = Vec<D>::Zero(), Uv = Vec<D>::Zero();
  shift[axis] = U * steps * dt;
  Uv[axis] = U;
  double dx = 0, du = 0, dp = 0, pmax = 0, umax = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    dx = std::max(dx, (pb.position[i] - pa.position[i] - shift).norm());
    du = std::max(du, (pb.velocity[i] - pa.velocity[i] - Uv).norm());
    dp = std::max(dp, std::abs(pb.pressure[i] - pa.pressure[i]));
    pmax = std::max(pmax, std::abs(pa.pressure[i]));
    if (pa.isFluid(i)) umax = std::max(umax, pa.velocity[i].norm());
  }
  BOOST_TEST_MESSAGE(D << "D after " << steps << " steps: |dx| " << dx << " m, |du| " << du << " m/s, |dp| " << dp
                       << " Pa (max p " << pmax << " Pa, fixed tank's own max |u| " << umax << " m/s)");
  // Round-off alone: the coordinates differ by 0.048 m, so each relative position carries
  // an error of a few 1e-17 m; the pressure solve is direct. Measured 1.3e-15 m,
  // 2.4e-14 m/s and 1.4e-12 of max p in 2D and 3D; the bounds are 100 times those.
  BOOST_TEST(dx < 1e-13);
  BOOST_TEST(du < 3e-12);
  BOOST_TEST(dp < 1.4e-10 * pmax);
  if (axis == 1) sensorsAgree(a, b);
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

BOOST_AUTO_TEST_CASE(translating_tank_is_galilean_invariant_2d) { galileanInvariance<2>(0); }
BOOST_AUTO_TEST_CASE(translating_tank_is_galilean_invariant_3d) { galileanInvariance<3>(0); }
BOOST_AUTO_TEST_CASE(rising_tank_is_galilean_invariant_and_its_sensor_moves_with_it_2d) { galileanInvariance<2>(1); }
BOOST_AUTO_TEST_CASE(rising_tank_is_galilean_invariant_and_its_sensor_moves_with_it_3d) { galileanInvariance<3>(1); }

BOOST_AUTO_TEST_CASE(the_fluid_reading_follows_a_turned_wall_2d) { sensorOnTurnedTank<2>(); }
BOOST_AUTO_TEST_CASE(the_fluid_reading_follows_a_turned_wall_3d) { sensorOnTurnedTank<3>(); }

BOOST_AUTO_TEST_CASE(a_motion_is_built_only_when_named) {
  test::TempCase bare("mwBare"), rolled("mwRolled");
  const std::string control = "endTime 1; deltaT 1e-3; adjustTimeStep yes; maxCo 0.2;\n";
  writeCase<2>(bare, "(0 0)", "", control);
  writeCase<2>(rolled, "(0 0)", "motion { type rotation; centre (0.15 0); angle \"4*sin(2*pi*t/1.6)\"; }", control);
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  Simulation<2> a(bare.dir(), opt), b(rolled.dir(), opt);
  Log::get().quiet = false;
  BOOST_TEST(a.state().particles.restPosition.empty());
  BOOST_TEST(a.state().particles.motion.empty());
  BOOST_TEST(a.pipeline().find("moving wall") == std::string::npos);
  BOOST_TEST(b.state().particles.restPosition.size() == b.state().size());
  BOOST_TEST(b.pipeline().find("moving wall 'tank': rotation about (0.15 0)") != std::string::npos);
  // Every wall particle of the tank moves; no fluid particle has a motion.
  long moving = 0, walls = 0;
  for (std::size_t i = 0; i < b.state().size(); ++i) {
    walls += b.state().particles.isWall(i);
    moving += b.state().particles.motion[i] != 0;
    if (b.state().isFluid(i)) BOOST_TEST(b.state().particles.motion[i] == 0);
  }
  BOOST_TEST(moving == walls);
}

BOOST_AUTO_TEST_CASE(restart_continues_a_rolling_tank_bit_for_bit) {
  const std::string control =
      "startFrom latestTime; endTime 0.06; deltaT 1e-3; adjustTimeStep yes; maxCo 0.2; maxDeltaT 4e-3;\n"
      "writeControl adjustableRunTime; writeInterval 0.03; progressInterval 1000;\n";
  const std::string roll = "motion { type rotation; centre (0.15 0); angle \"20*sin(2*pi*t/0.5)\"; }";
  test::TempCase whole("mwWhole"), split("mwSplit");
  writeCase<2>(whole, "(0 0)", roll, control);
  writeCase<2>(split, "(0 0)", roll, control);
  test::runWholeAndRestarted<2>(whole, split, {"0", "0.03"});
  const std::string a = readAll(whole.dir() + "/0.06/particles.vtp");
  BOOST_TEST_REQUIRE(!a.empty());
  BOOST_TEST((a == readAll(split.dir() + "/0.06/particles.vtp")));
}

BOOST_AUTO_TEST_CASE(the_time_step_respects_the_wall_speed) {
  // Water at rest, no gravity, periodic in x; a solid block above it rises at 2 m/s. The
  // wall's Courant limit maxCo h / |U_w| = 0.2 x 0.024 / 2 = 0.0024 s is the only limit, so
  // the run to 0.024 s takes exactly 10 steps (with the limit planted out: 3 steps).
  test::TempCase c("mwWallSpeed");
  c.file("system/controlDict",
         "endTime 0.024; deltaT 0.01; adjustTimeStep yes; maxCo 0.2; maxDeltaT 1;\n"
         "writeControl timeStep; writeInterval 1000; progressInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing 0.02;\nperiodic { min (0 0); max (0.4 1); directions (x); }\n"
         "regions {\n water { type fluid; shape box; min (0 0); max (0.4 0.2); }\n"
         " block { type wall; shape box; solid yes; min (0.1 0.4); max (0.3 0.5); layers 2;\n"
         "   motion { type translation; displacement (\"0\" \"2*t\"); } }\n}\n");
  c.file("system/sphSchemes", "derivatives SPH2;\nfreeSurface { enabled off; }\n");
  c.file("system/sphSolution", "pressure { solver UMFPACK; }\n");
  c.file("constant/physicalProperties", "rho 1000;\n");
  const auto sim = test::runQuietly<2>(c);
  BOOST_TEST(sim->state().step == 10);
  BOOST_TEST(sim->state().time == 0.024, boost::test_tools::tolerance(1e-12));
}
