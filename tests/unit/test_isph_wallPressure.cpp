// The wallPressure sensor (libsph/functionObjects/WallPressure.hpp, docs/postprocessing.md):
//  - still water, one projection step (the wall rows then hold the exact hydrostatic
//    pressure, test_isph_hydrostatic.cpp): sensors on the side walls and the floor, of
//    sizes below and above d0, centred anywhere on the lattice, read rho g (H - y_c) to
//    the hydrostatic test's tolerance, in 2D and 3D (segment, square, disc); H is the
//    level the fluid's own pressure gives (y + p/(rho g));
//  - the same on the faces of a solid wall box (an obstacle, `solid yes`) standing on the
//    floor, whose first two layers lie inside it, of sizes not a whole number of spacings;
//  - every one of those sensors both with `faceValue wallLayers` and with `faceValue fluid`
//    (the fluid's pressure carried hydrostatically to the face from the first wall layer's
//    fluid neighbours), and without faceValue a sensor reads the fluid;
//  - after the particles are reordered the reading is the same;
//  - a sensor inside one interval between two wall columns reads the linear
//    interpolation of the columns' face values at its midpoint; the segment weights equal
//    a brute-force integral of the piecewise linear interpolant;
//  - the low-pass filter's step and sinusoid responses equal the first-order filter's
//    exact answers; force and impulse of a constant pressure are p A and p A t.
// A sensor reading the nearest wall particle, or the first layer without the d0/2
// extrapolation, fails the first and third groups.
#define BOOST_TEST_MODULE isph_wallPressure
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "functionObjects/LowPassFilter.hpp"
#include "functionObjects/WallPressure.hpp"
#include "isph/Simulation.hpp"
#include <cmath>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>

using namespace shizuku;

namespace {
constexpr double kRho = 1000, kG = 9.81, kD0 = 0.02;
constexpr double kPressureTolerance = 1e-9;  // relative to rho g H, as test_isph_hydrostatic.cpp

// A tank `width` wide (x, and z in 3D), `height` high, open at the top, water `depth` deep,
// and `extra` regions.
template <int D>
void writeTank(test::TempCase& c, double width, double height, double depth, const std::string& extra = "") {
  auto vec = [](double x, double y, double z) {
    return "(" + std::to_string(x) + " " + std::to_string(y) + (D == 3 ? " " + std::to_string(z) : "") + ")";
  };
  c.file("system/controlDict", "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1000;\n");
  c.file("system/particlesDict", "spacing 0.02;\nregions {\n water { type fluid; shape box; min " + vec(0, 0, 0) +
                                     "; max " + vec(width, depth, width) + "; }\n tank { type wall; shape box; min " +
                                     vec(0, 0, 0) + "; max " + vec(width, height, width) +
                                     "; layers 3; open (top); }\n" + extra + "}\n");
  c.file("system/sphSolution", "pressure { solver BiCGSTAB; tolerance 1e-12; }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  c.file("constant/g", std::string("value ") + (D == 2 ? "(0 -9.81)" : "(0 -9.81 0)") + ";\n");
}

template <int D>
WallBox<D> tankBox(double width, double height) {
  WallBox<D> w;
  w.name = "tank";
  w.max = Vec<D>::Constant(width);
  w.max[1] = height;
  w.open[3] = true;
  w.layers = 3;
  w.d0 = kD0;
  w.outerMin = w.min - Vec<D>::Constant(3 * kD0);
  w.outerMax = w.max + Vec<D>::Constant(3 * kD0);
  w.outerMax[1] = height;
  return w;
}

template <int D>
std::unique_ptr<WallPressure<D>> sensor(const std::string& entries, const WallBox<D>& wall) {
  static std::vector<Dictionary> keep;  // the objects keep pointers into their dictionaries
  keep.reserve(100);
  keep.push_back(Dictionary::fromString("type wallPressure; wall " + wall.name + "; " + entries, "test"));
  Vec<D> g = Vec<D>::Zero();
  g[1] = -kG;
  return std::make_unique<WallPressure<D>>("sensor", keep.back(), std::vector<WallBox<D>>{wall}, g);
}

// The level at which the fluid's pressure is zero: y + p/(rho g), averaged over the fluid.
template <int D>
double level(const FlowState<D>& s) {
  double sum = 0, n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.isFluid(i)) {
      sum += s.particles.position[i].y() + s.particles.pressure[i] / (kRho * kG);
      n += 1;
    }
  return sum / n;
}

// Reverse the particle order (every field), as a cell reordering would change it.
template <int D>
void reverseOrder(FlowState<D>& s) {
  auto& P = s.particles;
  std::reverse(P.position.begin(), P.position.end());
  P.forEachField([](const char*, auto& v) { std::reverse(v.begin(), v.end()); });
  s.refreshTypeMasks();
}

struct Sensor {
  std::string entries;
  double y;  // height of the sensor's centre
};

template <int D>
void checkHydrostatic(double width, double height, double depth, const std::vector<Sensor>& sensors,
                      const std::string& extra = "", const std::optional<WallBox<D>>& sensed = std::nullopt) {
  test::TempCase c("wallPressure");
  writeTank<D>(c, width, height, depth, extra);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  sim.analyse();
  sim.step(1e-3);
  const double H = level(sim.state());
  BOOST_TEST_MESSAGE(D << "D tank: fluid level H = " << H);
  const WallBox<D> wall = sensed ? *sensed : tankBox<D>(width, height);
  for (const std::string faceValue : {" faceValue wallLayers;", " faceValue fluid;"})
    for (const auto& sn : sensors) {
      auto w = sensor<D>(sn.entries + faceValue, wall);
      const double p = w->pressure(sim.state()), exact = kRho * kG * (H - sn.y);
      BOOST_TEST_CONTEXT(D << "D sensor " << sn.entries << faceValue << ": p " << p << " exact " << exact) {
        BOOST_TEST(std::abs(p - exact) <= kPressureTolerance * kRho * kG * H);
      }
    }
  // Without faceValue a sensor reads the fluid (the default).
  BOOST_TEST(sensor<D>(sensors.front().entries, wall)->describe().find("face value from the fluid") != std::string::npos);
  // Reordered particles: the sensor finds its wall particles again, same reading.
  auto w = sensor<D>(sensors.front().entries + " faceValue wallLayers;", wall);
  const double before = w->pressure(sim.state());
  reverseOrder(sim.state());
  BOOST_TEST(w->pressure(sim.state()) == before);
}

// A solid wall box named "block" from lo to hi, 3 layers, as the generator describes it.
template <int D>
WallBox<D> blockBox(const Vec<D>& lo, const Vec<D>& hi) {
  WallBox<D> w;
  w.name = "block";
  w.min = w.outerMin = lo;
  w.max = w.outerMax = hi;
  w.layers = 3;
  w.d0 = kD0;
  w.solid = true;
  return w;
}

std::string text(const Vec<2>& x) { return "(" + std::to_string(x[0]) + " " + std::to_string(x[1]) + ")"; }
std::string text(const Vec<3>& x) {
  return "(" + std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + ")";
}

template <int D>
std::string blockRegion(const Vec<D>& lo, const Vec<D>& hi) {
  return " block { type wall; shape box; min " + text(lo) + "; max " + text(hi) + "; layers 3; solid yes; }\n";
}
}  // namespace

BOOST_AUTO_TEST_CASE(hydrostatic_tank_2d) {
  // Tank 0.4 x 0.5, water 0.3 deep, d0 = 0.02: right wall, left wall and floor, centres
  // on, between and off the columns (y = 0.01 + k d0), sizes 0.21 d0 to 2.5 d0, one centre
  // given 0.009 m inside the fluid (projected onto the face).
  std::vector<Sensor> sensors;
  for (double y : {0.016, 0.05, 0.1007, 0.137, 0.2, 0.25})
    for (double size : {0.0042, 0.013, 0.03, 0.05}) {
      if (y - size / 2 < 0) continue;
      sensors.push_back({"centre (0.4 " + std::to_string(y) + "); size " + std::to_string(size) + ";", y});
      sensors.push_back({"centre (0.009 " + std::to_string(y) + "); size " + std::to_string(size) + ";", y});
    }
  for (double x : {0.003, 0.1, 0.2031, 0.39})
    for (double size : {0.0042, 0.006}) sensors.push_back({"centre (" + std::to_string(x) + " 0); size " + std::to_string(size) + ";", 0});
  checkHydrostatic<2>(0.4, 0.5, 0.3, sensors);
}

BOOST_AUTO_TEST_CASE(hydrostatic_tank_3d) {
  // Tank 0.2 x 0.3 x 0.2, water 0.2 deep: squares and discs on the side faces x = 0.2,
  // z = 0 and on the floor.
  std::vector<Sensor> sensors;
  for (double y : {0.03, 0.0713, 0.12})
    for (const std::string shape : {"square", "disc"})
      for (double size : {0.0042, 0.013, 0.045}) {
        const std::string sz = "; size " + std::to_string(size) + "; shape " + shape + ";";
        sensors.push_back({"centre (0.2 " + std::to_string(y) + " 0.093)" + sz, y});
        sensors.push_back({"centre (0.1311 " + std::to_string(y) + " 0)" + sz, y});
      }
  for (const std::string shape : {"square", "disc"})
    sensors.push_back({"centre (0.1 0 0.0517); size 0.0042; shape " + shape + ";", 0});
  sensors.push_back({"centre (0.031 0 0.17); size 0.03; shape disc;", 0});
  checkHydrostatic<3>(0.2, 0.3, 0.2, sensors);
}

BOOST_AUTO_TEST_CASE(hydrostatic_obstacle_2d) {
  // A block 0.12 x 0.08 on the floor of a 0.4 x 0.5 tank, water 0.3 deep (faces on the
  // fluid lattice's faces, as the tank's: the still water is then exact after one step):
  // sensors on its top and both sides.
  const Vec<2> lo(0.14, 0), hi(0.26, 0.08);
  std::vector<Sensor> sensors;
  for (double x : {0.15, 0.1931, 0.24})
    for (double size : {0.0042, 0.017}) sensors.push_back({"centre (" + std::to_string(x) + " 0.08); size " + std::to_string(size) + ";", 0.08});
  for (double y : {0.021, 0.05, 0.07})
    for (double x : {0.14, 0.26}) sensors.push_back({"centre (" + std::to_string(x) + " " + std::to_string(y) + "); size 0.013;", y});
  checkHydrostatic<2>(0.4, 0.5, 0.3, sensors, blockRegion<2>(lo, hi), blockBox<2>(lo, hi));
}

BOOST_AUTO_TEST_CASE(hydrostatic_obstacle_3d) {
  // A block 0.08 x 0.1 x 0.06 on the floor of a 0.2 x 0.3 x 0.2 tank, water 0.2 deep:
  // squares and discs on its top, its -x face and its +z face.
  const Vec<3> lo(0.06, 0, 0.06), hi(0.14, 0.1, 0.12);
  std::vector<Sensor> sensors;
  for (const std::string shape : {"square", "disc"}) {
    const std::string sz = "; size 0.013; shape " + shape + ";";
    sensors.push_back({"centre (0.1 0.1 0.1)" + sz, 0.1});
    sensors.push_back({"centre (0.06 0.04 0.091)" + sz, 0.04});
    sensors.push_back({"centre (0.0811 0.0713 0.12)" + sz, 0.0713});
  }
  checkHydrostatic<3>(0.2, 0.3, 0.2, sensors, blockRegion<3>(lo, hi), blockBox<3>(lo, hi));
}

BOOST_AUTO_TEST_CASE(sensor_between_two_columns_reads_the_linear_interpolation) {
  // Wall pressures set to a nonlinear g(y) on the right wall (the face value of a column
  // is then g(y_k)): a sensor of 0.2 d0 inside [y_k, y_k+1] reads the linear interpolation
  // at its midpoint, (1 - t) g(y_k) + t g(y_k+1), not the nearest column's value.
  test::TempCase c("wallPressureStraddle");
  writeTank<2>(c, 0.4, 0.5, 0.3);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<2> sim(c.dir(), opt);
  auto& P = sim.state().particles;
  const auto g = [](double y) { return 1e4 * std::sin(20 * y) + 3e5 * y * y; };
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.isWall(i)) P.pressure[i] = g(P.position[i].y());
  const WallBox<2> wall = tankBox<2>(0.4, 0.5);
  for (double t : {0.1, 0.25, 0.5, 0.77, 0.9}) {
    const double yk = 0.11, mid = yk + t * kD0;
    auto w = sensor<2>("centre (0.4 " + std::to_string(mid) + "); size 0.004; faceValue wallLayers;", wall);
    const double tt = (std::stod(std::to_string(mid)) - yk) / kD0;
    const double exact = (1 - tt) * g(yk) + tt * g(yk + kD0);
    BOOST_TEST_CONTEXT("t = " << t) { BOOST_TEST(std::abs(w->pressure(sim.state()) - exact) < 1e-9 * std::abs(exact)); }
  }
}

BOOST_AUTO_TEST_CASE(segment_weights_integrate_the_interpolant) {
  // Against a midpoint-rule integral of the piecewise linear interpolant (constant beyond
  // the end nodes, or with linearEnds the end intervals' lines continued) with 2e5 cells,
  // on uneven nodes, intervals inside, across and beyond.
  const std::vector<double> x = {-0.03, -0.01, 0.01, 0.026, 0.042, 0.058, 0.074, 0.09, 0.11};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> val(-1, 1);
  std::vector<double> f(x.size());
  for (auto& v : f) v = val(rng);
  for (bool linearEnds : {false, true}) {
    auto interp = [&](double s) {
      if (!linearEnds && s <= x.front()) return f.front();
      if (!linearEnds && s >= x.back()) return f.back();
      std::size_t k = std::size_t(std::upper_bound(x.begin(), x.end(), s) - x.begin());
      k = std::min(std::max(k, std::size_t(1)), x.size() - 1) - 1;
      const double t = (s - x[k]) / (x[k + 1] - x[k]);
      return (1 - t) * f[k] + t * f[k + 1];
    };
    for (auto [a, b] : std::vector<std::pair<double, double>>{{0.0, 0.005}, {0.012, 0.07}, {-0.05, 0.2}, {0.1, 0.13},
                                                               {-0.04, -0.02}, {0.03, 0.03}, {0.12, 0.12}}) {
      double weighted = 0, total = 0;
      for (const auto& [k, w] : WallPressure<2>::segmentWeights(x, a, b, linearEnds)) {
        weighted += w * f[std::size_t(k)];
        total += w;
      }
      double brute = 0;
      const int n = 200000;
      if (b > a) {
        for (int i = 0; i < n; ++i) brute += interp(a + (i + 0.5) * (b - a) / n) / n;
      } else {
        brute = interp(a);
      }
      BOOST_TEST_CONTEXT("[" << a << ", " << b << "] linearEnds " << linearEnds) {
        BOOST_TEST(std::abs(total - 1) < 1e-14);
        BOOST_TEST(std::abs(weighted - brute) < 1e-9);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(low_pass_step_response) {
  // The input 0 at t = 0 and 1 from the first sample on (a ramp over the first interval
  // dt1 for a first-order hold): y(t) = 1 - (tau/dt1)(exp(-(t - dt1)/tau) - exp(-t/tau)),
  // at uneven steps.
  const double fc = 50, tau = 1 / (2 * M_PI * fc);
  LowPassFilter f(fc);
  BOOST_TEST(f.update(0, 0) == 0);
  const double dt1 = 3e-4;
  double t = 0, worst = 0;
  for (int n = 1; n <= 400; ++n) {
    t += n == 1 ? dt1 : (n % 3 == 0 ? 1e-4 : 2.5e-4);
    const double y = f.update(t, 1), exact = 1 - tau / dt1 * (std::exp(-(t - dt1) / tau) - std::exp(-t / tau));
    worst = std::max(worst, std::abs(y - exact));
  }
  BOOST_TEST_MESSAGE("step response: worst error " << worst);
  BOOST_TEST(worst < 1e-12);
  BOOST_TEST(f.update(t, 5) == f.output());  // a second sample at the same time changes nothing
}

BOOST_AUTO_TEST_CASE(low_pass_sinusoid_response) {
  // x = sin(w t) from rest: y = (sin wt - w tau cos wt + w tau exp(-t/tau)) / (1 + (w tau)^2),
  // so the steady gain is 1/sqrt(1 + (w tau)^2) (1/sqrt(2) at fc) and the phase -atan(w tau).
  // Sampled at w dt = 1e-3 the first-order hold differs from the continuous input by
  // O((w dt)^2).
  const double fc = 50, tau = 1 / (2 * M_PI * fc);
  for (double ratio : {0.3, 1.0, 3.0}) {
    const double w = ratio / tau, dt = 1e-3 / w;
    LowPassFilter f(fc);
    f.update(0, 0);
    double worst = 0, amplitude = 0;
    const int steps = int(10 * 2 * M_PI / (w * dt));
    for (int n = 1; n <= steps; ++n) {
      const double t = n * dt, y = f.update(t, std::sin(w * t));
      const double exact = (std::sin(w * t) - ratio * std::cos(w * t) + ratio * std::exp(-t / tau)) / (1 + ratio * ratio);
      worst = std::max(worst, std::abs(y - exact));
      if (n > steps / 2) amplitude = std::max(amplitude, std::abs(y));
    }
    BOOST_TEST_MESSAGE("w tau = " << ratio << ": worst error " << worst << ", gain " << amplitude);
    BOOST_TEST(worst < 1e-6);
    BOOST_TEST(std::abs(amplitude - 1 / std::sqrt(1 + ratio * ratio)) < 1e-5);
  }
}

namespace {
template <int D>
void checkForceAndImpulse(const std::string& entries, double area) {
  test::TempCase c("wallPressureForce");
  writeTank<D>(c, 0.2, 0.3, 0.1);
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  auto& s = sim.state();
  const double p0 = 1234.5;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.particles.isWall(i)) s.particles.pressure[i] = p0;
  auto w = sensor<D>(entries + " faceValue wallLayers; filter { type lowPass; cutoff 20 [Hz]; }", tankBox<D>(0.2, 0.3));
  BOOST_TEST(w->area() == area, boost::test_tools::tolerance(1e-14));
  RunInfo info;
  info.caseDir = c.dir();
  info.startTimeName = "0";
  s.time = 0.5;
  w->start(s, info);
  for (int n = 0; n <= 50; ++n) {
    if (n > 0) s.time += n % 2 ? 1e-3 : 3.7e-4;
    w->execute(s, info);
  }
  const double T = s.time - 0.5;
  BOOST_TEST(w->force() == p0 * area, boost::test_tools::tolerance(1e-13));
  BOOST_TEST(w->impulse() == p0 * area * T, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(w->filtered() == p0, boost::test_tools::tolerance(1e-13));
  w->end();
  // The file: a header and 51 rows, the last one time, p, p_lowPass, force, impulse.
  std::ifstream in(c.dir() + "/postProcessing/sensor/0/wallPressure.dat");
  std::string line, last;
  int rows = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') {
      ++rows;
      last = line;
    }
  BOOST_TEST(rows == 51);
  std::istringstream row(last);
  double t, p, pf, F, I;
  row >> t >> p >> pf >> F >> I;
  BOOST_TEST(I == p0 * area * T, boost::test_tools::tolerance(1e-9));
}
}  // namespace

BOOST_AUTO_TEST_CASE(force_and_impulse_of_a_constant_pressure) {
  checkForceAndImpulse<2>("centre (0.2 0.05); size 0.013;", 0.013);
  checkForceAndImpulse<3>("centre (0.2 0.05 0.1); size 0.013;", 0.013 * 0.013);
  checkForceAndImpulse<3>("centre (0.2 0.05 0.1); size 0.013; shape disc;", M_PI / 4 * 0.013 * 0.013);
}

BOOST_AUTO_TEST_CASE(input_errors_name_the_keyword) {
  const WallBox<2> wall = tankBox<2>(0.4, 0.5);
  auto message = [&](const std::string& text) {
    try {
      const Dictionary d = Dictionary::fromString(text, "controlDict");
      WallPressure<2> w("s", d, {wall});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A solid box one particle thick (0.015 < d0 across x): no second layer behind its face.
  const WallBox<2> thin = blockBox<2>(Vec<2>(0.2, 0), Vec<2>(0.215, 0.1));
  const Dictionary thinDict = Dictionary::fromString("type wallPressure; wall block; centre (0.2 0.05); size 0.004;", "c");
  try {
    WallPressure<2> w("s", thinDict, {thin});
    BOOST_TEST(false);
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("one particle thick") != std::string::npos);
  }
  const std::string unknown = message("type wallPressure; wall tnak; centre (0.4 0.1); size 0.004;");
  BOOST_TEST(unknown.find("keyword 'wall'") != std::string::npos);
  BOOST_TEST(unknown.find("did you mean 'tank'") != std::string::npos);
  const std::string off = message("type wallPressure; wall tank; centre (0.38 0.1); size 0.004;");
  BOOST_TEST(off.find("keyword 'centre'") != std::string::npos);
  BOOST_TEST(off.find("not on a face of wall 'tank'") != std::string::npos);
  BOOST_TEST(message("type wallPressure; wall tank; centre (0.2 0.5); size 0.004;").find("keyword 'centre'") !=
             std::string::npos);  // the open top is no face
  BOOST_TEST(message("type wallPressure; wall tank; centre (0.4 0.1); size 0;").find("keyword 'size'") !=
             std::string::npos);
  BOOST_TEST(message("type wallPressure; wall tank; centre (0.4 0.01); size 0.03;").find("reaches beyond the face") !=
             std::string::npos);
  BOOST_TEST(message("type wallPressure; wall tank; centre (0.4 0.1); size 0.004; shape disc;").find("keyword 'shape'") !=
             std::string::npos);
  BOOST_TEST(message("type wallPressure; wall tank; centre (0.4 0.1); size 0.004; filter { type lowPass; cutoff -1; }")
                 .find("keyword 'cutoff'") != std::string::npos);
}
