// Test helper: a whole run and a restarted one. `whole` runs to its endTime; `split` gets
// only the time directories `times` of the whole run (what it had written at the restart
// point) and runs from the latest of them to the same endTime. Both must exit 0.
#pragma once
#include "core/Log.hpp"
#include "isph/Simulation.hpp"
#include "TempCase.hpp"
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <vector>

namespace shizuku::test {

template <int D>
void runWholeAndRestarted(const TempCase& whole, const TempCase& split, const std::vector<const char*>& times) {
  SimulationOptions opt;
  opt.functionObjects = false;
  Log::get().quiet = true;
  { Simulation<D> sim(whole.dir(), opt); BOOST_TEST_REQUIRE(sim.run() == 0); }
  namespace fs = std::filesystem;
  for (const char* t : times) fs::copy(fs::path(whole.dir()) / t, fs::path(split.dir()) / t, fs::copy_options::recursive);
  { Simulation<D> sim(split.dir(), opt); BOOST_TEST_REQUIRE(sim.run() == 0); }
  Log::get().quiet = false;
}

}  // namespace shizuku::test
