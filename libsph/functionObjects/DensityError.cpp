// Function object `densityError` (eq. 22): see DensityError.hpp.
// Reads histogram { min; max; bins; write; } through the declarations below.
#include "functionObjects/DensityError.hpp"
#include "core/Parameter.hpp"
#include "io/TimeName.hpp"
#include "parallel/Communicator.hpp"
#include <cmath>
#include <limits>
#include <omp.h>

namespace shizuku {

namespace {
namespace key {
// Histogram of the density error in percent; bins beyond 1e6 would only cost memory.
const ParameterGroup histogram("system/controlDict: functions/<name>/histogram (type densityError)",
    "Histogram of the density error (percent) written by densityError.");
const ScalarParameter histogramMin = histogram.scalar("min", dim::none, "lower edge (percent)").def(-10).min(-1e6).max(1e6);
const ScalarParameter histogramMax = histogram.scalar("max", dim::none, "upper edge (percent, > min)").def(10).min(-1e6).max(1e6);
const IntParameter histogramBins = histogram.integer("bins", "number of bins").def(80).min(1).max(1000000);
const OptionParameter histogramWrite = histogram.option("write", {"writeTime", "sample", "no"},
    "write the histogram at write times, at every sample, or never").def("writeTime");
}  // namespace key
}  // namespace

template <int D>
DensityError<D>::DensityError(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "densityError", dict) {
  const Dictionary* h = dict.subDictPtr("histogram");
  if (!h) dict.getWordOr("histogram", "{ min -10; max 10; bins 80; write writeTime; }");  // lists the default
  min_ = key::histogramMin.read(h);
  max_ = key::histogramMax.read(h);
  bins_ = key::histogramBins.read(h);
  const std::string w = key::histogramWrite.read(h);
  write_ = w == "writeTime" ? HistogramWrite::writeTime
           : w == "sample"  ? HistogramWrite::sample : HistogramWrite::no;
  if (!(max_ > min_)) h->error("max", "must be greater than min");
  result_.histInterior.assign(std::size_t(bins_), 0);
  result_.histAll.assign(std::size_t(bins_), 0);
}

template <int D>
std::string DensityError<D>::details() const {
  return cat(", histogram ", bins_, " bins over [", min_, ", ", max_, "] %");
}

template <int D>
const DensityErrorResult& DensityError<D>::evaluate(const FlowState<D>& s) {
  const auto& p = s.particles;
  const double rho0 = s.rho0;
  const std::size_t n = s.numOwned();  // every rank counts its own particles; the counts are summed
  const auto error = [&](std::size_t i) { return densityErrorPercent(rho0, p.density[i]); };

  const DensityErrorSummary m = measureDensityError(s);
  result_.interior = m.interior;
  result_.all = m.all;

  // Histograms: per-thread counts (slot 0 below, 1..bins, bins+1 above), then added up.
  const int nb = bins_ + 2, threads = omp_get_max_threads();
  threadCounts_.assign(std::size_t(threads) * 2 * nb, 0);
  const double width = (max_ - min_) / bins_;
#pragma omp parallel
  {
    long* c = threadCounts_.data() + std::size_t(omp_get_thread_num()) * 2 * nb;
#pragma omp for schedule(static)
    for (long i = 0; i < long(n); ++i) {
      if (!p.isFluid(i)) continue;
      const double e = error(i);
      int k;
      if (e < min_) k = 0;
      else if (e > max_) k = bins_ + 1;
      else k = 1 + std::min(bins_ - 1, int(std::floor((e - min_) / width)));
      c[nb + k] += 1;
      if (p.surfaceClass(i) == SurfaceClass::interior) c[k] += 1;
    }
  }
  result_.belowInterior = result_.aboveInterior = result_.belowAll = result_.aboveAll = 0;
  std::fill(result_.histInterior.begin(), result_.histInterior.end(), 0);
  std::fill(result_.histAll.begin(), result_.histAll.end(), 0);
  for (int t = 0; t < threads; ++t) {
    const long* c = threadCounts_.data() + std::size_t(t) * 2 * nb;
    result_.belowInterior += c[0];
    result_.aboveInterior += c[bins_ + 1];
    result_.belowAll += c[nb];
    result_.aboveAll += c[nb + bins_ + 1];
    for (int k = 0; k < bins_; ++k) {
      result_.histInterior[k] += c[1 + k];
      result_.histAll[k] += c[nb + 1 + k];
    }
  }
  const auto& world = Communicator::world();
  if (world.isParallel()) {
    world.sumInPlace(result_.histInterior);
    world.sumInPlace(result_.histAll);
    std::vector<long> out = {result_.belowInterior, result_.aboveInterior, result_.belowAll, result_.aboveAll};
    world.sumInPlace(out);
    result_.belowInterior = out[0];
    result_.aboveInterior = out[1];
    result_.belowAll = out[2];
    result_.aboveAll = out[3];
  }
  const auto mode = [&](const std::vector<long>& h) {
    int best = -1;
    for (int k = 0; k < bins_; ++k)
      if (h[k] > 0 && (best < 0 || h[k] > h[best])) best = k;
    return best < 0 ? std::numeric_limits<double>::quiet_NaN() : binCentre(best);
  };
  result_.interior.mode = mode(result_.histInterior);
  result_.all.mode = mode(result_.histAll);
  return result_;
}

template <int D>
void DensityError<D>::open(const FlowState<D>& s, const RunInfo& info) {
  this->file_.emplace(this->makeFile(info, "densityError.dat"));
  this->file_->comment(cat("density error e_i = (rho0 - <rho>_i)/rho0 x 100 % (eq. 22), <rho>_i the summation density, rho0 = ",
                     PostProcessingFile::number(s.rho0), " kg/m^3\n",
                     "mean, rms, max |e|, mode (centre of the fullest histogram bin): interior particles;\n",
                     "meanAll, rmsAll, maxAll, modeAll: all fluid particles (interior + vicinity + free + splash)"));
  this->file_->columns({"time", "mean", "rms", "max", "mode", "meanAll", "rmsAll", "maxAll", "modeAll"},
                 {"s", "%", "%", "%", "%", "%", "%", "%", "%"});
}

template <int D>
void DensityError<D>::sample(const FlowState<D>& s, const RunInfo& info) {
  const auto& r = evaluate(s);
  this->file_->row(s.time, {r.interior.mean, r.interior.rms, r.interior.max, r.interior.mode, r.all.mean, r.all.rms,
                      r.all.max, r.all.mode});
  if (write_ == HistogramWrite::sample || (write_ == HistogramWrite::writeTime && info.isWriteTime))
    writeHistogram(s, info);
}

template <int D>
void DensityError<D>::writeHistogram(const FlowState<D>& s, const RunInfo& info) {
  PostProcessingFile f = this->makeFile(info, timeName(s.time) + "/histogram.dat");
  const auto& r = result_;
  f.comment(cat("histogram of the density error (eq. 22) at time ", PostProcessingFile::number(s.time), " s\n",
                "bins ", bins_, " of width ", PostProcessingFile::number((max_ - min_) / bins_), " % over [",
                PostProcessingFile::number(min_), ", ", PostProcessingFile::number(max_), "] %\n",
                "interior particles ", r.interior.count, " (below range ", r.belowInterior, ", above ",
                r.aboveInterior, "); all fluid particles ", r.all.count, " (below range ", r.belowAll, ", above ",
                r.aboveAll, ")"));
  f.columns({"binCentre", "countInterior", "countAll"}, {"%", "-", "-"});
  for (int k = 0; k < bins_; ++k)
    f.row(cat(PostProcessingFile::number(binCentre(k)), " ", r.histInterior[k], " ", r.histAll[k]));
}

template class DensityError<2>;
template class DensityError<3>;

}  // namespace shizuku
