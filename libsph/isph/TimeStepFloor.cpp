// The time-step floor: see TimeStepFloor.hpp.
#include "isph/TimeStepFloor.hpp"
#include "core/Log.hpp"
#include "core/types.hpp"
#include <cmath>
#include <cstring>

namespace shizuku {

namespace {
std::string limitsText(const TimeStepChoice& choice) {
  std::string s;
  for (int k = 0; k < choice.count; ++k) {
    const TimeStepLimit& l = choice.limits[k];
    if (!std::isfinite(l.dt) || l.name[0] == '\0') continue;
    s += cat(s.empty() ? "" : ", ", l.name, " ", l.dt, " s");
  }
  return s.empty() ? "" : "; the limits were: " + s;
}
}  // namespace

void checkTimeStepFloor(double t, long step, double dt, double minDeltaT, const char* limiter,
                        const TimeStepChoice& choice) {
  const bool advances = t + dt > t;
  // A step shortened to land on a write or the end time may be a sliver; there is one per
  // write, so it cannot make a run crawl: only t + dt > t is asked of it.
  const bool landing = std::strcmp(limiter, "write") == 0 || std::strcmp(limiter, "endTime") == 0;
  if (advances && (dt >= minDeltaT || landing)) return;
  const std::string what =
      advances ? cat("is below minDeltaT ", minDeltaT, " s (system/controlDict)")
               : cat("does not advance the time t = ", t, " s in double precision (t + dt == t; the smallest step "
                     "that does is about ", std::nextafter(t, INFINITY) - t, " s)");
  throw NumericalError(cat("time step refused at step ", step + 1, ", t = ", t, " s: dt = ", dt,
                           " s, set by the '", limiter, "' limit, ", what, limitsText(choice)));
}

}  // namespace shizuku
