// Tests of capShift (eq. 10: |dr| <= maxShift h): no shift exceeds the cap,
// directions are kept, shorter shifts are untouched.
#define BOOST_TEST_MODULE effects_shiftCap
#include <boost/test/unit_test.hpp>
#include "effects/ShiftCap.hpp"
#include <random>

using namespace shizuku;

template <int D>
void check() {
  std::mt19937 g(5);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> len(0.0, 0.36);  // up to 3x the cap
  const double cap = 0.12;                                 // 0.1 h with h = 1.2 d0
  std::vector<Vec<D>> dr(10000), before;
  long over = 0;
  for (auto& d : dr) {
    for (int a = 0; a < D; ++a) d[a] = n(g);
    d *= len(g) / d.norm();
    over += d.norm() > cap;
  }
  before = dr;
  const long capped = capShift(dr, cap);
  BOOST_TEST(capped == over);
  for (std::size_t i = 0; i < dr.size(); ++i) {
    BOOST_TEST(dr[i].norm() <= cap * (1 + 1e-15));
    if (before[i].norm() <= cap) {
      BOOST_TEST((dr[i] - before[i]).norm() == 0.0);
    } else {
      BOOST_TEST(dr[i].norm() == cap, boost::test_tools::tolerance(1e-14));
      BOOST_TEST(dr[i].dot(before[i]) / (dr[i].norm() * before[i].norm()) == 1.0, boost::test_tools::tolerance(1e-14));
    }
  }
}

BOOST_AUTO_TEST_CASE(cap_2d) { check<2>(); }
BOOST_AUTO_TEST_CASE(cap_3d) { check<3>(); }

// The cap as the solver applies it: ParticleShifting built from a `shifting` dictionary
// with maxShift 0.1 and a DPS distribution shift of C = 10 (ten h per unit kernel sum,
// far past the cap) on a disordered lattice: every shift applied is at most 0.1 h, and
// the cap binds (some shifts reach it).
#include "core/Dictionary.hpp"
#include "core/StageTimers.hpp"
#include "effects/ParticleShifting.hpp"
#include "test_effects_fixture.hpp"

BOOST_AUTO_TEST_CASE(particle_shifting_caps_at_max_shift_times_h) {
  using namespace shizuku::testing;
  Fixture<2> f(0.01);
  std::uniform_real_distribution<double> jitter(-0.2 * f.d0, 0.2 * f.d0);
  forBox<2>({0, 0, 0}, {19, 19, 0}, [&](const std::array<int, 3>& idx) {
    f.add(latticePoint<2>(idx, f.d0) + Vec<2>(jitter(rng()), jitter(rng())));
  });
  f.setPeriodic(Vec<2>(-0.5 * f.d0, -0.5 * f.d0), Vec<2>(19.5 * f.d0, 19.5 * f.d0));
  f.update();
  EffectRegistry<2> registry;
  registerBuiltinEffects<2>(registry);
  const Dictionary d = Dictionary::fromString("distribution { type DPS; C 10; } maxShift 0.1; taylorCorrection off;",
                                              "case/system/sphSchemes/shifting");
  auto shifting = ParticleShifting<2>::create(&d, registry, f.s);
  BOOST_TEST_REQUIRE(bool(shifting));
  shifting->allocate(f.s);
  StageTimers timers;
  shifting->registerTimers(timers);
  shifting->apply(f.s, timers);
  const double cap = 0.1 * f.s.h;
  long atCap = 0;
  for (const auto& dr : f.s.particles.shift) {
    BOOST_TEST(dr.norm() <= cap * (1 + 1e-12));
    atCap += dr.norm() > 0.999 * cap;
  }
  BOOST_TEST(atCap > 100);  // the 400 shifts of C = 10 are mostly far past the cap
}
