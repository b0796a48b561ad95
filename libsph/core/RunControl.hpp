// Run control from system/controlDict (design.md 1.2):
//   startFrom startTime|latestTime; startTime; stopAt endTime|writeNow; endTime; deltaT;
//   adjustTimeStep yes|no; maxCo; maxDeltaT; writeControl timeStep|runTime|adjustableRunTime;
//   writeInterval; writeFormat binary|ascii; progressInterval (steps between progress lines);
//   functions { ... } (read by the function-object list, not here).
// The controlDict is re-read while running (reread()), so editing `stopAt writeNow;` stops a run.
#pragma once
#include "core/Dictionary.hpp"
#include <string>

namespace shizuku {

struct RunControl {
  enum class StartFrom { startTime, latestTime };
  enum class StopAt { endTime, writeNow };
  enum class WriteControl { timeStep, runTime, adjustableRunTime };

  StartFrom startFrom = StartFrom::latestTime;
  double startTime = 0;
  StopAt stopAt = StopAt::endTime;
  double endTime = 0;
  double deltaT = 0;
  bool adjustTimeStep = false;
  double maxCo = 0.2;
  double maxDeltaT = 1e300;
  WriteControl writeControl = WriteControl::timeStep;
  double writeInterval = 1;
  bool ascii = false;
  int progressInterval = 100;

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

  // Next write time after time t (runTime/adjustableRunTime), from the start time grid.
  double nextWriteTime(double t) const;
  // Whether a step ending at (time, stepIndex) should write.
  bool isWriteStep(double time, long stepIndex) const;
};

}  // namespace shizuku
