// The time loop of a run (docs/design.md 1.3, docs/method.md 4.3): the time-step choice,
// the step, leaks and the removal of fluid that left the domain (Outflow), the health check, writes that land on the write interval, stop requests
// (signals, `stopAt writeNow`), function objects, the progress line and the summary.
// After a numerical failure it writes the last good state and returns exit status 2.
// Reads the RunControl of system/controlDict (startTime, endTime, deltaT, adjustTimeStep,
// maxCo, maxDeltaT, minDeltaT, writeControl, writeInterval, writeFormat, progressInterval).
#pragma once
#include "core/RunControl.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "isph/CaseFiles.hpp"
#include "isph/HealthGuard.hpp"
#include "isph/IsphStep.hpp"
#include "isph/Outflow.hpp"
#include "isph/StopRequests.hpp"
#include "isph/TimeStepFloor.hpp"
#include <memory>
#include <string>
#include <vector>

namespace shizuku {

template <int D>
class TimeLoop {
 public:
  TimeLoop(const CaseFiles& files, const RunControl& rc, FlowState<D>& s, IsphStep<D>& step, HealthGuard<D>& guard,
           Outflow<D>& outflow, std::vector<std::unique_ptr<FunctionObject<D>>>& functionObjects, StageTimers& timers,
           const std::string& startTimeName);
  // Runs from the current state to endTime; returns 0, or 2 after a numerical failure.
  int run(const std::string& pipeline);
  // dt for the next step: fixed, or the smallest of the CFL limit, the effects' limits,
  // maxDeltaT and 1.2 x the previous step, shortened to land on write and end times.
  // Each step's dt must pass the floor (TimeStepFloor.hpp: minDeltaT, t + dt > t).
  double chooseDeltaT(double previous, double nextWrite);
  double fluidCount() const;

 private:
  void start();
  // One step with its check, writes and function objects; true when the run must stop.
  bool advanceOneStep(double& previousDt, double& particleSteps, double wallStart, ControlDictWatch& watch);
  // Whether a stop request is due now (see the .cpp).
  bool stopDue(ControlDictWatch& watch);
  void writeLastGoodState(const NumericalError& e);
  void writeTime(const std::string& reason);
  void runFunctionObjects(bool isWriteTime, double wall, double particleSteps);
  bool atEnd() const { return s_.time >= rc_.endTime - rc_.timeTolerance(); }

  const CaseFiles& files_;
  const RunControl& rc_;
  FlowState<D>& s_;
  IsphStep<D>& step_;
  HealthGuard<D>& guard_;
  Outflow<D>& outflow_;
  std::vector<std::unique_ptr<FunctionObject<D>>>& functionObjects_;
  StageTimers& timers_;
  std::string startTimeName_;
  int functionObjectTimer_, outputTimer_;
  std::vector<std::string> written_;
  bool writtenAtCurrentTime_ = false;
  std::string stopRequest_;  // what asked the run to stop (empty: nothing yet)
  int signalsAtRequest_ = 0;
  bool stopDeferralLogged_ = false;
  double startTime_ = 0, span_ = 1;
  double fluidCount_ = 0;
  TimeStepChoice choice_;  // the limits the last chooseDeltaT compared
};

}  // namespace shizuku
