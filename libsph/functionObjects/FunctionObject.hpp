// Function objects (docs/design.md 1.3): run-time measurements listed in the
// controlDict `functions { <name> { type <type>; writeControl ...; writeInterval ...; ... } }`,
// each built only when listed, each writing postProcessing/<name>/<startTime>/<file>.
// The same objects run over saved time directories in shizukuPostProcess, so a
// live run and post-processing give identical values at the same times.
#pragma once
#include "core/Dictionary.hpp"
#include "core/StageTimers.hpp"
#include "operators/FlowState.hpp"
#include "particles/WallBox.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

// What a function object may know about the run besides the flow state.
struct RunInfo {
  std::string caseDir;
  std::string startTimeName;     // names the postProcessing/<name>/<startTime>/ folder
  const StageTimers* timers = nullptr;  // nullptr in post-processing
  double wallSeconds = 0;        // since the run started
  double particleSteps = 0;      // fluid particles x steps since the run started
  bool isWriteTime = false;      // the solver writes a time directory at this step
  bool postProcessing = false;   // shizukuPostProcess: sample at every call, whatever writeControl says
  // Each inlet's and outlet's crossings since the run began; nullptr where unknown
  // (post-processing) or the case has none.
  const std::vector<BoundaryCrossings>* crossings = nullptr;
};

template <int D>
class FunctionObject {
 public:
  virtual ~FunctionObject() = default;
  virtual std::string name() const = 0;
  virtual std::string type() const = 0;
  virtual std::string describe() const = 0;
  // Called once before the first sample (opens files, writes headers).
  virtual void start(const FlowState<D>& s, const RunInfo& info) = 0;
  // Called after every step (and once at the start time); samples when its own
  // writeControl says so (default: every step).
  virtual void execute(const FlowState<D>& s, const RunInfo& info) = 0;
  // Flush and close.
  virtual void end() {}
};

// Build the function objects of a `functions` dictionary (nullptr or empty: none);
// `walls`: the case's wall regions (wallPressure sensors sit on their faces); `gravity`: the
// case's g (zero without constant/g), which a wallPressure reading the fluid side needs.
template <int D>
std::vector<std::unique_ptr<FunctionObject<D>>> createFunctionObjects(const Dictionary* functions,
                                                                      const std::vector<WallBox<D>>& walls = {},
                                                                      const Vec<D>& gravity = Vec<D>::Zero());

}  // namespace shizuku
