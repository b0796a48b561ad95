// Still water in a tank (docs/method.md 4.2, 4.4): with u* = g dt everywhere and the
// dummy walls showing the Shepard fluid velocity, the linear hydrostatic field
// p = rho g (H - y), H the nominal depth (the fluid box's top, half a spacing above the top
// particle row), satisfies every SPH(2) Laplacian row, every free-surface row of eq. 6b and
// every Adami wall row exactly, so the first projection step must return it to round-off
// and leave u = 0 to round-off. Any deviation is a bug in the PPE assembly, the wall rows,
// the free-surface classes, normals or rows, or the corrector. Once shifting has moved
// the particles the error is no longer zero and falls at second order in d0.
#define BOOST_TEST_MODULE isph_hydrostatic
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "isph/Simulation.hpp"

using namespace shizuku;

namespace {
// A tank `width` wide (x, and z in 3D) and `height` high, open at the top, holding water
// `depth` deep over its whole width; gravity along -y; d0 = 2 cm.
struct Tank {
  double width, height, depth;
};

template <int D>
void writeTank(test::TempCase& c, const std::string& solver, const std::string& schemes, const Tank& t,
               double d0 = 0.02) {
  auto vec = [](double x, double y, double z) {
    return "(" + std::to_string(x) + " " + std::to_string(y) + (D == 3 ? " " + std::to_string(z) : "") + ")";
  };
  c.file("system/controlDict", "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing " + std::to_string(d0) + ";\nregions {\n water { type fluid; shape box; min " + vec(0, 0, 0) + "; max " +
             vec(t.width, t.depth, t.width) + "; }\n tank { type wall; shape box; min " + vec(0, 0, 0) + "; max " +
             vec(t.width, t.height, t.width) + "; layers 3; open (top); }\n}\n");
  c.file("system/sphSchemes", schemes);
  c.file("system/sphSolution", "pressure { solver " + solver + "; tolerance 1e-12; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  c.file("constant/g", std::string("value ") + (D == 2 ? "(0 -9.81)" : "(0 -9.81 0)") + ";\n");
}

// The tank of the original test (whole numbers of spacings: 20 x 25) and tanks whose
// walls and water are not a whole number of spacings: across (residuals 0.01 .. 0.99 d0)
// and in height (0.49 d0); in 3D in height (0.25 d0) and across (0.01, 0.1, 0.4 and 0.9 d0
// in x and z). The wall faces then have their own lattices (WallLattice.hpp) and the water its own spacing
// round(L/d0) per axis (fluidSpacing), so its outer columns sit about d0/2 from both side
// walls. Filled from the corner at d0 instead, a strip as wide as the residual stays empty
// at the far wall: from about 0.3 d0 the column next to it is classed free surface and the
// error is 0.07 .. 0.97 (2D), 0.95 (3D, 0.9 d0). In 3D a residual across of 0.01 .. 0.4
// d0 compresses the side walls along their faces (L/ceil(L/d0), 0.91 d0 for 10.01
// spacings); the top corner particles next to two such walls are still classed free by
// the surface indicator (docs/method.md 5.1). Planted: with divR against 1.5 times the 2D
// thresholds instead, those corners read as interior and the 0.2002 and 0.202 m tanks
// have an error of 2.9e-2.
const Tank kWhole2{0.4, 0.5, 0.3};
const std::vector<Tank> kNonWhole2 = {{0.4002, 0.505, 0.3}, {0.402, 0.505, 0.3}, {0.405, 0.505, 0.3},
                                      {0.4, 0.5098, 0.3},   {0.406, 0.505, 0.3}, {0.41, 0.505, 0.3},
                                      {0.418, 0.505, 0.3},  {0.4198, 0.505, 0.3}};
const Tank kWhole3{0.2, 0.3, 0.2};
const std::vector<Tank> kNonWhole3 = {{0.2, 0.305, 0.2},    {0.218, 0.305, 0.2}, {0.2002, 0.305, 0.2},
                                      {0.202, 0.305, 0.2},  {0.208, 0.305, 0.2}};

// Highest fluid particle (the free-surface row).
template <int D>
double topOfWater(const FlowState<D>& s) {
  double yTop = -1;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) yTop = std::max(yTop, s.particles.position[i].y());
  return yTop;
}

// One projection step from rest: the relative error of p against rho g (y_top - y), and
// the largest speed. The top row (and only it) must be classed free surface.
template <int D>
std::pair<double, double> firstStepError(const std::string& solver, const Tank& t) {
  test::TempCase c("hydrostatic");
  writeTank<D>(c, solver, "derivatives SPH2;\n", t);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  sim.analyse();
  const auto& s = sim.state();
  const double yTop = topOfWater(s), H = t.depth;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.isFluid(i)) continue;
    const bool top = std::abs(s.particles.position[i].y() - yTop) < 1e-9;
    BOOST_TEST_CONTEXT("particle " << i << " at " << s.particles.position[i].transpose()) {
      BOOST_TEST((s.surfaceClass(i) == SurfaceClass::free) == top);
    }
  }
  sim.step(1e-3);
  const double rho = 1000, g = 9.81;
  double maxErr = 0, maxU = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.isFluid(i)) continue;
    const double exact = rho * g * (H - s.particles.position[i].y());
    maxErr = std::max(maxErr, std::abs(s.particles.pressure[i] - exact));
    maxU = std::max(maxU, s.particles.velocity[i].norm());
  }
  return {maxErr / (rho * g * H), maxU};
}

// Largest speed after 200 steps of 2 ms without shifting.
template <int D>
double speedAfterStill(const Tank& t, int steps) {
  test::TempCase c("still");
  writeTank<D>(c, "BiCGSTAB", "derivatives SPH2;\n", t);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  sim.analyse();
  for (int k = 0; k < steps; ++k) {
    sim.step(2e-3);
    sim.analyse();
  }
  double maxU = 0;
  const auto& s = sim.state();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) maxU = std::max(maxU, s.particles.velocity[i].norm());
  return maxU;
}

// Round-off: the relative pressure error is ~1e-13 with every backend; 1e-9 leaves
// room for the iterative tolerance (1e-12) times the condition number.
constexpr double kPressureTolerance = 1e-9;
constexpr double kSpeedTolerance = 1e-9 * 9.81 * 1e-3 * 1e3;
}  // namespace

BOOST_AUTO_TEST_CASE(first_step_returns_linear_hydrostatic_pressure) {
  for (const std::string solver : {"BiCGSTAB", "UMFPACK", "KLU", "SparseLU"}) {
    const auto [err, u] = firstStepError<2>(solver, kWhole2);
    BOOST_TEST_MESSAGE(solver << ": max pressure error " << err << " (relative), max |u| " << u);
    BOOST_TEST(err < kPressureTolerance);
    BOOST_TEST(u < kSpeedTolerance);
  }
}

BOOST_AUTO_TEST_CASE(first_step_exact_in_tanks_of_any_size_2d_and_3d) {
  for (const Tank& t : kNonWhole2) {
    const auto [err, u] = firstStepError<2>("BiCGSTAB", t);
    BOOST_TEST_MESSAGE("2D tank " << t.width << " x " << t.height << ": max pressure error " << err << ", max |u| " << u);
    BOOST_TEST(err < kPressureTolerance);
    BOOST_TEST(u < kSpeedTolerance);
  }
  std::vector<Tank> tanks3{kWhole3};
  tanks3.insert(tanks3.end(), kNonWhole3.begin(), kNonWhole3.end());
  for (const Tank& t : tanks3) {
    const auto [err, u] = firstStepError<3>("BiCGSTAB", t);
    BOOST_TEST_MESSAGE("3D tank " << t.width << " x " << t.height << ": max pressure error " << err << ", max |u| " << u);
    BOOST_TEST(err < kPressureTolerance);
    BOOST_TEST(u < kSpeedTolerance);
  }
}

BOOST_AUTO_TEST_CASE(still_water_stays_still) {
  // Without shifting a perfect lattice stays a lattice: round-off only, in a tank of
  // whole spacings and in one of 20.25 x 25.25 spacings.
  for (const Tank& t : {kWhole2, kNonWhole2[2]}) {
    const double maxU = speedAfterStill<2>(t, 200);
    BOOST_TEST_MESSAGE("tank " << t.width << " x " << t.height << ": max |u| after 0.4 s: " << maxU);
    BOOST_TEST(maxU < 1e-10);
  }
}

namespace {
const std::string kTutorialSchemes =
    "derivatives SPH2;\nshifting { distribution { type OPS; C 0.2; Rp 0.2; np 4; } volumeCorrection { C 0.1; } "
    "maxShift 0.1; }\n";

// Largest |p - rho g (H - y)| over the fluid, relative to rho g H, with H the nominal depth
// (the fluid box's top), after `steps` steps of dt.
template <int D>
double nominalDepthError(const Tank& t, double d0, const std::string& schemes, int steps, double dt,
                         const std::string& extra = "") {
  test::TempCase c("surfaceCondition");
  writeTank<D>(c, "BiCGSTAB", schemes + extra, t, d0);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  sim.analyse();
  for (int k = 0; k < steps; ++k) {
    sim.step(dt);
    sim.analyse();
  }
  const auto& s = sim.state();
  const double rho = 1000, g = 9.81, H = t.depth;
  double maxErr = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.isFluid(i)) continue;
    const Vec<D>& x = s.particles.position[i];
    maxErr = std::max(maxErr, std::abs(s.particles.pressure[i] - rho * g * (H - x.y())));
  }
  return maxErr / (rho * g * H);
}
}  // namespace

// Issue 18: p = 0 on the surface (eq. 6b), 15 particles deep at d0 = 2 cm, after 0.2 s of
// the tutorial's shifting. A tank of whole spacings is a fixed point of the step: the shift of
// every particle is zero on the lattice, also beside the side walls that rise above the water
// (docs/method.md 6, "beside a dry wall"), so the pressure stays rho g (H - y) to the solver's
// tolerance: measured 9.5e-14 and 6.5e-11 of rho g H at d0 = 2 and 1 cm (second order holds
// trivially). At 3 cm the tank is 13.3 spacings wide, the water takes its own spacing across
// (docs/boundaries.md) and its lattice settles while the test runs: 1.9e-5, within issue 18's
// 0.5 %. Planted: with the detector's normal and every wall particle in the top corners' shift
// (the frame before the dry-wall treatment) the corners were lifted and the error was 8.1e-4,
// 1.4e-4, 1.3e-4 (first order at the corners); p = 0 on the particles (pressureCondition
// particles) is rho g d0/2 low everywhere.
BOOST_AUTO_TEST_CASE(still_tank_stays_exact_under_shifting_2d) {
  const Tank t{0.4, 0.5, 0.3};
  for (double d0 : {0.03, 0.02, 0.01}) {
    const double err = nominalDepthError<2>(t, d0, kTutorialSchemes, 100, 2e-3);
    BOOST_TEST_MESSAGE("2D d0 = " << d0 << ": max |p - rho g (H - y)| / (rho g H) = " << err);
    BOOST_TEST(err <= (d0 == 0.03 ? 5e-3 : kPressureTolerance));
  }
}

// In 3D the first step at three resolutions (0.12 m wide, 4, 6, 8 spacings; 3D tanks of whole and non-whole
// spacings above): exact to round-off against rho g (H - y), H nominal. With p = 0 on the
// particles the error is rho g d0/2 (d0/(2H) relative: 5, 3.3, 2.5 %), which is what each
// check below would see.
BOOST_AUTO_TEST_CASE(still_tank_first_step_three_resolutions_3d_and_the_old_condition) {
  const Tank t{0.12, 0.4, 0.3};
  for (double d0 : {0.03, 0.02, 0.015}) {
    const double err = nominalDepthError<3>(t, d0, "derivatives SPH2;\n", 1, 1e-3);
    BOOST_TEST_MESSAGE("3D d0 = " << d0 << ", first step: " << err);
    BOOST_TEST(err < kPressureTolerance);
  }
  // The condition of old, kept as an option: half a spacing low, first order in d0.
  for (double d0 : {0.03, 0.02}) {
    const double err = nominalDepthError<2>({0.4, 0.5, 0.3}, d0, "derivatives SPH2;\n", 1, 1e-3,
                                            "freeSurface { pressureCondition particles; }\n");
    BOOST_TEST_MESSAGE("2D d0 = " << d0 << ", p = 0 on the particles: " << err);
    BOOST_TEST(err == d0 / (2 * 0.3), boost::test_tools::tolerance(1e-6));
  }
}

// 3D after 0.1 s of the tutorial's shifting, a tank of whole spacings (0.12 m wide, 0.36 m
// high, 0.3 m deep: 4, 6, 8 spacings across, 10, 15, 20 deep): a fixed point as in 2D,
// measured 9.0e-14, 7.5e-14, 6.5e-14 of rho g H at d0 = 3, 2, 1.5 cm. Planted: with the frame
// before the dry-wall treatment the four top corner particles rose 0.01 d0 and the error was
// 9.8e-4, 5.9e-4, 3.6e-4 (first order).
BOOST_AUTO_TEST_CASE(still_tank_stays_exact_under_shifting_3d) {
  const Tank t{0.12, 0.36, 0.3};
  for (double d0 : {0.03, 0.02, 0.015}) {
    const double err = nominalDepthError<3>(t, d0, kTutorialSchemes, 50, 2e-3);
    BOOST_TEST_MESSAGE("3D d0 = " << d0 << " after 0.1 s: " << err);
    BOOST_TEST(err <= kPressureTolerance);
  }
}
