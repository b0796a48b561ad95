// conservation's fluidVolume (functionObjects/Conservation.hpp) against the known answer:
// the same N particles of an incompressible fluid, each holding d0^D, laid out as a
// block, then as ever thinner sheets (the block drawn out along x at constant volume,
// as a splash draws water into a sheet; the particles keep their spacing d0) down to a
// single row, always occupy N m/rho0. The old measure sum m/<rho> counts the truncated
// kernel sums of the surface particles and grows as the surface grows; fluidVolume
// counts only the interior particles' density and stays at the nominal volume; a block
// compressed to spacing 0.98 d0 shrinks by about 0.98^D in it. The
// state is analysed by the solver's own stages (Simulation::analyse: neighbours,
// density, the free-surface classes). 2D and 3D.
#define BOOST_TEST_MODULE isph_fluidVolume
#include <boost/test/unit_test.hpp>

#include "../support/TempCase.hpp"
#include "functionObjects/Conservation.hpp"
#include "isph/Simulation.hpp"
#include <cmath>

using namespace shizuku;

namespace {
// Layouts of the same count: {nx, ny[, nz]} with the product 576 (2D) or 1728 (3D).
template <int D>
std::vector<std::array<int, D>> layouts() {
  if constexpr (D == 2) return {{24, 24}, {72, 8}, {144, 4}, {288, 2}, {576, 1}};
  else return {{12, 12, 12}, {48, 12, 3}, {96, 9, 2}, {144, 12, 1}};
}

template <int D>
void drawnOut() {
  test::TempCase c(D == 2 ? "sheet2" : "sheet3");
  const std::string v = D == 2 ? "(0 0)" : "(0 0 0)", w = D == 2 ? "(0.24 0.24)" : "(0.12 0.12 0.12)";
  c.file("system/controlDict", "endTime 1; deltaT 0.1;\n");
  c.file("system/particlesDict", "spacing 0.01;\nregions { block { type fluid; shape box; min " + v + "; max " + w +
                                     "; } }\n");
  c.file("constant/physicalProperties", "rho 1000; nu 0;\n");
  SimulationOptions opt;
  opt.functionObjects = false;
  Simulation<D> sim(c.dir(), opt);
  auto& s = sim.state();
  const double d0 = 0.01, nominal = double(s.particles.countFluid()) * s.particles.mass / s.rho0;
  double previous = 0;
  for (const auto& n : layouts<D>()) {
    std::size_t i = 0;
    std::array<int, D> k{};
    for (; i < s.size(); ++i) {
      for (int a = 0; a < D; ++a) s.particles.position[i][a] = (k[a] + 0.5) * d0;
      for (int a = 0; a < D && ++k[a] == n[a]; ++a) k[a] = 0;
    }
    sim.analyse();
    const auto r = Conservation<D>::compute(s);
    long interior = 0;
    for (std::size_t j = 0; j < s.size(); ++j) interior += s.surfaceClass(j) == SurfaceClass::interior;
    BOOST_TEST_MESSAGE(D << "D, " << n[0] << " x " << n[1] << ": volume/nominal " << r.volume / nominal
                         << ", fluidVolume/nominal " << r.fluidVolume / nominal << ", interior particles " << interior);
    // interior particles sit on the lattice the mass is calibrated on: <rho> = rho0 to round-off
    BOOST_TEST(std::abs(r.fluidVolume / nominal - 1) < 1e-12);
    BOOST_TEST(r.volume / nominal > previous);  // the old measure grows as the sheet thins
    previous = r.volume / nominal;
  }
  BOOST_TEST(previous > 1.5);
  // A compressed block: every spacing 0.98 d0. The interior's <rho> rises by about
  // 1/0.98^D (the lattice sum of the kernel follows the integral to a fraction of a
  // per cent), so the interior particles' share of fluidVolume falls to about 0.98^D; a
  // measure that ignored the density would not move.
  {
    std::size_t i = 0;
    std::array<int, D> k{};
    const int side = D == 2 ? 24 : 12;
    for (; i < s.size(); ++i) {
      for (int a = 0; a < D; ++a) s.particles.position[i][a] = (k[a] + 0.5) * 0.98 * d0;
      for (int a = 0; a < D && ++k[a] == side; ++a) k[a] = 0;
    }
    sim.analyse();
    const auto r = Conservation<D>::compute(s);
    double interior = 0;
    for (std::size_t j = 0; j < s.size(); ++j) interior += s.surfaceClass(j) == SurfaceClass::interior;
    // interior particles hold 0.98^D of their share, the others (truncated kernels) theirs
    const double f = interior / double(s.size()), expected = 1 - f * (1 - std::pow(0.98, D));
    const double fraction = r.fluidVolume / nominal;
    BOOST_TEST_MESSAGE(D << "D, compressed by 0.98: fluidVolume/nominal " << fraction << ", expected " << expected
                         << " (interior fraction " << f << ")");
    BOOST_TEST(f > 0.1);
    BOOST_TEST(std::abs(fraction - expected) < 0.1 * (1 - expected));
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(fluid_volume_of_a_block_drawn_into_a_sheet_2d) { drawnOut<2>(); }
BOOST_AUTO_TEST_CASE(fluid_volume_of_a_block_drawn_into_a_sheet_3d) { drawnOut<3>(); }
