// Function object `timing` (docs/design.md 1.3, part 2 "each stage is timed by
// name"): wall-clock seconds spent in each stage of the step since the
// previous sample (differences of the solver's StageTimers totals, so nothing
// shared is reset), then the throughput over the same interval:
//   particleStepsPerSecond = (fluid particles x steps) / wall seconds.
// The first call only remembers the totals (there is no interval yet); a
// sample with no step since the previous one writes nothing.
// In post-processing (RunInfo::timers == nullptr) there is nothing to time: it
// writes no file and says so once.
// File timing.dat: time, one column per stage (named after it, s), particleStepsPerSecond (1/s).
// Reads (controlDict functions/<name>): type timing; writeControl; writeInterval.
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"
#include <optional>

namespace shizuku {

template <int D>
class Timing : public SampledFunctionObject<D> {
 public:
  Timing(const std::string& name, const Dictionary& dict);

 protected:
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  void writeHeader();
  std::vector<std::string> names_;      // stage names in the header
  std::vector<double> lastTotal_;       // stage totals at the previous sample
  double lastWall_ = 0, lastParticleSteps_ = 0;
  bool haveLast_ = false;
  std::vector<double> row_;
};

extern template class Timing<2>;
extern template class Timing<3>;

}  // namespace shizuku
