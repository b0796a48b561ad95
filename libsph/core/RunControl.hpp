// Run control from system/controlDict (docs/design.md 1.2): reads startFrom, startTime,
// stopAt, endTime, deltaT, minDeltaT, adjustTimeStep, maxCo, maxDeltaT, writeControl,
// writeInterval, writeFormat, progressInterval (declared in RunControl.cpp);
// functions { ... } and healthChecks { ... } are read elsewhere.
// The controlDict is re-read while running (reread()), so editing `stopAt writeNow;` stops a run.
#pragma once
#include <algorithm>
#include <cmath>
#include "core/Dictionary.hpp"
#include <string>

namespace shizuku {

struct RunControl {
  enum class StartFrom { startTime, latestTime };
  enum class StopAt { endTime, writeNow };
  enum class WriteControl { timeStep, runTime, adjustableRunTime };

  // Set by read(); the defaults, ranges and meanings are declared once in RunControl.cpp.
  StartFrom startFrom{};
  double startTime{};
  StopAt stopAt{};
  double endTime{};
  double deltaT{};
  double minDeltaT{};  // the time loop refuses a smaller step (isph/TimeStepFloor.hpp)
  bool adjustTimeStep{};
  double maxCo{};
  double maxDeltaT{};
  WriteControl writeControl{};
  double writeInterval{};
  bool ascii{};
  int progressInterval{};

  // Read from a parsed controlDict (errors name file, line and keyword).
  static RunControl read(const Dictionary& dict);
  // Time tolerance for "landing exactly" on end and write times.
  double timeTolerance() const { return 1e-9 * (deltaT > 0 ? deltaT : 1.0); }

  // Whether a step dt towards a target time (end or write) `remaining` ahead should land on
  // it: when dt reaches it or falls short of it by less than 1e-6 dt. Without the second
  // rule a time summed over many fixed steps (60 000 x 1e-4 s ends 4e-11 s short of 6 s)
  // finishes with a sliver step, in which the stabilized PPE source term (1/dt^2, eq. 9)
  // is 1e13 times too large.
  static bool landsOn(double dt, double remaining) { return remaining - dt < 1e-6 * dt; }

  // The step towards a write time `remaining` ahead when steps may be at most dt: the time
  // left divided into the fewest equal steps of at most dt, a step longer than dt by less
  // than 1e-6 dt counting as dt (landsOn's rule, so no sliver is left over). Landing on a
  // write time then shortens the steps before it evenly instead of cutting the last one or
  // two short: a step up to twice shorter than its neighbours made the pressure's part that
  // scales with 1/dt spike at every write time (docs/method.md 4.3). A running plan (the
  // previous step, `previous`, still divides the time left evenly) is kept while it exceeds
  // dt by at most kLandingAllowance: a limit that falls by a few per cent in the last steps
  // would otherwise halve the last step. Returns dt when remaining or dt is not positive.
  static constexpr double kLandingAllowance = 0.05;
  static double evenStepTo(double dt, double remaining, double previous = 0) {
    if (!(remaining > 0) || !(dt > 0)) return dt;
    const auto even = [remaining](double limit) {
      return remaining / std::max(1.0, std::ceil(remaining / limit - 1e-6));
    };
    const double strict = even(dt), kept = even((1 + kLandingAllowance) * dt);
    return kept > strict && std::abs(kept - previous) <= 1e-9 * previous ? kept : strict;
  }

  // Next write time after time t (runTime/adjustableRunTime), from the start time grid.
  double nextWriteTime(double t) const;
  // Whether a step ending at (time, stepIndex) should write.
  bool isWriteStep(double time, long stepIndex) const;
};

}  // namespace shizuku
