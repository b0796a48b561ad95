// The law of the wall (docs/method.md 11.2, effects/WallFriction.hpp) and the wall-friction
// force built from constant/physicalProperties: the log layer, the viscous sublayer and the
// fully rough limit of u_tau; a stream over a floor decelerated by u_tau^2 / d0 in its first
// row and nowhere else, in 2D and 3D; a moving wall dragging water at rest; the cap that
// stops an explicit step from reversing the flow; input errors; no effect without the
// dictionary.
#define BOOST_TEST_MODULE effects_wallFriction
#include <boost/test/unit_test.hpp>
#include "core/Dictionary.hpp"
#include "effects/EffectFactories.hpp"
#include "effects/EffectSet.hpp"
#include "effects/WallFriction.hpp"
#include "test_effects_fixture.hpp"
#include <cmath>

using namespace shizuku;
using namespace shizuku::testing;

namespace {

const double nu = 1e-6;

template <int D>
std::vector<Vec<D>> frictionAcceleration(const Fixture<D>& f, const std::string& props) {
  const Dictionary d = Dictionary::fromString(props, "case/constant/physicalProperties");
  std::unique_ptr<Effect<D>> e = makeWallFriction<D>(d, f.s);
  auto* force = dynamic_cast<ForceEffect<D>*>(e.get());
  BOOST_REQUIRE(force);
  std::vector<Vec<D>> acc(f.s.size(), Vec<D>::Zero());
  force->addAcceleration(f.s, acc);
  return acc;
}

// Eight rows of water over three wall layers below it (normal e_D), periodic along the wall
// over `width` sites; d0 = 1 cm.
template <int D>
void floorSlab(Fixture<D>& f, int width) {
  forSlab<D>(width, -3, 7, [&](const std::array<int, 3>& idx) {
    f.add(latticePoint<D>(idx, f.d0), idx[D - 1] < 0 ? ParticleType::wall : ParticleType::fluid);
  });
  f.setPeriodicAlongSurface(width, f.d0);
  f.update();
}

template <int D>
void streamFeelsTheWallStressInItsFirstRow() {
  Fixture<D> f(0.01);
  const int width = D == 2 ? 10 : 6;
  floorSlab(f, width);
  Vec<D> U = Vec<D>::Zero();
  U[0] = 1.0;
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (f.s.particles.isFluid(i)) f.s.particles.velocity[i] = U;
  const auto acc = frictionAcceleration(f, "rho 1000; nu 1e-6; wallFriction { }");
  // The first row sits d0/2 above the wall face (the face is halfway between the first
  // fluid row and the first wall layer).
  const double us = frictionVelocity(1.0, 0.5 * f.d0, nu, 0);
  int firstRow = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (!f.s.particles.isFluid(i)) continue;
    const bool first = f.s.particles.position[i][D - 1] < 0.5 * f.d0;
    BOOST_TEST_CONTEXT("particle at " << f.s.particles.position[i].transpose()) {
      BOOST_TEST(std::abs(acc[i][0] - (first ? -us * us / f.d0 : 0.0)) <= 1e-12 * us * us / f.d0);
      for (int a = 1; a < D; ++a) BOOST_TEST(std::abs(acc[i][a]) <= 1e-12 * us * us / f.d0);
    }
    firstRow += first;
  }
  BOOST_TEST(firstRow == (D == 2 ? width : width * width));
}

}  // namespace

BOOST_AUTO_TEST_CASE(smooth_log_layer_satisfies_the_law_of_the_wall) {
  // U / u_tau = ln(9 y u_tau / nu) / kappa above y+ = 11: the classical smooth-wall law
  // ln(y+)/kappa + B with B = ln(9)/0.41 = 5.36 (textbook values 5.0-5.5).
  int logLayer = 0;
  for (const double U : {0.1, 1.0, 5.0})
    for (const double y : {1e-3, 5e-3, 2e-2}) {
      const double us = frictionVelocity(U, y, nu, 0);
      const double yPlus = y * us / nu;
      BOOST_TEST_CONTEXT("U " << U << " y " << y << " y+ " << yPlus) {
        if (yPlus > 11.0) {
          ++logLayer;
          BOOST_TEST(std::abs(us / kVonKarman * std::log(9 * yPlus) - U) <= 1e-12 * U);
          BOOST_TEST(std::abs(U / us - std::log(yPlus) / kVonKarman - 5.36) < 0.01);
        } else {
          BOOST_TEST(std::abs(us * us - nu * U / y) <= 1e-14 * nu * U / y);  // viscous sublayer
        }
      }
    }
  BOOST_TEST(logLayer == 8);  // all but U = 0.1 m/s at y = 1 mm (y+ = 10)
  // At 3 m/s and y = 2.5 mm (the a/80 dam break's first row) the stress is about 22 Pa in water.
  const double us = frictionVelocity(3.0, 2.5e-3, nu, 0);
  BOOST_TEST(1000 * us * us > 20.0);
  BOOST_TEST(1000 * us * us < 25.0);
}

BOOST_AUTO_TEST_CASE(viscous_sublayer_and_fully_rough_limit) {
  // Slow flow close to a smooth wall: y+ <= 11, the laminar stress nu U / y.
  const double U = 0.01, y = 1e-3;
  const double us = frictionVelocity(U, y, nu, 0);
  BOOST_TEST(y * us / nu <= 11.0);
  BOOST_TEST(std::abs(us * us - nu * U / y) <= 1e-14 * nu * U / y);
  // The two branches meet near y+ = 11: the log law's u_tau just above the switch is within
  // 2 % of the laminar one just below it.
  const double yEdge = 11.0 * 11.0 * nu / 1.0;  // laminar y+ = 11 at U = 1 m/s: y = 121 nu / U
  const double below = frictionVelocity(1.0, 0.999 * yEdge, nu, 0), above = frictionVelocity(1.0, 1.001 * yEdge, nu, 0);
  BOOST_TEST(std::abs(above / below - 1) < 0.02);
  // Fully rough (nu -> 0): U / u_tau = ln(30 y / ks) / kappa, whatever nu.
  for (const double ks : {1e-4, 1e-3}) {
    const double usRough = frictionVelocity(2.0, 0.01, 1e-14, ks);
    BOOST_TEST(std::abs(usRough - kVonKarman * 2.0 / std::log(30 * 0.01 / ks)) <= 1e-9 * usRough);
  }
  // Slow flow over a rough wall stays in the viscous sublayer: the laminar stress, not less.
  BOOST_TEST(std::abs(frictionVelocity(1e-4, 5e-3, nu, 1e-3) - std::sqrt(nu * 1e-4 / 5e-3)) <= 1e-15);
  // Roughness raises the stress over the smooth wall's.
  BOOST_TEST(frictionVelocity(2.0, 0.01, nu, 1e-3) > frictionVelocity(2.0, 0.01, nu, 0));
  BOOST_TEST(frictionVelocity(0.0, 0.01, nu, 0) == 0.0);
}

BOOST_AUTO_TEST_CASE(stream_over_a_floor_2d) { streamFeelsTheWallStressInItsFirstRow<2>(); }
BOOST_AUTO_TEST_CASE(stream_over_a_floor_3d) { streamFeelsTheWallStressInItsFirstRow<3>(); }

BOOST_AUTO_TEST_CASE(moving_wall_drags_water_at_rest_and_the_cap_stops_reversal) {
  Fixture<2> f(0.01);
  floorSlab(f, 10);
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (f.s.particles.isWall(i)) f.s.particles.velocity[i] = Vec<2>(0.5, 0);
  const double us = frictionVelocity(0.5, 0.5 * f.d0, nu, 0);
  auto acc = frictionAcceleration(f, "rho 1000; nu 1e-6; wallFriction { roughness 0; }");
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (!f.s.particles.isFluid(i) || f.s.particles.position[i].y() > 0.5 * f.d0) continue;
    BOOST_TEST(std::abs(acc[i].x() - us * us / f.d0) <= 1e-12 * us * us / f.d0);
  }
  // A step so long that u_tau^2 / d0 dt exceeds the relative speed: the step stops the
  // relative motion and no more (a = 0.5 m/s / dt).
  f.s.dt = 10.0;
  BOOST_REQUIRE(us * us / f.d0 * f.s.dt > 0.5);
  acc = frictionAcceleration(f, "rho 1000; nu 1e-6; wallFriction { }");
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    if (!f.s.particles.isFluid(i) || f.s.particles.position[i].y() > 0.5 * f.d0) continue;
    BOOST_TEST(std::abs(acc[i].x() - 0.5 / f.s.dt) <= 1e-14);
  }
}

BOOST_AUTO_TEST_CASE(input_errors_name_the_keyword) {
  Fixture<2> f(0.01);
  floorSlab(f, 10);
  auto message = [&](const std::string& props) {
    try {
      frictionAcceleration(f, props);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message("rho 1000; nu 0; wallFriction { }").find("wallFriction") != std::string::npos);
  BOOST_TEST(message("rho 1000; nu 1e-6; wallCondition noSlip; wallFriction { }").find("wallCondition") !=
             std::string::npos);
  BOOST_TEST(message("rho 1000; nu 1e-6; wallFriction { roughness -1; }").find("roughness") != std::string::npos);
  BOOST_TEST(message("rho 1000; nu 1e-6; wallCondition slip; wallFriction { roughness 1e-4; }").empty());
}

BOOST_AUTO_TEST_CASE(no_wall_friction_without_its_dictionary) {
  // An absent effect is not built: the case's forces are gravity and viscosity only, and the
  // viscous term keeps the no-slip walls.
  Fixture<2> f(0.01);
  floorSlab(f, 10);
  const Dictionary g = Dictionary::fromString("value (0 -9.81);", "case/constant/g");
  const Dictionary sch = Dictionary::fromString("", "case/system/sphSchemes");
  auto names = [&](const std::string& props) {
    const Dictionary d = Dictionary::fromString(props, "case/constant/physicalProperties");
    const auto set = EffectSet<2>::build(&g, d, 1e-6, sch, f.s);
    std::string all;
    for (const auto& e : set.forces) all += e->name() + " " + e->describe() + "; ";
    return all;
  };
  const std::string without = names("rho 1000; nu 1e-6;");
  BOOST_TEST(without.find("wallFriction") == std::string::npos);
  BOOST_TEST(without.find("noSlip") != std::string::npos);
  const std::string with = names("rho 1000; nu 1e-6; wallFriction { }");
  BOOST_TEST(with.find("wallFriction") != std::string::npos);
  BOOST_TEST(with.find("walls slip") != std::string::npos);
}
