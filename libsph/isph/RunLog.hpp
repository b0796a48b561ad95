// What the log says while a case runs (docs/design.md 1.3): the progress line every
// `progressInterval` steps and the summary at the end (wall time per stage, particle-steps
// per second, files written). Reads no dictionary keys.
#pragma once
#include "core/StageTimers.hpp"
#include "isph/IsphStep.hpp"
#include <string>
#include <vector>

namespace shizuku {

// "12.5 s", "3.1 min", "1.25 h"; "?" when not finite.
std::string formatSeconds(double seconds);

struct ProgressInfo {
  long step = 0;
  double time = 0, dt = 0;
  double densityErrorRms = 0;  // interior, % (eq. 22)
  double fractionDone = 0;
  double wallSeconds = 0;
  long removed = 0;            // fluid particles removed through the domain's bounds so far
  double removedFraction = 0;  // their mass over the initial fluid mass
  long leaks = 0;              // wall leaks found so far
  long released = 0, captured = 0;  // particles inlets released and outlets captured so far
};

// "step N  t = ..  dt = .. (limiter)  PPE .. it, res ..  max|U| = ..  rhoErr rms = .. %  ADS ..  shift passes N  in N out N  removed N (f %)  leaks N  x% done, ETA .."
std::string progressLine(const ProgressInfo& p, const StepReport& r);

struct RunSummary {
  long steps = 0;
  double simulated = 0, wallSeconds = 0, particleSteps = 0;
  long ppeFallbacks = 0;
  std::string caseDir;
  std::vector<std::string> written;  // time names
  bool functionObjects = false;
};

// The closing lines of a run, one string per line.
std::vector<std::string> summaryLines(const RunSummary& r, const StageTimers& timers);

}  // namespace shizuku
