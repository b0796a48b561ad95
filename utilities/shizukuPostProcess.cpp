// shizukuPostProcess: run one function object over saved time directories
// (docs/design.md 1.1, 1.3), writing the files a live run writes.
//
//   shizukuPostProcess -case tutorials/damBreak -func densityError
//   shizukuPostProcess -case DIR -func centre -time 0.1:0.5
//   shizukuPostProcess -case DIR -func conservation -time latestTime
//
// NAME is an entry of the controlDict `functions` (its settings are used), or
// a function-object type (probes needs points, so it must be an entry; the
// others run with default settings). For each selected time the saved
// particles are read and the analysis state of those positions is rebuilt
// exactly as the solver computes it at the start of a step (neighbours,
// summation density, free-surface classes, operator weights); the object then
// samples once per time, whatever its writeControl says. So the numbers equal
// those of a live run at the same times (tests/post/). Output goes to
// postProcessing/<NAME>/<first selected time>/; if that folder exists (a live
// run or an earlier post-processing wrote it) the program stops unless
// -overwrite is given. The output is all or nothing: it is written to
// <first time>.tmp-<pid>/ and replaces the folder only when every time has been
// processed; a time that cannot be read is an error naming it, and the folder
// stays as it was. `timing` measures a live run: here it does nothing.
// Exit status: 0 success, 1 bad input.
#include "core/CommandLine.hpp"
#include "core/Log.hpp"
#include "functionObjects/FunctionObjectFactory.hpp"
#include "functionObjects/TimeSelection.hpp"
#include "io/FileOps.hpp"
#include "io/TimeDirectory.hpp"
#include "isph/Simulation.hpp"
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <omp.h>
#include <unistd.h>

namespace po = boost::program_options;
namespace fs = std::filesystem;
using namespace shizuku;

namespace {

// The output of one post-processing goes to <out>.tmp-<pid> and replaces <out>
// only when every selected time has been processed: a failure leaves <out> (an
// earlier run's, or none) as it was and removes the staging folder, and the
// postProcessing folders it created when they are left empty.
struct Staging {
  std::string out, folder, name;  // name: the folder's last part, the function object's "start time"
  std::vector<std::string> created;
  bool published = false;
  explicit Staging(const std::string& target) : out(target) {
    name = fs::path(out).filename().string() + ".tmp-" + std::to_string(::getpid());
    folder = fileops::parentOf(out) + "/" + name;
    removeStaleTemporaries(fileops::parentOf(out));  // leftovers of a killed post-processing
    for (std::string p = fileops::parentOf(out); !fs::exists(p); p = fileops::parentOf(p)) created.push_back(p);
  }
  ~Staging() {
    if (published) return;
    fileops::removeTree(folder);
    std::error_code ec;
    for (const auto& p : created) fs::remove(p, ec);  // only when empty
  }
  void publish() {
    if (!fileops::isDirectory(out)) fileops::renamePath(folder, out);
    else if (fileops::exchangePaths(folder, out)) fileops::removeTree(folder);  // atomic; folder: the old output
    else {
      fileops::removeTree(out);
      fileops::renamePath(folder, out);
    }
    published = true;
  }
};

// Runs `object` over the selected times, its files named by `startName`. A time
// that cannot be read is an InputError naming it.
template <int D>
void processTimes(Simulation<D>& sim, FunctionObject<D>& object, const std::vector<std::pair<double, std::string>>& selected,
                  const std::string& dir, const std::string& startName) {
  RunInfo run;
  run.caseDir = dir;
  run.startTimeName = startName;
  run.postProcessing = true;
  run.isWriteTime = true;  // every saved time is a write time
  bool started = false;
  for (const auto& [t, name] : selected) {
    try {
      sim.loadTime(name);
    } catch (const std::exception& e) {
      throw InputError("time " + name + " (" + dir + "/" + name + ") cannot be read, so nothing was written: " +
                       e.what());
    }
    if (!started) {
      object.start(sim.state(), run);
      started = true;
    }
    object.execute(sim.state(), run);
    info("  time " + name);
  }
  object.end();
}

template <int D>
int postProcess(const std::string& dir, const std::string& func, const std::string& times, bool overwrite) {
  // The function object: a controlDict entry, or a type with default settings.
  const Dictionary control = Dictionary::fromFile(dir + "/system/controlDict");
  const Dictionary* functions = control.subDictPtr("functions");
  Dictionary defaults;
  const Dictionary* settings = nullptr;
  if (functions && functions->found(func) && functions->isDict(func)) {
    settings = &functions->subDict(func);
  } else {
    const auto types = functionObjectTypes();
    if (std::find(types.begin(), types.end(), func) == types.end()) {
      std::string entries, typeList;
      if (functions)
        for (const auto& k : functions->keys()) entries += " " + k;
      for (const auto& t : types) typeList += " " + t;
      throw InputError("-func " + func + ": not an entry of " + dir + "/system/controlDict functions (" +
                       (entries.empty() ? "none" : entries.substr(1)) + ") nor a function-object type (" +
                       typeList.substr(1) + ")");
    }
    defaults = Dictionary::fromString("type " + func + ";", "-func " + func);
    settings = &defaults;
  }
  auto object = createFunctionObject<D>(func, *settings);
  settings->checkAllRead();
  if (object->type() == "timing") {  // before anything is touched: a live run's timing.dat stays
    info("timing '" + func + "' measures the stages of a live run; there is nothing to post-process");
    return 0;
  }

  const auto selected = selectTimes(listTimeDirectories(dir), times);
  if (selected.empty()) throw InputError("no saved time directory in " + dir);
  const std::string out = dir + "/postProcessing/" + func + "/" + selected.front().second;
  if (fs::exists(out) && !overwrite)
    throw InputError(out + " exists (written by a run or an earlier post-processing); use -overwrite to replace it");
  SimulationOptions opt;
  opt.postProcessing = true;
  Simulation<D> sim(dir, opt);
  info(cat(object->describe(), ": ", selected.size(), " time", selected.size() == 1 ? "" : "s", ", output ", out));
  Staging staging(out);
  processTimes(sim, *object, selected, dir, staging.name);
  object.reset();  // closes the files
  staging.publish();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  po::options_description desc(
      "shizukuPostProcess: run a function object over saved time directories, writing the files a live run writes\n"
      "Options");
  desc.add_options()
      ("help,h", "print this help and exit")
      ("case", po::value<std::string>()->default_value("."), "case directory (default: the current folder)")
      ("func", po::value<std::string>(), "function object: an entry of controlDict `functions`, or a type "
                                         "(densityError conservation fluidExtent) with default settings")
      ("time", po::value<std::string>()->default_value(""),
       "times: 0.1,0.2 | 0.1:0.5 | :0.5 | 0.5: | latestTime | firstTime | all (default: every saved time)")
      ("overwrite", "replace postProcessing/<func>/<first time>/ if it exists")
      ("threads", po::value<int>(), "OpenMP threads, 1 to 4 x the hardware threads (default: OMP_NUM_THREADS or all cores)");
  po::variables_map vm;
  if (auto status = parseCommandLine(argc, argv, "shizukuPostProcess", desc, vm,
                                     "Exit status: 0 success, 1 bad input.\n", "func"))
    return *status;
  if (auto status = applyThreadsOption(vm, "shizukuPostProcess")) return *status;
  const std::string dir = vm["case"].as<std::string>();
  try {
    const int dimension = caseDimension(dir);
    const std::string func = vm["func"].as<std::string>(), times = vm["time"].as<std::string>();
    return dimension == 3 ? postProcess<3>(dir, func, times, vm.count("overwrite"))
                          : postProcess<2>(dir, func, times, vm.count("overwrite"));
  } catch (const std::bad_alloc&) {
    Log::get().error("out of memory: an allocation failed in case '" + dir + "'");
    return 1;
  } catch (const std::exception& e) {
    Log::get().error(e.what());
    return 1;
  }
}
