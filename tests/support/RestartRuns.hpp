// Test helpers that run a case's whole time loop through Simulation::run, the log quiet:
//  - runQuietly: one run to its endTime (it must exit 0); the simulation is returned for
//    the state it ended in;
//  - runWholeAndRestarted: a whole run and a restarted one. `whole` runs to its endTime;
//    `split` gets only the time directories `times` of the whole run (what it had written
//    at the restart point) and runs from the latest of them to the same endTime.
#pragma once
#include "core/Log.hpp"
#include "isph/Simulation.hpp"
#include "TempCase.hpp"
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <memory>
#include <vector>

namespace shizuku::test {

template <int D>
std::unique_ptr<Simulation<D>> runQuietly(const TempCase& c) {
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  auto sim = std::make_unique<Simulation<D>>(c.dir(), opt);
  const int status = sim->run();
  Log::get().quiet = false;
  BOOST_TEST_REQUIRE(status == 0);
  return sim;
}

template <int D>
void runWholeAndRestarted(const TempCase& whole, const TempCase& split, const std::vector<const char*>& times) {
  runQuietly<D>(whole);
  namespace fs = std::filesystem;
  for (const char* t : times) fs::copy(fs::path(whole.dir()) / t, fs::path(split.dir()) / t, fs::copy_options::recursive);
  runQuietly<D>(split);
}

}  // namespace shizuku::test
