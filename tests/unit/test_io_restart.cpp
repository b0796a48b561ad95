// startFrom latestTime continues exactly as an uninterrupted run would
// (docs/design.md 1.3), bit for bit. A toy deterministic time loop stands in for
// the solver: it uses every field a ParticleSet carries (positions,
// velocities, pressure, density, shift, classes, ids, mass, rho0, spacing) and
// the whole TimeState (time, step, dt adapted from max |U| and limited by the
// previous dt). Run A goes to the end; run B writes time directories, stops
// (as a crash would) between writes, restarts from the latest one and goes to
// the end. Both final states and all their writes must match byte for byte.
#define BOOST_TEST_MODULE io_restart
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "test_io_helpers.hpp"
#include <fstream>
#include <sstream>

using namespace shizuku;
using namespace shizuku::iotest;

namespace {

// One step of a nonlinear, chaotic toy dynamics (a tiny error grows fast).
template <int D>
void step(ParticleSet<D>& p, TimeState& s) {
  double umax = 0;
  for (auto& u : p.velocity) umax = std::max(umax, u.norm());
  double dt = std::min(1.2 * s.deltaT0, 0.05 * p.spacing / (umax + 1e-12));
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec<D> f = -p.position[i] * (1 + p.pressure[i] * p.pressure[i]);
    p.velocity[i] += dt * f / (p.mass / p.rho0);
    p.position[i] += dt * p.velocity[i] + p.shift[i];
    p.pressure[i] = std::sin(p.pressure[i] + p.position[i].squaredNorm() + double(p.id[i]) * 1e-3);
    p.density[i] = p.rho0 * (1 + 0.01 * std::cos(p.density[i] + p.velocity[i][0]));
    p.shift[i] = 1e-3 * dt * p.velocity[i];
    p.surface[i] = std::uint8_t(p.pressure[i] > 0.5 ? 2 : 0);
  }
  s.time += dt;
  s.deltaT0 = dt;
  s.deltaT = dt;
  ++s.step;
}

template <int D>
ParticleSet<D> initial() {
  auto p = randomSet<D>(64, true, 5);
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < D; ++k) {
      p.position[i][k] = u(g);
      p.velocity[i][k] = 0.1 * u(g);
      p.shift[i][k] = 0;
    }
    p.pressure[i] = u(g);
    p.density[i] = 1000;
    p.id[i] = std::int64_t(i);
  }
  p.mass = 0.01;
  p.rho0 = 1000;
  p.spacing = 0.01;
  return p;
}

// Runs from (p, s) until step `stopStep`, writing every `every` steps.
template <int D>
void run(const std::string& dir, ParticleSet<D>& p, TimeState& s, long stopStep, long every) {
  while (s.step < stopStep) {
    step(p, s);
    if (s.step % every == 0) writeTimeDirectory<D>(dir, timeName(s.time), p, s, false);
  }
}

template <int D>
void checkRestart() {
  ScratchDir a, b;
  const long end = 300, every = 50;
  auto pa = initial<D>();
  TimeState sa{0, 0, 1e-4, 1e-4, ""};
  run<D>(a.path, pa, sa, end, every);

  auto pb = initial<D>();
  TimeState sb{0, 0, 1e-4, 1e-4, ""};
  run<D>(b.path, pb, sb, 170, every);  // "crash" at step 170; last write at 150
  auto latest = listTimeDirectories(b.path).back();
  TimeState sr;
  auto pr = readTimeDirectory<D>(b.path, latest.second, sr);
  BOOST_TEST(sr.step == 150);
  run<D>(b.path, pr, sr, end, every);

  checkSameState(pr, pa);
  BOOST_TEST(sameBits(sr.time, sa.time));
  BOOST_TEST(sameBits(sr.deltaT0, sa.deltaT0));
  BOOST_TEST(sr.step == sa.step);
  // The two cases hold the same time directories, byte for byte.
  auto la = listTimeDirectories(a.path), lb = listTimeDirectories(b.path);
  BOOST_TEST(la == lb);
  for (auto& [t, name] : la) {
    BOOST_TEST(slurp(a.path + "/" + name + "/particles.vtp") == slurp(b.path + "/" + name + "/particles.vtp"), name);
    BOOST_TEST(slurp(a.path + "/" + name + "/uniform/time") == slurp(b.path + "/" + name + "/uniform/time"), name);
  }
  BOOST_TEST(slurp(a.path + "/particles.pvd") == slurp(b.path + "/particles.pvd"));
}

// The same toy with the time kept only to the 8 digits of the directory name
// diverges: the check above can fail.
template <int D>
bool roundedTimeDiverges() {
  ScratchDir a;
  auto pa = initial<D>();
  TimeState sa{0, 0, 1e-4, 1e-4, ""};
  run<D>(a.path, pa, sa, 200, 50);
  TimeState sr;
  auto pr = readTimeDirectory<D>(a.path, listTimeDirectories(a.path)[1].second, sr);  // step 100
  sr.time = parseTimeName(timeName(sr.time)).value();
  sr.deltaT0 = parseTimeName(timeName(sr.deltaT0)).value();
  run<D>(a.path, pr, sr, 200, 1000);
  return !sameBits(pr.position, pa.position) || !sameBits(sr.time, sa.time);
}

}  // namespace

BOOST_AUTO_TEST_CASE(restart2D) { checkRestart<2>(); }
BOOST_AUTO_TEST_CASE(restart3D) { checkRestart<3>(); }
BOOST_AUTO_TEST_CASE(theCheckCanFail) {
  BOOST_TEST(roundedTimeDiverges<2>());
  BOOST_TEST(roundedTimeDiverges<3>());
}
