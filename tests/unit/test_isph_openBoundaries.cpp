// Inlets and outlets in the full ISPH step (docs/boundaries.md "Inlets and outlets"), on a
// short channel (2D) and square duct (3D) at U = 0.2 m/s, d0 = 1 cm:
//   - the pipeline (-dryRun, the log) has a line per inlet and outlet; the run ends without failure; fluid count = initial + released - captured - removed
//     exactly; ids unique and below nextId; every outlet particle holds the outlet's
//     pressure and every inlet particle the inlet's velocity; the inlet released
//     rows x round(U T / d0) particles (its particles move at U whatever the fluid does);
//   - a run of 32 steps equals, byte for byte, 16 steps + restart from the written state
//     + 16 steps, with particles released and captured in both halves (nextId, the
//     inlet velocities and the outlet pressures come back from the file); also with an
//     inlet velocity u(y, t) and the default iterative solver, restarted at step 25 of 40.
#define BOOST_TEST_MODULE isph_openBoundaries
#include <boost/test/unit_test.hpp>
#include "../support/TempCase.hpp"
#include "core/Log.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "isph/Simulation.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iomanip>
#include <set>
#include <sstream>

using namespace shizuku;

namespace {

constexpr double kU = 0.2, kD0 = 0.01, kOutletPressure = 2.0;
constexpr double kDt = 1.0 / 128;  // U dt = 0.156 d0; a power of two keeps time sums exact

const char* kUniform = "{ type uniform; value (0.2 0); }";
const char* kDirect = "pressure { solver UMFPACK; }\n";

// A channel (2D) or square duct (3D) of 0.1 m x H between a 4-spacing inlet and outlet.
// inlet: the inlet's velocity dictionary in 2D (3D: uniform); solver: system/sphSolution.
template <int D>
void writeDuct(test::TempCase& c, double endTime, double writeInterval, const std::string& inlet = kUniform,
               const std::string& solver = kDirect) {
  const std::string z0 = D == 3 ? " 0" : "", zH = D == 3 ? " 0.04" : "";
  const std::string H = D == 3 ? "0.04" : "0.05";
  const auto num = [](double x) { std::ostringstream os; os << std::setprecision(17) << x; return os.str(); };
  c.file("system/controlDict", "endTime " + num(endTime) + "; deltaT " + num(kDt) + "; writeControl runTime; writeInterval " +
                                   num(writeInterval) + "; progressInterval 1000;\n");
  c.file("system/particlesDict",
         "spacing 0.01;\nregions\n{\n"
         " water { type fluid; shape box; min (0 0" + z0 + "); max (0.1 " + H + zH +
             "); velocity { type uniform; value (0.2 0" + z0 + "); } }\n"
         " walls { type wall; shape box; min (-0.04 0" + z0 + "); max (0.14 " + H + zH + "); layers 3; open (left right); }\n"
         " inflow { type inlet; shape box; min (-0.04 0" + z0 + "); max (0 " + H + zH + "); direction (1 0" + z0 +
             "); velocity " + (D == 3 ? std::string("{ type uniform; value (0.2 0 0); }") : inlet) + " }\n"
         " outflow { type outlet; shape box; min (0.1 0" + z0 + "); max (0.14 " + H + zH + "); direction (1 0" + z0 +
             "); pressure 2; }\n}\n");
  // The channel tutorial's scheme: without shifting and volume correction the density
  // error of this 5-row channel grows with the travel (20 % after 3.75 d0).
  c.file("system/sphSchemes",
         "derivatives SPH2;\nshifting { distribution { type OPS; C 0.2; Rp 0.2; np 4; } volumeCorrection { C 0.1; }\n"
         "  surfaceFitting { C 1e-4; maxCurvature 0.2; minDistance 0.15; maxDistance 0.6; } maxShift 0.1; }\n"
         "ads { }\nxsph { epsilon 0.5; }\n");
  c.file("system/sphSolution", solver);
  c.file("constant/physicalProperties", "rho 1000; nu 1e-4;\n");
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

template <int D>
std::size_t count(const ParticleSet<D>& P, ParticleType t) {
  std::size_t n = 0;
  for (auto ty : P.type) n += ty == std::uint8_t(t);
  return n;
}

// rows > 0: a uniform inlet of U with that many rows (its velocity and release count are
// checked); 0: an expression inlet.
template <int D>
void checkState(const FlowState<D>& s, std::size_t fluid0, long rows) {
  const auto& P = s.particles;
  BOOST_TEST(long(count(P, ParticleType::fluid)) ==
             long(fluid0) + s.balance.released - s.balance.captured - s.balance.removedCount);
  std::set<std::int64_t> ids(P.id.begin(), P.id.end());
  BOOST_TEST(ids.size() == P.size());
  BOOST_TEST(*ids.rbegin() < P.nextId);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.isOutlet(i)) BOOST_TEST(P.pressure[i] == kOutletPressure);
    if (P.isInlet(i) && rows > 0) {
      BOOST_TEST(P.velocity[i][0] == kU);
      for (int k = 1; k < D; ++k) BOOST_TEST(P.velocity[i][k] == 0.0);
    }
  }
  const long columns = std::lround(std::floor(kU * s.time / kD0 + 0.5));
  BOOST_TEST_MESSAGE(D << "D: t = " << s.time << " s, released " << s.balance.released << ", captured "
                       << s.balance.captured << ", removed " << s.balance.removedCount << ", fluid "
                       << count(P, ParticleType::fluid) << " (initially " << fluid0 << ")");
  if (rows > 0) BOOST_TEST(s.balance.released == rows * columns);
}

template <int D>
void ductRuns(long rows) {
  test::TempCase c("duct");
  writeDuct<D>(c, 24 * kDt, 24 * kDt);
  SimulationOptions opt;
  opt.functionObjects = false;
  opt.threads = 1;  // ctest runs tests side by side on a shared machine
  Log::get().quiet = true;
  Simulation<D> sim(c.dir(), opt);
  const std::size_t fluid0 = count(sim.state().particles, ParticleType::fluid);
  // -dryRun and the log print the pipeline: a line per inlet and outlet.
  const std::string z0 = D == 3 ? " 0" : "", top = D == 3 ? " 0.04 0.04)" : " 0.05)";
  const std::string inletLine = "inlet 'inflow': box (-0.04 0" + z0 + ")-(0" + top + ", direction +x, velocity (0.2 0" + z0 +
                                ") m/s; releases fluid at its face, pressure by the wall rule\n";
  const std::string outletLine = "outlet 'outflow': box (0.1 0" + z0 + ")-(0.14" + top +
                                 ", direction +x, pressure 2 Pa; captures fluid at its face, velocity from the fluid (zero gradient)\n";
  BOOST_TEST_INFO(sim.pipeline());
  BOOST_TEST(sim.pipeline().find(inletLine) != std::string::npos);
  BOOST_TEST(sim.pipeline().find(outletLine) != std::string::npos);
  const int rc = sim.run();
  Log::get().quiet = false;
  BOOST_TEST_REQUIRE(rc == 0);
  BOOST_TEST(sim.state().step == 24);
  checkState(sim.state(), fluid0, rows);
  BOOST_TEST(sim.state().balance.captured > 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(channel_2d_runs_and_balances) { ductRuns<2>(5); }
BOOST_AUTO_TEST_CASE(square_duct_3d_runs_and_balances) { ductRuns<3>(16); }

// A 2D channel run of `steps` steps (written every `every`) against the same run restarted
// from its step `stop`: the last state byte for byte, particles released and captured in
// both parts. rows: as checkState.
void restartIsExact(const std::string& inlet, const std::string& solver, int steps, int every, int stop, long rows) {
  test::TempCase whole("openWhole"), split("openSplit");
  writeDuct<2>(whole, steps * kDt, every * kDt, inlet, solver);
  writeDuct<2>(split, steps * kDt, every * kDt, inlet, solver);
  SimulationOptions opt;
  opt.functionObjects = false;
  opt.threads = 1;  // ctest runs tests side by side on a shared machine
  Log::get().quiet = true;
  FluidBalance half, end;
  std::size_t fluid0 = 0;
  {
    Simulation<2> sim(whole.dir(), opt);
    fluid0 = count(sim.state().particles, ParticleType::fluid);
    BOOST_TEST_REQUIRE(sim.run() == 0);
    end = sim.state().balance;
    checkState(sim.state(), fluid0, rows);
  }
  // The split run gets only what the whole run had written up to step `stop`.
  namespace fs = std::filesystem;
  const std::string mid = timeName(stop * kDt), last = timeName(steps * kDt);
  for (const std::string& t : {std::string("0"), mid})
    fs::copy(fs::path(whole.dir()) / t, fs::path(split.dir()) / t, fs::copy_options::recursive);
  {
    Simulation<2> sim(split.dir(), opt);
    BOOST_TEST_REQUIRE(sim.state().step == stop);
    half = sim.state().balance;
    BOOST_TEST_REQUIRE(sim.run() == 0);
    checkState(sim.state(), fluid0, rows);
  }
  Log::get().quiet = false;
  BOOST_TEST_MESSAGE("restart at step " << stop << " of " << steps << ": first part released " << half.released << ", captured " << half.captured
                     << "; whole run: released " << end.released << ", captured " << end.captured);
  BOOST_TEST(half.released > 0);
  BOOST_TEST(half.captured > 0);
  BOOST_TEST(end.released > half.released);
  BOOST_TEST(end.captured > half.captured);
  const std::string a = readAll(whole.dir() + "/" + last + "/particles.vtp");
  const std::string b = readAll(split.dir() + "/" + last + "/particles.vtp");
  BOOST_TEST_REQUIRE(!a.empty());
  BOOST_TEST((a == b));  // every byte: positions, velocities, pressures, types, ids, nextId
  if (a != b) {
    TimeState ta, tb;
    const auto pa = readTimeDirectory<2>(whole.dir(), last, ta), pb = readTimeDirectory<2>(split.dir(), last, tb);
    BOOST_TEST_MESSAGE("sizes " << pa.size() << " vs " << pb.size() << ", nextId " << pa.nextId << " vs " << pb.nextId);
    double dx = 0, du = 0, dp = 0;
    for (std::size_t i = 0; i < std::min(pa.size(), pb.size()); ++i) {
      dx = std::max(dx, (pa.position[i] - pb.position[i]).norm());
      du = std::max(du, (pa.velocity[i] - pb.velocity[i]).norm());
      dp = std::max(dp, std::abs(pa.pressure[i] - pb.pressure[i]));
    }
    BOOST_TEST_MESSAGE("max |dx| " << dx << ", |du| " << du << ", |dp| " << dp);
  }
  BOOST_TEST(readAll(whole.dir() + "/" + last + "/uniform/time") == readAll(split.dir() + "/" + last + "/uniform/time"));
}

BOOST_AUTO_TEST_CASE(restart_with_inlets_and_outlets_is_bit_exact) { restartIsExact(kUniform, kDirect, 32, 16, 16, 5); }

// An inlet velocity that changes with t, and the default iterative solver (BiCGSTAB + AMG
// kept 10 steps, rebuilt after each write in both runs): restart at step 25 of 40.
BOOST_AUTO_TEST_CASE(restart_with_a_time_dependent_inlet_is_bit_exact) {
  restartIsExact("{ type expression; value (\"0.3*4*y*(0.05-y)/0.05^2*(1+2*t)\" \"0\"); }",
                 "pressure { solver BiCGSTAB; tolerance 1e-10; }\n", 40, 5, 25, 0);
}
