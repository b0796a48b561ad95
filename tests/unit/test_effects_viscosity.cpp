// The value of the viscous acceleration nu <lap u> (eq. 4, docs/method.md 4.1) built by
// the solver's factory from constant/physicalProperties, and its wall term (the no-slip
// mirror velocity 2 U_w - u_i, or free slip; docs/method.md 11) and time-step limit
// 0.125 h^2 / nu (docs/method.md 4.3).
#define BOOST_TEST_MODULE effects_viscosity
#include <boost/test/unit_test.hpp>
#include "core/Dictionary.hpp"
#include "effects/EffectFactories.hpp"
#include "test_effects_fixture.hpp"

using namespace shizuku;
using namespace shizuku::testing;

namespace {

const double nu = 1e-3;

std::vector<Vec<2>> viscousAcceleration(const Fixture<2>& f, const std::string& props) {
  const Dictionary d = Dictionary::fromString(props, "case/constant/physicalProperties");
  std::unique_ptr<Effect<2>> e = makeViscosity<2>(d, f.s);
  auto* force = dynamic_cast<ForceEffect<2>*>(e.get());
  BOOST_REQUIRE(force);
  std::vector<Vec<2>> acc(f.s.size(), Vec<2>::Zero());
  force->addAcceleration(f.s, acc);
  return acc;
}

// Fluid rows 0..8 over three wall layers, x periodic over 10 spacings.
void wallSlab(Fixture<2>& f) {
  forBox<2>({0, -3, 0}, {9, 8, 0}, [&](const std::array<int, 3>& idx) {
    f.add(latticePoint<2>(idx, f.d0), idx[1] < 0 ? ParticleType::wall : ParticleType::fluid);
  });
  f.s.periodic.periodic = {true, false};
  f.s.periodic.lo = Vec<2>(-0.5 * f.d0, 0);
  f.s.periodic.hi = Vec<2>(9.5 * f.d0, 0);
  f.update();
}

// V sum over the wall neighbours of fluid particle i of the Laplacian weights.
double wallWeight(const Fixture<2>& f, std::size_t i) {
  double sum = 0;
  for (Index k = f.s.neighbours.begin(i); k < f.s.neighbours.end(i); ++k)
    if (f.s.particles.isWall(f.s.neighbours.j[k])) sum += f.s.weights.lapW[k];
  return f.s.V() * sum;
}

}  // namespace

BOOST_AUTO_TEST_CASE(quadratic_velocity_on_a_disordered_set_is_exact) {
  // u = (y^2 + x/2, x y + 2 x^2): lap u = (2, 4). The SPH(2) Laplacian is exact for
  // quadratics (docs/method.md 3.2), so every particle with a full support (two h = 2.4 d0
  // from the edge) must get nu (2, 4) to round-off, on a lattice moved by +-0.2 d0.
  Fixture<2> f(0.05);
  std::uniform_real_distribution<double> jitter(-0.2 * f.d0, 0.2 * f.d0);
  forBox<2>({0, 0, 0}, {20, 20, 0}, [&](const std::array<int, 3>& idx) {
    Vec<2> x = latticePoint<2>(idx, f.d0);
    x += Vec<2>(jitter(rng()), jitter(rng()));
    const std::size_t i = f.add(x);
    f.s.particles.velocity[i] = Vec<2>(x.y() * x.y() + 0.5 * x.x(), x.x() * x.y() + 2 * x.x() * x.x());
  });
  f.update();
  const auto acc = viscousAcceleration(f, "rho 1000; nu 1e-3;");
  int checked = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    const Vec<2>& x = f.s.particles.position[i];
    if (x.minCoeff() < 3.5 * f.d0 || x.maxCoeff() > 16.5 * f.d0) continue;
    BOOST_TEST_CONTEXT("particle " << i << " at " << x.transpose()) {
      BOOST_TEST(std::abs(acc[i].x() - 2 * nu) < 1e-9 * nu);
      BOOST_TEST(std::abs(acc[i].y() - 4 * nu) < 1e-9 * nu);
    }
    ++checked;
  }
  BOOST_TEST(checked == 13 * 13);  // lattice indices 4..16 in each direction
}

BOOST_AUTO_TEST_CASE(no_slip_wall_at_rest_brakes_a_uniform_stream) {
  // Fluid moving uniformly at U = (1, 0) over a wall at rest: fluid neighbours add nothing,
  // each wall neighbour shows the mirror velocity -U, so a = -2 U nu V sum_wall lapW, the
  // wall term alone. Rows out of the walls' reach feel nothing.
  Fixture<2> f(0.01);
  wallSlab(f);
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (f.s.particles.isFluid(i)) f.s.particles.velocity[i] = Vec<2>(1, 0);
  const auto acc = viscousAcceleration(f, "rho 1000; nu 1e-3; wallCondition noSlip;");
  int nearWall = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (!f.s.particles.isFluid(i)) continue;
    const double w = wallWeight(f, i);
    BOOST_TEST_CONTEXT("particle " << i << " at " << f.s.particles.position[i].transpose()) {
      BOOST_TEST(std::abs(acc[i].x() - (-2 * nu * w)) <= 1e-12 * (1 + std::abs(nu * w)));
      BOOST_TEST(std::abs(acc[i].y()) <= 1e-12);
      if (f.s.particles.position[i].y() < 0.5 * f.d0) BOOST_TEST(acc[i].x() < -0.5 * nu / (f.d0 * f.d0));
    }
    nearWall += w != 0;
  }
  BOOST_TEST(nearWall == 20);  // rows 0 and 1 reach the top wall layer within 2h = 2.4 d0
  // The same stream over a free-slip wall feels no force at all.
  for (const auto& a : viscousAcceleration(f, "rho 1000; nu 1e-3; wallCondition slip;")) BOOST_TEST(a.norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(moving_no_slip_wall_drags_fluid_at_rest) {
  // Couette start: the wall moves at U_w = (0.5, 0), the fluid is at rest. The wall
  // neighbours show 2 U_w, so a = 2 U_w nu V sum_wall lapW, along +x.
  Fixture<2> f(0.01);
  wallSlab(f);
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (f.s.particles.isWall(i)) f.s.particles.velocity[i] = Vec<2>(0.5, 0);
  const auto acc = viscousAcceleration(f, "rho 1000; nu 1e-3;");
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (!f.s.particles.isFluid(i)) continue;
    BOOST_TEST(std::abs(acc[i].x() - nu * wallWeight(f, i)) <= 1e-12 * (1 + std::abs(nu * wallWeight(f, i))));
    BOOST_TEST(acc[i].x() >= 0.0);
  }
}

BOOST_AUTO_TEST_CASE(time_step_limit_is_an_eighth_of_h2_over_nu) {
  Fixture<2> f(0.01);
  wallSlab(f);
  const Dictionary d = Dictionary::fromString("rho 1000; nu 1e-3;", "case/constant/physicalProperties");
  const auto e = makeViscosity<2>(d, f.s);
  const TimeStepLimit lim = e->timeStepLimit(f.s);
  BOOST_TEST(lim.dt == 0.125 * f.s.h * f.s.h / nu, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::string(lim.name) == "viscous");
}
