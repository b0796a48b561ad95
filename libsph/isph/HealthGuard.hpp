// The health guard of a run (docs/design.md 1.3, docs/solver.md "Health checks"): after
// every step it checks the fluid particles and stops the run with a NumericalError naming
// the first offending particle when one is non-finite or faster than maxSpeed, or when the
// interior density error rms (eq. 22) exceeds maxDensityErrorRms. The outflow (Outflow.hpp)
// fails through it when the removed mass or the wall leaks pass their limits.
// The offending particles go to postProcessing/healthChecks/<time>/offending.vtp. It also
// keeps the last good state (the start of the current step), which the time loop writes
// after a failure.
// Reads (system/controlDict, healthChecks): maxDensityErrorRms (%), maxSpeed (m/s; 0: ten
// times the larger of the fastest initial speed and the free-fall speed sqrt(2 |g| L) over
// the largest extent L), maxLostFraction (of the initial fluid mass), maxLeaks; declared in
// HealthGuard.cpp. domainMargin is retired: read with a warning naming the new keys.
#pragma once
#include "core/Dictionary.hpp"
#include "operators/DensityErrorMeasure.hpp"
#include <string>
#include <vector>

namespace shizuku {

struct HealthLimits {
  double maxDensityErrorRms = 20;        // % over interior particles
  double maxSpeed = 0;                   // m/s; 0: automatic
  double maxLostFraction = 0.01;         // removed mass over the initial fluid mass
  long maxLeaks = 0;                     // fluid particles through the walls
};

template <int D>
class HealthGuard {
 public:
  explicit HealthGuard(const Dictionary& controlDict);
  // The automatic speed limit, from the initial extent of all particles.
  void setLimits(const FlowState<D>& s, const Vec<D>& gravity);
  const HealthLimits& limits() const { return limits_; }
  // Throws NumericalError on a failed check (`where`: "after the step", ...); returns the
  // largest fluid speed.
  double check(const FlowState<D>& s, const char* where, const std::string& caseDir);

  // The density error of the last check (eq. 22), for the progress line.
  const DensityErrorSummary& densityError() const { return density_; }

  // Stops the run (NumericalError) with `offending` (indices) written as the offending particles.
  [[noreturn]] void failWith(const FlowState<D>& s, const std::string& message, const std::vector<Index>& offending,
                             const std::string& caseDir);

  void saveGoodState(const FlowState<D>& s);
  // The positions at the start of the current step, in the current particle order.
  const std::vector<Vec<D>>& goodPositions() const { return goodX_; }
  // The state at the start of the current step, also when particles were removed since.
  void restoreGoodState(FlowState<D>& s) const;

 private:
  double checkOwn(const FlowState<D>& s, const char* where, const std::string& caseDir);
  std::string writeOffendingParticles(const FlowState<D>& s, const std::string& caseDir) const;
  [[noreturn]] void fail(const FlowState<D>& s, const std::string& message, const std::string& caseDir) const;
  HealthLimits limits_;
  DensityErrorSummary density_;
  std::vector<Index> offending_;
  // Last good state (start of the current step).
  std::vector<Vec<D>> goodX_, goodU_;
  std::vector<double> goodP_;
  std::vector<std::int64_t> goodId_;
  std::vector<std::uint8_t> goodType_;
  std::vector<Vec<D>> goodRest_;          // moving walls: rest positions (empty without)
  std::vector<std::uint8_t> goodMotion_;
  std::vector<Vec<D>> goodWallNormal_;    // the walls' normals (empty without walls)
  std::vector<Vec<D>> goodRestNormal_;    // moving walls: their rest normals (empty without)
  double goodTime_ = 0, goodDt_ = 0;
  FluidBalance goodBalance_;
  long goodStep_ = 0;
};

}  // namespace shizuku
