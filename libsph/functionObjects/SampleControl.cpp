// Sampling schedule of one function object: see SampleControl.hpp.
#include "functionObjects/SampleControl.hpp"
#include "core/Log.hpp"
#include "core/Parameter.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

namespace {
const ParameterGroup sampling("system/controlDict: functions/<name>",
    "Keys of every function object: its type and when it samples.");
const OptionParameter writeControl = sampling.option("writeControl",
    {"timeStep", "runTime", "adjustableRunTime", "writeTime"}, "sample every writeInterval steps or seconds, or at write times")
    .def("timeStep");
const ScalarParameter writeInterval = sampling.scalar("writeInterval", dim::none,
    "steps (timeStep) or seconds between samples; not with writeTime")
    .def(1).shownDefault("1 step; required with a run-time writeControl").above(0).max(1e12);
}  // namespace

SampleControl SampleControl::read(const Dictionary& d) {
  SampleControl c;
  const std::string m = writeControl.read(d);
  c.mode_ = m == "timeStep" ? Mode::timeStep
            : m == "runTime" ? Mode::runTime
            : m == "adjustableRunTime" ? Mode::adjustableRunTime : Mode::writeTime;
  if (c.mode_ == Mode::timeStep) {
    c.interval_ = writeInterval.readOr(d, 1.0);
    if (c.interval_ < 1 || c.interval_ != std::floor(c.interval_))
      d.error("writeInterval", "must be a whole number of steps >= 1 with writeControl timeStep");
  } else if (c.mode_ == Mode::writeTime) {
    if (d.found("writeInterval")) d.error("writeInterval", "is not used with writeControl writeTime; remove it");
  } else {
    if (!d.found("writeInterval")) d.getScalar("writeInterval", dim::time);  // missing: an error naming it
    c.interval_ = writeInterval.readOr(d, 0.0, dim::time);
  }
  return c;
}

bool SampleControl::due(double time, double dt, long step, bool isWriteTime) {
  bool sample = first_;
  switch (mode_) {
    case Mode::timeStep:
      sample = sample || step % long(interval_) == 0;
      break;
    case Mode::writeTime:
      sample = sample || isWriteTime;
      break;
    case Mode::runTime:
    case Mode::adjustableRunTime: {
      // Tolerance: a time this close below a multiple of the interval has reached it
      // (round-off in accumulated time steps); at most half a step.
      double tol = 1e-6 * interval_;
      if (dt > 0) tol = std::min(tol, 0.5 * dt);
      const long index = long(std::floor((time + tol) / interval_));
      sample = sample || index > lastIndex_;
      if (sample) lastIndex_ = index;
      break;
    }
  }
  first_ = false;
  return sample;
}

std::string SampleControl::describe() const {
  switch (mode_) {
    case Mode::timeStep: return interval_ == 1 ? "every step" : cat("every ", long(interval_), " steps");
    case Mode::writeTime: return "at write times";
    default: return cat("every ", interval_, " s");
  }
}

}  // namespace shizuku
