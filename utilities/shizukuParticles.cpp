// shizukuParticles: generate the initial particles of a case from
// system/particlesDict and write them as the start-time directory (0/), without
// running, so they can be looked at in ParaView before a run (docs/design.md 1.1).
//
//   shizukuParticles -case tutorials/damBreak
//
// Reads and checks the whole case like `shizuku -dryRun` (exit 1 with file, line
// and keyword on bad input); masses are calibrated as the solver does.
// A case that holds other time directories (a run's results) is refused, naming
// them, unless -overwrite is given: the new 0/ would not be what they started
// from. A start folder holding files of the user's is never replaced.
#include "core/CommandLine.hpp"
#include "core/Log.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "isph/Simulation.hpp"
#include <boost/program_options.hpp>
#include <iostream>

namespace po = boost::program_options;
using namespace shizuku;

// Time directories of the case other than `start`: the results of a run.
std::string otherTimes(const std::string& dir, const std::string& start) {
  std::string list;
  for (const auto& t : listTimeDirectories(dir))
    if (t.second != start) list += " " + t.second;
  return list;
}

template <int D>
int generate(const std::string& dir, bool overwrite) {
  SimulationOptions opt;
  opt.functionObjects = false;
  opt.postProcessing = true;  // start from particlesDict, ignore saved times
  Simulation<D> sim(dir, opt);
  const std::string start = timeName(sim.state().time), later = otherTimes(dir, start);
  if (!later.empty()) {
    if (!overwrite)
      throw InputError(dir + " holds the results of a run (time directories" + later + "): writing " + dir + "/" + start +
                       " from particlesDict would replace the particles they started from; remove those time "
                       "directories first, or give -overwrite to replace " + dir + "/" + start + " anyway");
    Log::get().warning("-overwrite: replacing " + dir + "/" + start + "; the time directories" + later + " stay as they are");
  }
  sim.writeInitialParticles();
  const auto& P = sim.state().particles;
  info(cat("Wrote ", dir, "/", timeName(sim.state().time), "/particles.vtp: ", P.countFluid(), " fluid and ",
           P.size() - P.countFluid(), " wall particles, d0 = ", P.spacing, " m, particle mass ", P.mass));
  return 0;
}

int main(int argc, char** argv) {
  po::options_description desc("shizukuParticles: write the initial particles of a case\nOptions");
  desc.add_options()("help,h", "print this help and exit")(
      "case", po::value<std::string>()->default_value("."), "case directory")(
      "overwrite", "write 0/ even when the case holds the time directories of a run");
  po::variables_map vm;
  if (auto status = parseCommandLine(argc, argv, "shizukuParticles", desc, vm)) return *status;
  const std::string dir = vm["case"].as<std::string>();
  try {
    return caseDimension(dir) == 3 ? generate<3>(dir, vm.count("overwrite")) : generate<2>(dir, vm.count("overwrite"));
  } catch (const std::exception& e) {
    Log::get().error(e.what());
    return 1;
  }
}
