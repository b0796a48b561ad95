// The last good state of a run (libsph/isph/HealthGuard.hpp, docs/solver.md "Health checks"):
// the state at the start of a step, which the time loop writes after a numerical failure.
// Within a step the particles may be reordered (the cell reordering), removed (outflow,
// the domain check) or added (inlets), so restoring must give back every field a particle
// carries in the saved order, not only the positions. A moving wall's particles carry
// their rest position and motion index (docs/method.md 11.1): restored out of order, the
// walls would be rebuilt from another particle's rest position when the run is resumed
// from the written state. Checked here in 2D and 3D: save, permute, remove and append a
// particle, move everything, restore; every field equals the saved one, particle by
// particle; and a case without moving walls gets no rest positions back.
#define BOOST_TEST_MODULE isph_goodState
#include <boost/test/unit_test.hpp>
#include "core/Dictionary.hpp"
#include "isph/HealthGuard.hpp"
#include <numeric>

using namespace shizuku;

namespace {

// Twelve particles: eight fluid, four wall particles of two moving walls (motion 1 and 2).
template <int D>
FlowState<D> makeState(bool moving) {
  FlowState<D> s;
  auto& P = s.particles;
  const std::size_t n = 12;
  P.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> x = Vec<D>::Zero();
    x[0] = 0.1 * double(i);
    x[D - 1] = 0.01 * double(i * i);
    P.position[i] = x;
    P.velocity[i] = Vec<D>::Constant(double(i) + 0.5);
    P.pressure[i] = 100.0 * double(i);
    P.id[i] = std::int64_t(i);
    P.type[i] = std::uint8_t(i < 8 ? ParticleType::fluid : ParticleType::wall);
  }
  if (moving) {
    P.restPosition.resize(n);
    P.motion.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      P.restPosition[i] = P.position[i] + Vec<D>::Constant(1.0);
      P.motion[i] = std::uint8_t(i < 8 ? 0 : (i < 10 ? 1 : 2));
    }
  }
  s.time = 1.25;
  s.step = 40;
  s.dt = 1e-3;
  s.refreshTypeMasks();
  return s;
}

// What a step may do to the particles before it fails: reorder them, remove one, append a
// copy of another, move them all and advance the clock.
template <int D>
void disturb(FlowState<D>& s) {
  auto& P = s.particles;
  std::vector<std::size_t> order(P.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::reverse(order.begin(), order.end());
  std::swap(order[1], order[6]);
  P.permute(order);
  std::vector<std::uint8_t> remove(P.size(), 0);
  remove[3] = 1;
  P.removeMarked(remove);
  P.addCopy(0);
  for (auto& x : P.position) x += Vec<D>::Constant(0.3);
  for (auto& u : P.velocity) u *= 2.0;
  s.time += s.dt;
  ++s.step;
  s.refreshTypeMasks();
}

template <int D>
void checkRestored(bool moving) {
  FlowState<D> s = makeState<D>(moving);
  const FlowState<D> saved = makeState<D>(moving);
  HealthGuard<D> guard(Dictionary::fromString("", "controlDict"));
  guard.saveGoodState(s);
  disturb(s);
  guard.restoreGoodState(s);
  const auto& P = s.particles;
  const auto& Q = saved.particles;
  BOOST_TEST_REQUIRE(P.size() == Q.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    BOOST_TEST(P.id[i] == Q.id[i]);
    BOOST_TEST(P.type[i] == Q.type[i]);
    BOOST_TEST((P.position[i] - Q.position[i]).norm() == 0.0);
    BOOST_TEST((P.velocity[i] - Q.velocity[i]).norm() == 0.0);
    BOOST_TEST(P.pressure[i] == Q.pressure[i]);
  }
  BOOST_TEST(P.restPosition.size() == Q.restPosition.size());
  BOOST_TEST(P.motion.size() == Q.motion.size());
  if (moving && P.restPosition.size() == Q.restPosition.size() && P.motion.size() == Q.motion.size())
    for (std::size_t i = 0; i < P.size(); ++i) {
      BOOST_TEST((P.restPosition[i] - Q.restPosition[i]).norm() == 0.0, "rest position of particle " << i);
      BOOST_TEST(P.motion[i] == Q.motion[i], "motion of particle " << i);
    }
  BOOST_TEST(s.time == saved.time);
  BOOST_TEST(s.step == saved.step);
  BOOST_TEST(s.dt == saved.dt);
  BOOST_TEST(s.isFluidMask.size() == P.size());
  for (std::size_t i = 0; i < P.size(); ++i) BOOST_TEST(s.isFluid(i) == (i < 8));
}

}  // namespace

BOOST_AUTO_TEST_CASE(moving_walls_restored_in_the_saved_order_2d) { checkRestored<2>(true); }
BOOST_AUTO_TEST_CASE(moving_walls_restored_in_the_saved_order_3d) { checkRestored<3>(true); }
BOOST_AUTO_TEST_CASE(fixed_walls_get_no_rest_positions_2d) { checkRestored<2>(false); }
BOOST_AUTO_TEST_CASE(fixed_walls_get_no_rest_positions_3d) { checkRestored<3>(false); }
