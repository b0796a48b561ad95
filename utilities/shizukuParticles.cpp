// shizukuParticles: generate the initial particles of a case from
// system/particlesDict and write them as the start-time directory (0/), without
// running, so they can be looked at in ParaView before a run (docs/design.md 1.1).
//
//   shizukuParticles -case tutorials/damBreak
//
// Reads and checks the whole case like `shizuku -dryRun` (exit 1 with file, line
// and keyword on bad input); masses are calibrated as the solver does.
#include "core/CommandLine.hpp"
#include "core/Log.hpp"
#include "io/TimeName.hpp"
#include "isph/Simulation.hpp"
#include <boost/program_options.hpp>
#include <iostream>

namespace po = boost::program_options;
using namespace shizuku;

template <int D>
int generate(const std::string& dir) {
  SimulationOptions opt;
  opt.functionObjects = false;
  opt.postProcessing = true;  // start from particlesDict, ignore saved times
  Simulation<D> sim(dir, opt);
  sim.writeInitialParticles();
  const auto& P = sim.state().particles;
  info(cat("Wrote ", dir, "/", timeName(sim.state().time), "/particles.vtp: ", P.countFluid(), " fluid and ",
           P.size() - P.countFluid(), " wall particles, d0 = ", P.spacing, " m, particle mass ", P.mass));
  return 0;
}

int main(int argc, char** argv) {
  po::options_description desc("shizukuParticles: write the initial particles of a case\nOptions");
  desc.add_options()("help,h", "print this help and exit")(
      "case", po::value<std::string>()->default_value("."), "case directory");
  po::variables_map vm;
  if (auto status = parseCommandLine(argc, argv, "shizukuParticles", desc, vm)) return *status;
  const std::string dir = vm["case"].as<std::string>();
  try {
    return caseDimension(dir) == 3 ? generate<3>(dir) : generate<2>(dir);
  } catch (const std::exception& e) {
    Log::get().error(e.what());
    return 1;
  }
}
