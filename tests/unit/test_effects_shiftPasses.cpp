// Tests of the shift's passes (docs/method.md 6, "Larger steps"; ParticleShifting::passes):
// a step of Courant number Co above maxCoPerPass shifts in ceil(Co / maxCoPerPass) passes
// that together amount to Co / maxCoPerPass single passes, so that OPS homogenises a fluid
// at the same rate per unit time whatever the step.
//
// Known answer: OPS is one explicit step of a diffusion of the particle positions (method.md
// 6). A longitudinal sine wave of displacement on a periodic lattice (a density wave) decays
// by a factor (1 - lambda) per pass of the full coefficient, lambda set by C h^2 k^2. Over the
// same simulated time, steps of Co = 0.2 (one pass each) and steps of Co = 0.5 (three passes
// of 5/6 each) apply 10 and 4 x 3 x 5/6 = 10 passes' worth of diffusion: log amplitudes
// (1 - lambda)^10 against (1 - 5 lambda / 6)^12, equal to lambda / 12 relative (at most 2 %
// for the lambda of this wave). With one pass per step the larger steps would diffuse 4
// passes' worth: 60 % less, which the test must and does tell apart.
#define BOOST_TEST_MODULE effects_shiftPasses
#include <boost/test/unit_test.hpp>
#include "core/Dictionary.hpp"
#include "core/StageTimers.hpp"
#include "effects/ParticleShifting.hpp"
#include "test_effects_fixture.hpp"
#include <cmath>

using namespace shizuku;
using namespace shizuku::testing;

namespace {

const char* kShifting = "distribution { type OPS; C 0.2; Rp 0.2; np 4; } maxShift 0.1; taylorCorrection off; ";

template <int D>
std::unique_ptr<ParticleShifting<D>> makeShifting(const std::string& extra, const FlowState<D>& s) {
  static EffectRegistry<D> registry = [] {
    EffectRegistry<D> r;
    registerBuiltinEffects<D>(r);
    return r;
  }();
  const Dictionary d = Dictionary::fromString(std::string(kShifting) + extra, "case/system/sphSchemes/shifting");
  return ParticleShifting<D>::create(&d, registry, s);
}

// A periodic lattice of n sites a side, every particle moving at u along x (the shift does
// not depend on the velocity; the Courant number does).
template <int D>
void lattice(Fixture<D>& f, int n, double u) {
  forBox<D>({0, 0, 0}, {n - 1, n - 1, n - 1}, [&](const std::array<int, 3>& idx) {
    const std::size_t i = f.add(latticePoint<D>(idx, f.d0));
    f.s.particles.velocity[i] = u * Vec<D>::Unit(0);
  });
  f.setPeriodic(Vec<D>::Constant(-0.5 * f.d0), Vec<D>::Constant((n - 0.5) * f.d0));
}

// Amplitude of the displacement's sine wave sin(k x0) e_x about the lattice sites x0.
template <int D>
double amplitude(const Fixture<D>& f, const std::vector<Vec<D>>& sites, double k) {
  double sum = 0;
  for (std::size_t i = 0; i < sites.size(); ++i)
    sum += f.s.periodic.difference(f.s.particles.position[i], sites[i])[0] * std::sin(k * sites[i][0]);
  return 2.0 * sum / double(sites.size());
}

// The wave's amplitude after `steps` steps of Courant number co, relative to its start.
template <int D>
double decay(int n, double co, int steps, const std::string& extra) {
  Fixture<D> f(0.01);
  const double u = 1.0;
  lattice(f, n, u);
  f.s.dt = co * f.s.h / u;
  const double L = n * f.d0, k = 2 * M_PI / L, a0 = 0.05 * f.d0;
  std::vector<Vec<D>> sites = f.s.particles.position;
  for (std::size_t i = 0; i < sites.size(); ++i) f.s.particles.position[i][0] += a0 * std::sin(k * sites[i][0]);
  f.update();
  auto shifting = makeShifting<D>(extra, f.s);
  BOOST_TEST_REQUIRE(bool(shifting));
  shifting->allocate(f.s);
  StageTimers timers;
  shifting->registerTimers(timers);
  for (int step = 0; step < steps; ++step) {
    shifting->beginStep(co);
    shifting->apply(f.s, timers);
    f.update();  // the solver's next step builds its list at the shifted positions
  }
  return amplitude(f, sites, k) / a0;
}

template <int D>
void passCounts() {
  Fixture<D> f(0.01);
  lattice(f, 6, 1.0);
  f.update();
  auto shifting = makeShifting<D>("maxCoPerPass 0.2;", f.s);
  BOOST_TEST_REQUIRE(bool(shifting));
  struct Case { double co; int count; double scale; };
  for (const Case c : {Case{0.0, 1, 1.0}, Case{0.1, 1, 1.0}, Case{0.2, 1, 1.0}, Case{0.21, 2, 0.525},
                       Case{0.5, 3, 2.5 / 3}, Case{1.0, 5, 1.0}}) {
    const ShiftPasses p = shifting->passes(c.co);
    BOOST_TEST(p.count == c.count, "Co " << c.co);
    BOOST_TEST(p.scale == c.scale, boost::test_tools::tolerance(1e-9));
  }
  // Steps the CFL limit sets, dt = maxCo h / max|u| (TimeLoop), have Co = dt max|u| / h
  // (IsphStep) = maxCo up to rounding: maxCo 0.2 is one pass and 0.4 two, for any speed.
  const double h = f.s.h;
  for (const double u : {0.3, 1.7, 2.9, 7.3, 11.1}) {
    BOOST_TEST(shifting->passes((0.2 * h / u) * u / h).count == 1, "u " << u);
    BOOST_TEST(shifting->passes((0.4 * h / u) * u / h).count == 2, "u " << u);
  }
  // Every step is one pass when maxCoPerPass is out of reach.
  BOOST_TEST(makeShifting<D>("maxCoPerPass 1e9;", f.s)->passes(0.5).count == 1);
}

template <int D>
void samePerUnitTime(int n) {
  const double small = decay<D>(n, 0.2, 10, "maxCoPerPass 0.2;");
  const double large = decay<D>(n, 0.5, 4, "maxCoPerPass 0.2;");
  const double onePass = decay<D>(n, 0.5, 4, "maxCoPerPass 1e9;");
  BOOST_TEST_MESSAGE(D << "D: amplitude after t = 2 h/u: Co 0.2 " << small << ", Co 0.5 in passes " << large
                       << ", Co 0.5 one pass a step " << onePass);
  BOOST_TEST_REQUIRE(small < 0.9);  // the wave decays measurably, or the comparison is empty
  BOOST_TEST(std::log(large) / std::log(small) == 1.0, boost::test_tools::tolerance(0.03));
  BOOST_TEST(std::log(onePass) / std::log(small) < 0.6);  // what the passes restore
}

}  // namespace

BOOST_AUTO_TEST_CASE(pass_count_and_scale_2d) { passCounts<2>(); }
BOOST_AUTO_TEST_CASE(pass_count_and_scale_3d) { passCounts<3>(); }
BOOST_AUTO_TEST_CASE(ops_decays_at_the_same_rate_per_unit_time_2d) { samePerUnitTime<2>(20); }
BOOST_AUTO_TEST_CASE(ops_decays_at_the_same_rate_per_unit_time_3d) { samePerUnitTime<3>(10); }
