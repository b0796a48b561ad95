// shizuku: the ISPH solver (docs/design.md 1.1).
//
//   shizuku -case tutorials/damBreak          run the case
//   mpirun -np N shizuku -case DIR -parallel  run on N ranks (docs/parallel.md)
//   shizuku -case DIR -dryRun                 read and check everything, print the pipeline, exit 0
//   shizuku -case DIR -noFunctionObjects      run without function objects
//   shizuku -version                          print the version and the commit it was built from
//   shizuku -keywords markdown [-scope S]     print the keyword tables of every dictionary
//                                             scope (or of scope S) from the declarations
//   shizuku -keywords scopes                  list the declared dictionary scopes
//
// Reads the case directory, generates the initial particles from
// system/particlesDict when 0/ holds none, runs the time loop and writes time
// directories, particles.pvd and postProcessing/. Exit status: 0 success,
// 1 bad input (message names file, line and keyword), 2 numerical failure
// (after writing the last good state).
#include "core/CommandLine.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include "isph/Simulation.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/RankStart.hpp"
#include "ShizukuCommit.hpp"  // generated at build time (cmake/ShizukuCommit.cmake)
#include <boost/program_options.hpp>
#include <ctime>
#include <iostream>
#include <new>
#include <omp.h>
#include <unistd.h>

namespace po = boost::program_options;
using namespace shizuku;

namespace {

// "Shizuku <version> (commit <short sha>[-dirty])", or "(commit unknown)" when
// built outside a git work tree.
constexpr const char* kVersion = "Shizuku " SHIZUKU_VERSION " (commit " SHIZUKU_COMMIT ")";

template <int D>
int runCase(const std::string& dir, bool dryRun, bool functionObjects) {
  SimulationOptions opt;
  opt.functionObjects = functionObjects;
  Simulation<D> sim(dir, opt);
  if (dryRun) {
    info(sim.pipeline());
    for (const auto& d : Dictionary::defaultsUsed()) info("default: " + d);
    info(describeParametersInEffect());
    info("Dry run: the case is valid; nothing was run or written.");
    return 0;
  }
  info(describeParametersInEffect());
  return sim.run();
}

// -keywords markdown|scopes: the catalogue of declared parameters, no case needed.
int printKeywords(const std::string& format, const std::string& scope) {
  if (format == "scopes") {
    for (const auto& s : parameterScopes()) std::cout << s << "\n";
    return 0;
  }
  if (format != "markdown") {
    std::cerr << "Error: -keywords takes markdown or scopes, not '" << format << "'\n";
    return 1;
  }
  if (scope.empty()) {
    std::cout << keywordTablesMarkdown();
    return 0;
  }
  const std::string table = keywordTableMarkdown(scope);
  if (table.empty()) {
    std::cerr << "Error: no parameters are declared in scope '" << scope << "' (shizuku -keywords scopes lists them)\n";
    return 1;
  }
  std::cout << table;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  po::options_description desc("shizuku: incompressible SPH (ISPH) solver for free-surface flow\nOptions");
  desc.add_options()
      ("help,h", "print this help and exit")
      ("version", "print the version and the commit the program was built from, and exit")
      ("case", po::value<std::string>()->default_value("."), "case directory (default: the current folder)")
      ("dryRun", "read and check the whole case, print the active pipeline and exit 0 without running")
      ("noFunctionObjects", "run without function objects")
      ("parallel", "run on the ranks the MPI launcher started: mpirun -np N shizuku -case DIR -parallel")
      ("keywords", po::value<std::string>(), "print the declared keywords and exit: markdown (tables) or scopes")
      ("scope", po::value<std::string>()->default_value(""), "with -keywords markdown: only this dictionary scope")
      ("threads", po::value<int>(), "OpenMP threads, 1 to 4 x the hardware threads (default: OMP_NUM_THREADS or all cores)");
  installStopSignalHandlers();  // a signal during a long set-up stops cleanly too
  po::variables_map vm;
  if (auto status = parseCommandLine(argc, argv, "shizuku", desc, vm,
                                     "Exit status: 0 success, 1 bad input, 2 numerical failure.\n"))
    return *status;
  if (vm.count("version")) {
    std::cout << kVersion << "\n";
    return 0;
  }
  if (vm.count("keywords")) return printKeywords(vm["keywords"].as<std::string>(), vm["scope"].as<std::string>());
  if (auto status = startRanks(vm.count("parallel"), "shizuku", &argc, &argv)) return *status;
  const std::string dir = vm["case"].as<std::string>();
  if (auto status = applyThreadsOption(vm, "shizuku")) return *status;

  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  char host[256] = "?";
  gethostname(host, sizeof host);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
  info(cat(kVersion, " - incompressible SPH with SPH(2) operators and density-corrected shifting"));
  info(cat("Command : ", command));
  info(cat("Case    : ", dir));
  if (Communicator::world().started()) info(cat("Ranks   : ", Communicator::world().size()));
  info(cat("Threads : ", omp_get_max_threads()));
  info(cat("Host    : ", host));
  info(cat("Date    : ", date));
  info("");
  // An error ends the run with its status. On several ranks an error that only some ranks
  // met (the others wait for them in a collective) stops the whole run instead, naming the
  // rank (only rank 0 writes the log).
  const auto fail = [](int status, const std::string& message) {
    Log::get().error(message);
    const auto& world = Communicator::world();
    if (world.isParallel() && !world.everyRankFailed(30.0)) {
      if (!world.isRoot()) std::cerr << "Error: rank " << world.rank() << ": " << message << std::endl;
      world.abort(status);
    }
    return status;
  };
  try {
    const int dimension = caseDimension(dir);
    return dimension == 3 ? runCase<3>(dir, vm.count("dryRun"), !vm.count("noFunctionObjects"))
                          : runCase<2>(dir, vm.count("dryRun"), !vm.count("noFunctionObjects"));
  } catch (const InputError& e) {
    return fail(1, e.what());
  } catch (const NumericalError& e) {
    return fail(2, e.what());
  } catch (const std::bad_alloc&) {
    // Set-up checks the memory before allocating particles (particles/MemoryCheck.hpp);
    // anything that still runs out ends here, with every time directory already written kept.
    return fail(1, cat("out of memory: an allocation failed in case '", dir, "'; the case needs more memory than "
                       "the machine (or ulimit -v) gives: use a larger spacing or fewer particles"));
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}
