// Function object `densityError` (docs/design.md 1.3): the density error of eq. (22),
//   e_i = (rho0 - <rho>_i) / rho0 x 100 %,   <rho>_i the summation density (eq. 18),
// over two sets of fluid particles: the interior ones (free-surface class
// `interior`, docs/method.md 5.2) and all fluid particles (walls never count).
// Statistics per set: mean e, rms = sqrt(mean e^2), max |e|, and mode = centre
// of the fullest bin of the histogram (ties: the lowest such bin; nan when no
// value falls inside [min, max]).
// Histogram: `bins` equal bins over [min, max] % (a value equal to max goes in
// the last bin); values outside are counted in the header as below/above.
// Files:
//   densityError.dat: time, mean, rms, max, mode (interior), meanAll, rmsAll, maxAll, modeAll (all fluid), in %
//   <timeName>/histogram.dat (one folder per histogram time): binCentre (%), countInterior, countAll
// Reads (controlDict functions/<name>): type densityError; writeControl; writeInterval;
//   histogram { min -10; max 10; bins 80; write writeTime; }   (write writeTime|sample|no:
//   a histogram at every sample that is a write time (default), at every sample, or never)
#pragma once
#include "functionObjects/SampledFunctionObject.hpp"
#include "operators/DensityErrorMeasure.hpp"
#include <optional>

namespace shizuku {

struct DensityErrorResult {
  DensityErrorStats interior, all;
  std::vector<long> histInterior, histAll;   // counts per bin
  long belowInterior = 0, aboveInterior = 0, belowAll = 0, aboveAll = 0;
};

template <int D>
class DensityError : public SampledFunctionObject<D> {
 public:
  enum class HistogramWrite { writeTime, sample, no };
  DensityError(const std::string& name, const Dictionary& dict);

  double histogramMin() const { return min_; }
  double histogramMax() const { return max_; }
  int bins() const { return bins_; }
  double binCentre(int k) const { return min_ + (k + 0.5) * (max_ - min_) / bins_; }
  // Statistics and histograms of the state (into a buffer reused between calls).
  const DensityErrorResult& evaluate(const FlowState<D>& s);

 protected:
  std::string details() const override;
  void open(const FlowState<D>& s, const RunInfo& info) override;
  void sample(const FlowState<D>& s, const RunInfo& info) override;

 private:
  void writeHistogram(const FlowState<D>& s, const RunInfo& info);
  double min_ = -10, max_ = 10;
  int bins_ = 80;
  HistogramWrite write_ = HistogramWrite::writeTime;
  DensityErrorResult result_;
  std::vector<long> threadCounts_;  // per thread: 2 x (bins + 2) counts
};

extern template class DensityError<2>;
extern template class DensityError<3>;

}  // namespace shizuku
