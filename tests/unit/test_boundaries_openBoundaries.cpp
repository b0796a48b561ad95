// Inlets and outlets at run time (boundaries/OpenBoundaries, docs/boundaries.md "Inlets and
// outlets"), in 2D and 3D, on a plug flow moved by hand (every particle at the inlet's
// velocity U, no pressure solve), so that every count has an exact answer:
//   - an inlet column starts d0/2 + k d0 upstream of its face, so after a travel U T the
//     inlet has released rows x round(U T / d0) particles (floor(U T / d0 + 1/2));
//   - the outlet (filled whole at the start) captures as many and removes as many past its
//     far face, so the fluid, inlet and outlet counts stay constant;
//   - fluid count = initial + released - captured - removed after every step;
//   - ids stay unique, and each step's new ids are inlet particles numbered from the
//     previous nextId up;
//   - a captured particle takes the outlet's pressure; an expression inlet velocity
//     u = 4 Umax y (H - y) / H^2 (1 + t) is applied to every inlet particle, and described;
//   - 3D input errors name the keyword and suggest the fix (the 2D ones are bad-input cases).
#define BOOST_TEST_MODULE boundaries_openBoundaries
#include <boost/test/unit_test.hpp>

#include "boundaries/OpenBoundaries.hpp"
#include "particles/ParticleGenerator.hpp"
#include "../support/ErrorOf.hpp"
#include <cmath>
#include <set>

using namespace shizuku;

namespace {

constexpr double d0 = 0.01, H = 0.05, U = 0.1;

// A duct [0, 0.1] x [0, H] (x [0, H] in 3D) between a 4-spacing inlet and outlet.
template <int D>
std::string duct(const std::string& inletVelocity, double outletPressure) {
  const std::string z0 = D == 3 ? " 0" : "", zH = D == 3 ? " 0.05" : "";
  return "spacing 0.01;\nregions\n{\n"
         " water { type fluid; shape box; min (0 0" + z0 + "); max (0.1 0.05" + zH + "); velocity { type uniform; value (0.1 0" + z0 + "); } }\n"
         " walls { type wall; shape box; min (-0.04 0" + z0 + "); max (0.14 0.05" + zH + "); layers 3; open (left right); }\n"
         " inflow { type inlet; shape box; min (-0.04 0" + z0 + "); max (0 0.05" + zH + "); direction (1 0" + z0 + ");\n"
         "          velocity " + inletVelocity + " }\n"
         " outflow { type outlet; shape box; min (0.1 0" + z0 + "); max (0.14 0.05" + zH + "); direction (1 0" + z0 +
         "); pressure " + std::to_string(outletPressure) + "; }\n}\n";
}

template <int D>
std::string uniformInlet() { return D == 2 ? "{ type uniform; value (0.1 0); }" : "{ type uniform; value (0.1 0 0); }"; }

template <int D>
struct Duct {
  Dictionary dict;  // the regions keep a pointer into it
  FlowState<D> s;
  std::unique_ptr<OpenBoundaries<D>> open;
  explicit Duct(const std::string& text) : dict(Dictionary::fromString(text, "case/system/particlesDict")) {
    GeneratedParticles<D> g = generateParticles<D>(dict);
    s.particles = std::move(g.set);
    s.d0 = d0;
    s.h = 1.2 * d0;
    s.kernel = Kernel<D>(KernelType::cubicSpline, s.h);
    s.hasOpenBoundaries = true;
    s.refreshTypeMasks();
    open = std::make_unique<OpenBoundaries<D>>(std::move(g.openBoundaries), s, Domain<D>());
    open->prescribe(s);
  }
  std::size_t count(ParticleType t) const {
    std::size_t n = 0;
    for (auto ty : s.particles.type) n += ty == std::uint8_t(t);
    return n;
  }
  // One step of the plug flow: the fluid moves at its velocity (the ISPH step's job), then
  // the open boundaries move their buffers, release, capture and remove.
  void step(double dt) {
    auto& P = s.particles;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.isFluid(i)) P.position[i] += dt * P.velocity[i];
    s.dt = dt;
    s.time += dt;
    ++s.step;
    open->afterStep(s);
    s.refreshTypeMasks();
  }
};

template <int D>
void checkIdsUnique(const ParticleSet<D>& P) {
  std::set<std::int64_t> ids(P.id.begin(), P.id.end());
  BOOST_TEST(ids.size() == P.size());
  BOOST_TEST(*ids.rbegin() < P.nextId);
}

// Rows of lattice points across an open boundary of the duct: (H/d0)^(D-1).
template <int D>
long rows() { return D == 2 ? 5 : 25; }

template <int D>
void plugFlowCounts() {
  Duct<D> c(duct<D>(uniformInlet<D>(), 3.0));
  const std::size_t fluid0 = c.count(ParticleType::fluid), inlet0 = c.count(ParticleType::inlet),
                    outlet0 = c.count(ParticleType::outlet);
  BOOST_TEST(fluid0 == std::size_t(10 * rows<D>()));
  BOOST_TEST(inlet0 == std::size_t(4 * rows<D>()));
  BOOST_TEST(outlet0 == std::size_t(4 * rows<D>()));
  const double dt = 0.0125;  // U dt = d0 / 8
  long removed = 0;
  for (int n = 1; n <= 24; ++n) {  // U T = 3 d0
    const std::int64_t nextIdBefore = c.s.particles.nextId;
    const long releasedBefore = c.s.balance.released;
    const std::size_t sizeBefore = c.s.size();
    const std::size_t outletBefore = c.count(ParticleType::outlet);
    const long capturedBefore = c.s.balance.captured;
    c.step(dt);
    const auto& P = c.s.particles;
    const long released = c.s.balance.released - releasedBefore;
    const long captured = c.s.balance.captured - capturedBefore;
    removed += long(sizeBefore) + released - long(c.s.size());
    // New ids: inlet particles, from the previous nextId up, one per release.
    long fresh = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.id[i] >= nextIdBefore) {
        ++fresh;
        BOOST_TEST(P.isInlet(i));
      }
    BOOST_TEST(fresh == released);
    BOOST_TEST(P.nextId == nextIdBefore + released);
    checkIdsUnique(P);
    // The balance, exactly, every step.
    BOOST_TEST(long(c.count(ParticleType::fluid)) ==
               long(fluid0) + c.s.balance.released - c.s.balance.captured - c.s.balance.removedCount);
    BOOST_TEST(long(c.count(ParticleType::outlet)) == long(outletBefore) + captured -
                                                         (long(sizeBefore) + released - long(c.s.size())));
    BOOST_TEST(c.count(ParticleType::inlet) == inlet0);
    // Outlet particles lie inside the outlet up to its far face; captured ones hold its pressure.
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.isOutlet(i)) {
        BOOST_TEST(P.position[i][0] <= 0.14 + 1e-12);
        BOOST_TEST(P.position[i][0] > 0.1);
        BOOST_TEST(P.pressure[i] == 3.0);
      }
    // Whole spacings of travel: round(U T / d0) columns released, captured, removed.
    if (n % 8 == 0 || n % 8 == 2 || n % 8 == 6) {
      const long columns = std::lround(std::floor(U * n * dt / d0 + 0.5));
      BOOST_TEST_CONTEXT("step " << n << ", U T / d0 = " << U * n * dt / d0) {
        BOOST_TEST(c.s.balance.released == rows<D>() * columns);
        BOOST_TEST(c.s.balance.captured == rows<D>() * columns);
        BOOST_TEST(removed == rows<D>() * columns);
        BOOST_TEST(c.count(ParticleType::fluid) == fluid0);
        BOOST_TEST(c.count(ParticleType::outlet) == outlet0);
      }
    }
  }
  BOOST_TEST(c.s.balance.released == 3 * rows<D>());
  BOOST_TEST(c.open->crossings()[0].count == 3 * rows<D>());  // inflow
  BOOST_TEST(c.open->crossings()[1].count == 3 * rows<D>());  // outflow
  // The buffer stays on the lattice: every inlet particle at min + (i + 1/2) d0 + U T.
  for (std::size_t i = 0; i < c.s.size(); ++i)
    if (c.s.particles.isInlet(i)) {
      const double x = c.s.particles.position[i][0];
      BOOST_TEST(x > -0.04);
      BOOST_TEST(x <= 0.0);
      const double k = (x - 0.03 + 0.04) / d0 - 0.5;  // travel 0.03 = 3 d0
      BOOST_TEST(std::abs(k - std::round(k)) < 1e-9);
    }
}

// A fluid particle pushed across the outlet's face by hand becomes an outlet particle with
// the outlet's pressure; one pushed past the far face in the same step is removed.
template <int D>
void captureTakesOutletPressure() {
  Duct<D> c(duct<D>(uniformInlet<D>(), -7.5));
  auto& P = c.s.particles;
  for (auto& u : P.velocity) u.setZero();  // only the particles moved by hand cross
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.isInlet(i)) P.velocity[i].setZero();
  std::vector<std::size_t> last;  // two fluid particles of the last column
  for (std::size_t i = 0; i < P.size() && last.size() < 2; ++i)
    if (P.isFluid(i) && P.position[i][0] > 0.09) last.push_back(i);
  BOOST_TEST_REQUIRE(last.size() == 2u);
  const std::size_t a = last[0], b = last[1];
  const std::int64_t idA = P.id[a], idB = P.id[b];
  P.pressure[a] = P.pressure[b] = 42;
  P.position[a][0] = 0.1005;  // just past the face
  P.position[b][0] = 0.1405;  // past the far face too
  const std::size_t n = P.size();
  c.s.dt = 0.01;  // every velocity is zero: only a and b have moved
  c.open->afterStep(c.s);
  c.s.refreshTypeMasks();
  BOOST_TEST(c.s.balance.captured == 2);
  BOOST_TEST(c.s.balance.released == 0);
  BOOST_TEST(c.s.size() == n - 1);
  bool foundA = false;
  for (std::size_t i = 0; i < P.size(); ++i) {
    BOOST_TEST(P.id[i] != idB);
    if (P.id[i] == idA) {
      foundA = true;
      BOOST_TEST(P.isOutlet(i));
      BOOST_TEST(P.pressure[i] == -7.5);
    }
  }
  BOOST_TEST(foundA);
}

// u = 4 Umax y (H - y) / H^2 (1 + t): every inlet particle carries it at the current time.
template <int D>
void expressionVelocity() {
  const std::string e = "{ type expression; value (\"4*0.15*y*(0.05-y)/0.05^2*(1+t)\" \"0\"" +
                        std::string(D == 3 ? " \"0\"" : "") + "); }";
  Duct<D> c(duct<D>(e, 0));
  auto check = [&](double t) {
    long n = 0;
    for (std::size_t i = 0; i < c.s.size(); ++i)
      if (c.s.particles.isInlet(i)) {
        const Vec<D>& x = c.s.particles.position[i];
        const double u = 4 * 0.15 * x[1] * (H - x[1]) / (H * H) * (1 + t);
        BOOST_TEST(std::abs(c.s.particles.velocity[i][0] - u) <= 1e-15);
        for (int k = 1; k < D; ++k) BOOST_TEST(c.s.particles.velocity[i][k] == 0.0);
        ++n;
      }
    BOOST_TEST(n == 4 * rows<D>());
  };
  check(0.0);
  BOOST_TEST(c.open->describe()[0].find("velocity (\"4*0.15*y*(0.05-y)/0.05^2*(1+t)\" \"0\"") != std::string::npos);
  // Ten steps later, at t = 0.2 s.
  for (int n = 0; n < 10; ++n) c.step(0.02);
  check(0.2);
  BOOST_TEST(c.s.balance.released > 0);
}

// The error a 3D duct gives with `from` replaced by `to` in its particlesDict.
std::string error3d(const std::string& from, const std::string& to) {
  std::string text = duct<3>(uniformInlet<3>(), 0);
  const std::size_t at = text.find(from);
  BOOST_TEST_REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  return test::errorOf([&] { Duct<3> c(text); });
}

}  // namespace

// An outlet particle carried back upstream by a backflow rejoins the fluid once it is more
// than d0/2 upstream of the face (within d0/2 it stays in the buffer), and the captured
// count gives it back, so the mass balance holds. Left an outlet particle, it wandered
// through the fluid as a p = 0 point and sank into the floor (docs/boundaries.md, "Backflow").
template <int D>
void backflowReturnsToFluid() {
  Duct<D> c(duct<D>(uniformInlet<D>(), 0.0));
  auto& P = c.s.particles;
  for (auto& u : P.velocity) u.setZero();
  std::vector<std::size_t> first;  // two outlet particles of the first buffer column
  for (std::size_t i = 0; i < P.size() && first.size() < 2; ++i)
    if (P.isOutlet(i) && P.position[i][0] < 0.1 + d0) first.push_back(i);
  BOOST_TEST_REQUIRE(first.size() == 2u);
  const std::size_t a = first[0], b = first[1];
  const std::size_t fluid0 = c.count(ParticleType::fluid), n = P.size();
  c.s.dt = 0.01;
  P.velocity[a][0] = -(0.005 + 0.006) / c.s.dt;  // from x = 0.105 to 0.094: 0.6 d0 upstream
  P.velocity[b][0] = -(0.005 + 0.004) / c.s.dt;  // to 0.096: 0.4 d0 upstream, stays
  c.open->afterStep(c.s);
  c.s.refreshTypeMasks();
  BOOST_TEST(P.size() == n);
  BOOST_TEST(P.isFluid(a));
  BOOST_TEST(P.isOutlet(b));
  BOOST_TEST(c.count(ParticleType::fluid) == fluid0 + 1);
  BOOST_TEST(c.s.balance.captured == -1);
  BOOST_TEST(long(c.count(ParticleType::fluid)) ==
             long(fluid0) + c.s.balance.released - c.s.balance.captured - c.s.balance.removedCount);
}

BOOST_AUTO_TEST_CASE(input_errors_3d) {
  const std::string in = "max (0 0.05 0.05); direction (1 0 0)", out = "max (0.14 0.05 0.05); direction (1 0 0)";
  const std::vector<std::array<std::string, 3>> cases = {
      {in, "max (0 0.05 0.05); direction (0 0 1)",
       "keyword 'direction': inlet 'inflow': direction (0 0 1) runs along the domain's side, not into it: the box spans "
       "the domain's centre (0.025 m) along z, so its face would meet a wall, not the fluid: did you mean direction (1 0 0)?"},
      {in, "max (0 0.05 0.05); direction (2 0 1)", "is oblique: inlets and outlets are boxes whose direction is an axis "
                                                   "(+-x, +-y, +-z); did you mean direction (1 0 0)?"},
      {out, "max (0.14 0.05 0.05); direction (-1 0 0)", "outlet 'outflow': direction (-1 0 0) points into the domain "
                                                        "(its centre lies at 0.05 m along x); an outlet's direction points "
                                                        "out of it: did you mean direction (1 0 0)?"},
      {out, "max (0.135 0.05 0.05); direction (1 0 0)", "keyword 'max': the length of outlet 'outflow' along its direction "
                                                        "is 0.035 m = 3.5 spacings (d0 = 0.01 m): it must be a whole number "
                                                        "of spacings; did you mean max (0.14 0.05 0.05)?"},
      {"min (-0.04 0 0); max (0 0.05 0.05)", "min (-0.02 0 0); max (0 0.05 0.05)",
       "keyword 'min': inlet 'inflow' is 0.02 m = 2 spacings long along its direction; it must cover the kernel support "
       "2h = 0.024 m (3 spacings), so that fluid at its face has all its neighbours: did you mean min (-0.03 0 0)?"}};
  for (const auto& [from, to, expected] : cases) {
    const std::string msg = error3d(from, to);
    BOOST_TEST_INFO("'" << to << "' gives: " << msg);
    BOOST_TEST(msg.find(expected) != std::string::npos);
    BOOST_TEST(msg.find("case/system/particlesDict:") == 0u);
  }
}

BOOST_AUTO_TEST_CASE(plug_flow_counts_2d) { plugFlowCounts<2>(); }
BOOST_AUTO_TEST_CASE(plug_flow_counts_3d) { plugFlowCounts<3>(); }
BOOST_AUTO_TEST_CASE(capture_takes_outlet_pressure_2d) { captureTakesOutletPressure<2>(); }
BOOST_AUTO_TEST_CASE(capture_takes_outlet_pressure_3d) { captureTakesOutletPressure<3>(); }
BOOST_AUTO_TEST_CASE(expression_velocity_2d) { expressionVelocity<2>(); }
BOOST_AUTO_TEST_CASE(expression_velocity_3d) { expressionVelocity<3>(); }
BOOST_AUTO_TEST_CASE(backflow_returns_to_fluid_2d) { backflowReturnsToFluid<2>(); }
BOOST_AUTO_TEST_CASE(backflow_returns_to_fluid_3d) { backflowReturnsToFluid<3>(); }
