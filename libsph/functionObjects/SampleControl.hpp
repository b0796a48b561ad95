// When a function object samples (docs/design.md 1.3): its own
//   writeControl  timeStep | runTime | adjustableRunTime | writeTime;
//   writeInterval N (steps, timeStep) | seconds (runTime, adjustableRunTime);
// (defaults and ranges declared in SampleControl.cpp)
// timeStep:   sample when step % N == 0;
// runTime / adjustableRunTime (the same here: the solver adjusts dt only for its
//             own write times): sample when floor(t / interval) has advanced
//             since the last sample (a time within a small tolerance below a
//             multiple counts as reaching it);
// writeTime:  sample when the solver writes a time directory (RunInfo::isWriteTime).
// The first call (the run's start time) always samples, so a restarted run
// starts its new file with the state it starts from.
// Reads (controlDict functions/<name>): writeControl, writeInterval.
#pragma once
#include "core/Dictionary.hpp"
#include <string>

namespace shizuku {

class SampleControl {
 public:
  enum class Mode { timeStep, runTime, adjustableRunTime, writeTime };

  static SampleControl read(const Dictionary& dict);
  // Decide whether the call at (time, step) samples, and remember it if so.
  bool due(double time, double dt, long step, bool isWriteTime);
  // "every step", "every 0.1 s", "at write times", ...
  std::string describe() const;

  Mode mode() const { return mode_; }
  double interval() const { return interval_; }

 private:
  Mode mode_ = Mode::timeStep;
  double interval_ = 1;
  bool first_ = true;
  long lastIndex_ = 0;
};

}  // namespace shizuku
