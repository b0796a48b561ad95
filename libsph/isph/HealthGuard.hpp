// The health guard of a run (docs/design.md 1.3, docs/solver.md "Health checks"): after
// every step it checks the fluid particles and stops the run with a NumericalError naming
// the first offending particle when one is non-finite, outside the domain box, faster than
// maxSpeed, or when the interior density error rms (eq. 22) exceeds maxDensityErrorRms.
// The offending particles go to postProcessing/healthChecks/<time>/offending.vtp. It also
// keeps the last good state (the start of the current step), which the time loop writes
// after a failure.
// Reads (system/controlDict, healthChecks): maxDensityErrorRms (%), domainMargin (times the
// initial extent, on each side), maxSpeed (m/s; 0: ten times the larger of the fastest
// initial speed and the free-fall speed sqrt(2 |g| L) over the largest extent L); declared
// in HealthGuard.cpp.
#pragma once
#include "core/Dictionary.hpp"
#include "operators/DensityErrorMeasure.hpp"
#include <string>
#include <vector>

namespace shizuku {

struct HealthLimits {
  double maxDensityErrorRms = 20;        // % over interior particles
  double domainMargin = 0.5;             // times the initial extent, on each side
  double maxSpeed = 0;                   // m/s; 0: automatic
  Eigen::VectorXd domainMin, domainMax;  // fluid particles must stay inside
};

template <int D>
class HealthGuard {
 public:
  explicit HealthGuard(const Dictionary& controlDict);
  // The domain box from the initial extent of all particles, and the automatic speed limit.
  void setLimits(const FlowState<D>& s, const Vec<D>& gravity);
  const HealthLimits& limits() const { return limits_; }
  // Throws NumericalError on a failed check (`where`: "after the step", ...); returns the
  // largest fluid speed.
  double check(const FlowState<D>& s, const char* where, const std::string& caseDir);

  // The density error of the last check (eq. 22), for the progress line.
  const DensityErrorSummary& densityError() const { return density_; }

  void saveGoodState(const FlowState<D>& s);
  void restoreGoodState(FlowState<D>& s) const;

 private:
  std::string writeOffendingParticles(const FlowState<D>& s, const std::string& caseDir) const;
  [[noreturn]] void fail(const FlowState<D>& s, const std::string& message, const std::string& caseDir) const;
  HealthLimits limits_;
  DensityErrorSummary density_;
  std::vector<Index> offending_;
  // Last good state (start of the current step).
  std::vector<Vec<D>> goodX_, goodU_;
  std::vector<double> goodP_;
  std::vector<std::int64_t> goodId_;
  double goodTime_ = 0, goodDt_ = 0;
  long goodStep_ = 0;
};

}  // namespace shizuku
