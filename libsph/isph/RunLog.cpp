// The progress line and the closing summary of a run: see RunLog.hpp.
#include "isph/RunLog.hpp"
#include "io/TimeDirectory.hpp"
#include "core/Log.hpp"
#include <cmath>
#include <iomanip>
#include <omp.h>
#include <sstream>

namespace shizuku {

std::string formatSeconds(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  std::ostringstream os;
  if (s < 120) os << std::fixed << std::setprecision(1) << s << " s";
  else if (s < 7200) os << std::fixed << std::setprecision(1) << s / 60 << " min";
  else os << std::fixed << std::setprecision(2) << s / 3600 << " h";
  return os.str();
}

std::string progressLine(const ProgressInfo& p, const StepReport& r) {
  const double frac = p.fractionDone;
  return cat("step ", p.step, "  t = ", p.time, "  dt = ", p.dt, " (", r.dtLimiter, ")  PPE ", r.ppe.iterations,
             " it, res ", std::setprecision(2), r.ppe.residual, std::setprecision(6),
             r.ppeStandardRows ? cat(" (", r.ppeStandardRows, " std rows)") : "", "  max|U| = ", r.maxSpeed,
             "  rhoErr rms = ", std::setprecision(3), p.densityErrorRms, std::setprecision(6), " %",
             r.adsCount >= 0 ? cat("  ADS ", r.adsCount) : "",
             r.shiftPasses > 1 ? cat("  shift passes ", r.shiftPasses) : "",
             p.released + p.captured > 0 ? cat("  in ", p.released, " out ", p.captured) : "",
             p.removed > 0 ? cat("  removed ", p.removed, " (", std::setprecision(3), 100 * p.removedFraction,
                                 std::setprecision(6), " %)") : "",
             p.leaks > 0 ? cat("  leaks ", p.leaks) : "", "  ", std::fixed, std::setprecision(1), 100 * frac,
             std::defaultfloat, std::setprecision(6), "% done, ETA ",
             formatSeconds(frac > 0 ? p.wallSeconds * (1 - frac) / frac : NAN));
}

std::vector<std::string> summaryLines(const RunSummary& r, const StageTimers& timers) {
  std::vector<std::string> v;
  v.push_back(cat("\nEnd: ", r.steps, " steps, simulated ", r.simulated, " s in ", formatSeconds(r.wallSeconds), ", ",
                  std::setprecision(3), r.steps > 0 ? r.particleSteps / r.wallSeconds : 0.0, " particle-steps/s (",
                  r.particleSteps > 0 ? r.wallSeconds / r.particleSteps * 1e6 : 0.0, " us per particle-step), ",
                  omp_get_max_threads(), " threads"));
  const double tsum = timers.sumTotal();
  for (std::size_t k = 0; k < timers.names().size(); ++k)
    v.push_back(cat("  ", std::left, std::setw(26), timers.names()[k], std::right, std::setw(10), std::fixed,
                    std::setprecision(3), timers.total()[k], " s  ", std::setw(5), std::setprecision(1),
                    tsum > 0 ? 100 * timers.total()[k] / tsum : 0.0, " %", std::defaultfloat));
  if (r.ppeFallbacks > 0)
    v.push_back(cat("PPE: the iterative solver fell back to a direct LU in ", r.ppeFallbacks, " steps"));
  v.push_back("Files written:");
  for (const auto& w : r.written) {
    const std::string file = particleFileOf(r.caseDir + "/" + w);
    v.push_back("  " + (file.empty() ? r.caseDir + "/" + w : file));
  }
  if (!r.written.empty()) v.push_back("  " + r.caseDir + "/particles.pvd");
  if (r.functionObjects) v.push_back("  " + r.caseDir + "/postProcessing/ (function objects)");
  return v;
}

}  // namespace shizuku
