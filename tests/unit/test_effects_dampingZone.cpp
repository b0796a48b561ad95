// The damping zone (docs/method.md 4.5, eq. 4b): inside [min, max] a fluid particle feels
// a = -rate xi^2 u with xi its fractional position along the axis, nothing outside, walls
// nothing; the effect limits dt to 1/rate; a reversed box, an axis the case lacks and a
// missing rate are input errors.
#define BOOST_TEST_MODULE effects_dampingZone
#include <boost/test/unit_test.hpp>
#include "core/Dictionary.hpp"
#include "effects/EffectFactories.hpp"
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;

namespace {

template <int D>
std::unique_ptr<Effect<D>> zone(const FlowState<D>& s, const std::string& axis = "x") {
  static std::vector<std::unique_ptr<Dictionary>> keep;
  const std::string lo = D == 2 ? "(2 -1)" : "(2 -1 -1)", hi = D == 2 ? "(6 9)" : "(6 9 9)";
  keep.push_back(std::make_unique<Dictionary>(Dictionary::fromString(
      "min " + lo + "; max " + hi + "; axis " + axis + "; rate 8;", "case/system/sphSchemes")));
  return makeDampingZone<D>(*keep.back(), s);
}

template <int D>
void acceleration() {
  Fixture<D> f;
  for (int i = 0; i < 9; ++i) {
    Vec<D> x = Vec<D>::Zero();
    x[0] = i;
    f.add(x, i == 4 ? ParticleType::wall : ParticleType::fluid);
    f.s.particles.velocity.back() = Vec<D>::Constant(0.5 + i);
  }
  auto e = zone<D>(f.s);
  auto* force = dynamic_cast<ForceEffect<D>*>(e.get());
  BOOST_TEST_REQUIRE(force);
  f.s.isFluidMask.assign(f.s.size(), 1);
  f.s.isFluidMask[4] = 0;
  std::vector<Vec<D>> acc(f.s.size(), Vec<D>::Zero());
  force->addAcceleration(f.s, acc);
  for (int i = 0; i < 9; ++i) {
    const double xi = (i - 2) / 4.0;
    const bool inside = i >= 2 && i <= 6 && i != 4;
    const Vec<D> expect = inside ? Vec<D>(-8 * xi * xi * f.s.particles.velocity[std::size_t(i)]) : Vec<D>::Zero();
    BOOST_TEST_CONTEXT("particle at x = " << i) { BOOST_TEST((acc[std::size_t(i)] - expect).norm() < 1e-14); }
  }
  BOOST_TEST(e->timeStepLimit(f.s).dt == 1.0 / 8);
}

}  // namespace

BOOST_AUTO_TEST_CASE(damping_is_rate_xi_squared_inside_the_zone_2d) { acceleration<2>(); }
BOOST_AUTO_TEST_CASE(damping_is_rate_xi_squared_inside_the_zone_3d) { acceleration<3>(); }

BOOST_AUTO_TEST_CASE(bad_zones_are_input_errors) {
  Fixture<2> f;
  BOOST_CHECK_THROW(zone<2>(f.s, "z"), InputError);
  const auto bad = Dictionary::fromString("min (6 0); max (2 1); rate 8;", "case/system/sphSchemes");
  BOOST_CHECK_THROW(makeDampingZone<2>(bad, f.s), InputError);
  const auto noRate = Dictionary::fromString("min (2 0); max (6 1);", "case/system/sphSchemes");
  BOOST_CHECK_THROW(makeDampingZone<2>(noRate, f.s), InputError);
}
