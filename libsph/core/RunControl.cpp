// Reading and evaluating the run-control keys of system/controlDict.
#include "core/RunControl.hpp"
#include <cmath>

namespace shizuku {

RunControl RunControl::read(const Dictionary& d) {
  RunControl rc;
  rc.startFrom = d.getOptionOr("startFrom", {"startTime", "latestTime"}, "latestTime") == "startTime"
                     ? StartFrom::startTime : StartFrom::latestTime;
  rc.startTime = d.getScalarOr("startTime", 0.0, dim::time);
  rc.stopAt = d.getOptionOr("stopAt", {"endTime", "writeNow"}, "endTime") == "writeNow" ? StopAt::writeNow
                                                                                       : StopAt::endTime;
  rc.endTime = d.getScalar("endTime", dim::time);
  rc.deltaT = d.getScalar("deltaT", dim::time);
  if (!(rc.deltaT > 0) || !std::isfinite(rc.deltaT)) d.error("deltaT", "must be a positive number");
  if (!std::isfinite(rc.endTime) || rc.endTime < rc.startTime) d.error("endTime", "must be >= startTime");
  rc.adjustTimeStep = d.getSwitchOr("adjustTimeStep", false);
  rc.maxCo = d.getScalarOr("maxCo", 0.2, dim::none);
  if (!(rc.maxCo > 0)) d.error("maxCo", "must be > 0");
  rc.maxDeltaT = d.getScalarOr("maxDeltaT", 1e300, dim::time);
  if (!(rc.maxDeltaT > 0)) d.error("maxDeltaT", "must be > 0");
  const std::string wc = d.getOptionOr("writeControl", {"timeStep", "runTime", "adjustableRunTime"}, "timeStep");
  rc.writeControl = wc == "timeStep" ? WriteControl::timeStep
                    : wc == "runTime" ? WriteControl::runTime : WriteControl::adjustableRunTime;
  rc.writeInterval = d.getScalarOr("writeInterval", rc.writeControl == WriteControl::timeStep ? 100.0 : rc.endTime,
                                   rc.writeControl == WriteControl::timeStep ? dim::none : dim::time);
  if (!(rc.writeInterval > 0)) d.error("writeInterval", "must be > 0");
  if (rc.writeControl == WriteControl::timeStep && rc.writeInterval != std::floor(rc.writeInterval))
    d.error("writeInterval", "must be a whole number of steps with writeControl timeStep");
  rc.ascii = d.getOptionOr("writeFormat", {"binary", "ascii"}, "binary") == "ascii";
  rc.progressInterval = d.getIntOr("progressInterval", 100);
  if (rc.progressInterval <= 0) d.error("progressInterval", "must be > 0");
  d.markRead("functions");
  d.markRead("healthChecks");
  return rc;
}

double RunControl::nextWriteTime(double t) const {
  const double k = std::floor((t - startTime) / writeInterval + 1e-9) + 1;
  return startTime + k * writeInterval;
}

bool RunControl::isWriteStep(double time, long stepIndex) const {
  if (writeControl == WriteControl::timeStep) return stepIndex % long(writeInterval) == 0;
  const double k = (time - startTime) / writeInterval;
  const double tol = writeControl == WriteControl::adjustableRunTime ? 1e-6 : 0.5 * deltaT / writeInterval;
  return std::abs(k - std::round(k)) < tol;
}

}  // namespace shizuku
