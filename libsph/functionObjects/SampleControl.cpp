// Sampling schedule of one function object: see SampleControl.hpp.
#include "functionObjects/SampleControl.hpp"
#include "core/Log.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

SampleControl SampleControl::read(const Dictionary& d) {
  SampleControl c;
  const std::string m =
      d.getOptionOr("writeControl", {"timeStep", "runTime", "adjustableRunTime", "writeTime"}, "timeStep");
  c.mode_ = m == "timeStep" ? Mode::timeStep
            : m == "runTime" ? Mode::runTime
            : m == "adjustableRunTime" ? Mode::adjustableRunTime : Mode::writeTime;
  if (c.mode_ == Mode::timeStep) {
    c.interval_ = d.getIntOr("writeInterval", 1);
    if (c.interval_ < 1) d.error("writeInterval", "must be a whole number of steps >= 1 with writeControl timeStep");
  } else if (c.mode_ == Mode::writeTime) {
    if (d.found("writeInterval")) d.error("writeInterval", "is not used with writeControl writeTime; remove it");
  } else {
    c.interval_ = d.getScalar("writeInterval", dim::time);
    if (!(c.interval_ > 0) || !std::isfinite(c.interval_)) d.error("writeInterval", "must be a positive time");
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
