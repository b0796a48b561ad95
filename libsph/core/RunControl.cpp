// Reading and evaluating the run-control keys of system/controlDict, declared
// once below (keyword, default, range, meaning; docs/dictionaries.md is generated
// from these declarations).
#include "core/RunControl.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <cmath>

namespace shizuku {

namespace {

namespace key {

// Time bounds: a step below 1e-12 s is a unit slip in any SPH case; every time
// has the sane magnitude bound of 1e12 s.
const ParameterGroup controlDict("system/controlDict", "Run control; re-read while running (`stopAt writeNow;` stops a run).");
const OptionParameter startFrom = controlDict.option("startFrom", {"startTime", "latestTime"},
    "start from `startTime` or from the latest time directory").def("latestTime");
const ScalarParameter startTime = controlDict.scalar("startTime", dim::time,
    "start time when no time directory is read").def(0);
const OptionParameter stopAt = controlDict.option("stopAt", {"endTime", "writeNow"},
    "`writeNow` writes the current state and stops (edit while running)").def("endTime");
const ScalarParameter endTime = controlDict.scalar("endTime", dim::time, "end time (>= startTime)").required();
const ScalarParameter deltaT = controlDict.scalar("deltaT", dim::time,
    "time step (the first step with adjustTimeStep)").required().min(1e-12);
const ScalarParameter minDeltaT = controlDict.scalar("minDeltaT", dim::time,
    "smallest step the time loop takes; a smaller one (or one with t + dt == t) stops the run with exit 2")
    .def(0).shownDefault("1e-6 deltaT").above(0);
const SwitchParameter adjustTimeStep = controlDict.onOff("adjustTimeStep",
    "adapt the step to maxCo, viscosity, gravity and maxDeltaT").def(false);
const ScalarParameter maxCo = controlDict.scalar("maxCo", dim::none,
    "largest Courant number maxCo = dt max|U| / h (adjustTimeStep)").def(0.2).above(0).max(10);
const ScalarParameter maxDeltaT = controlDict.scalar("maxDeltaT", dim::time,
    "largest step with adjustTimeStep").def(1e300).shownDefault("unlimited").min(1e-12);
const OptionParameter writeControl = controlDict.option("writeControl", {"timeStep", "runTime", "adjustableRunTime"},
    "write every writeInterval steps, or seconds (adjustableRunTime lands on write times in equal steps: "
    "method.md 4.3)").def("timeStep");
const ScalarParameter writeInterval = controlDict.scalar("writeInterval", dim::none,
    "steps (timeStep) or seconds between writes").def(100).shownDefault("100 steps; endTime with a run-time writeControl")
    .above(0).max(1e12);
const OptionParameter writeFormat = controlDict.option("writeFormat", {"binary", "ascii"},
    "VTK data encoding of the time directories").def("binary");
const IntParameter progressInterval = controlDict.integer("progressInterval",
    "steps between progress lines in the log").def(100).min(1);


}  // namespace key

// t + deltaT must differ from t in double precision, at the start time and, with a fixed
// step, at the end time (the largest time reached); otherwise the run stands still.
void checkDeltaTAdvances(const Dictionary& d, const RunControl& rc) {
  auto stuck = [&](double t) { return !(t + rc.deltaT > t); };
  const char* which = stuck(rc.startTime) ? "startTime" : !rc.adjustTimeStep && stuck(rc.endTime) ? "endTime" : "";
  if (which[0] == '\0') return;
  const double t = which[0] == 's' ? rc.startTime : rc.endTime;
  d.error("deltaT", cat("deltaT ", rc.deltaT, " s does not advance the time at ", which, " ", t,
                        " s in double precision (", which, " + deltaT == ", which, "; the smallest step that does is about ",
                        std::nextafter(t, INFINITY) - t, " s)"));
}

}  // namespace

RunControl RunControl::read(const Dictionary& d) {
  RunControl rc;
  rc.startFrom = key::startFrom.read(d) == "startTime" ? StartFrom::startTime : StartFrom::latestTime;
  rc.startTime = key::startTime.read(d);
  rc.stopAt = key::stopAt.read(d) == "writeNow" ? StopAt::writeNow : StopAt::endTime;
  rc.endTime = key::endTime.read(d);
  rc.deltaT = key::deltaT.read(d);
  if (rc.endTime < rc.startTime) d.error("endTime", "must be >= startTime");
  rc.minDeltaT = key::minDeltaT.readOr(d, 1e-6 * rc.deltaT);
  if (rc.minDeltaT > rc.deltaT) d.error("minDeltaT", cat("must not exceed deltaT ", rc.deltaT, " s"));
  rc.adjustTimeStep = key::adjustTimeStep.read(d);
  rc.maxCo = key::maxCo.read(d);
  rc.maxDeltaT = key::maxDeltaT.read(d);
  checkDeltaTAdvances(d, rc);
  const std::string wc = key::writeControl.read(d);
  rc.writeControl = wc == "timeStep" ? WriteControl::timeStep
                    : wc == "runTime" ? WriteControl::runTime : WriteControl::adjustableRunTime;
  rc.writeInterval = rc.writeControl == WriteControl::timeStep ? key::writeInterval.readOr(d, 100.0)
                                                                : key::writeInterval.readOr(d, rc.endTime, dim::time);
  if (rc.writeControl == WriteControl::timeStep && rc.writeInterval != std::floor(rc.writeInterval))
    d.error("writeInterval", "must be a whole number of steps with writeControl timeStep");
  rc.ascii = key::writeFormat.read(d) == "ascii";
  rc.progressInterval = key::progressInterval.read(d);
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
