// The time-step floor (docs/reliability.md, "Time-step floor"): the time loop refuses a
// step whose dt is below minDeltaT (system/controlDict; default 1e-6 deltaT) or that does
// not advance the time in double precision (t + dt == t; the only check on a step shortened
// to land on a write or the end time, one per write). Either would make the run crawl
// or stand still, writing time folders without end. The refusal is a NumericalError (exit
// 2, the last good state written) naming the criterion that set dt and every limit's value.
// Reads no keys: the time loop hands it minDeltaT.
#pragma once
#include "effects/Effect.hpp"
#include <array>

namespace shizuku {

// The candidates chooseDeltaT compared, kept for the message (no allocation per step).
struct TimeStepChoice {
  std::array<TimeStepLimit, 8> limits{};
  int count = 0;
  void clear() { count = 0; }
  void add(const TimeStepLimit& l) { if (count < int(limits.size())) limits[count++] = l; }
};

// Throws NumericalError when dt (set by `limiter`) is below minDeltaT or t + dt == t.
void checkTimeStepFloor(double t, long step, double dt, double minDeltaT, const char* limiter,
                        const TimeStepChoice& choice);

}  // namespace shizuku
