// Function object `waveGauge`: free-surface elevations at fixed positions; see WaveGauge.hpp.
#include "functionObjects/WaveGauge.hpp"
#include "core/Parameter.hpp"

namespace shizuku {

namespace {
namespace key {
const ParameterGroup waveGauge("system/controlDict: functions/<name> (type waveGauge)",
    "Free-surface elevation at fixed horizontal positions (a wave gauge), from the fluid's kernel sum.");
const OptionParameter positions = waveGauge.option("positions", {},
    "the gauges: (x ...) in 2D, ((x z) ...) in 3D, m; the level is measured up (+y)").required();
const ScalarParameter bottom = waveGauge.scalar("bottom", dim::length,
    "y where the gauge lines start (at or below the bed)").def(0);
const ScalarParameter stillWaterLevel = waveGauge.scalar("stillWaterLevel", dim::length,
    "y of the still water: the elevation is y_surface - stillWaterLevel").def(0);
const ScalarParameter minKernelSum = waveGauge.scalar("minKernelSum", dim::none,
    "kernel sum at the free surface: the level is where the sum crosses it").def(0.5).above(0).max(1);
}  // namespace key

template <int D>
std::vector<Vec<D>> gaugeFeet(const Dictionary& dict) {
  const double y = key::bottom.read(dict);
  std::vector<Vec<D>> feet;
  if constexpr (D == 2) {
    for (double x : dict.getScalarList(key::positions.keyword(), dim::length)) feet.push_back(Vec<2>(x, y));
  } else {
    for (const Vec<2>& xz : dict.getVectorList<2>(key::positions.keyword(), dim::length))
      feet.push_back(Vec<3>(xz[0], y, xz[1]));
  }
  if (feet.empty())
    dict.error(key::positions.keyword(), D == 2 ? "needs at least one gauge, e.g. (0.5 1.2)"
                                                : "needs at least one gauge, e.g. ((0.5 0.1))");
  return feet;
}
}  // namespace

template <int D>
WaveGauge<D>::WaveGauge(const std::string& name, const Dictionary& dict)
    : WaterLevel<D>(name, "waveGauge", dict, gaugeFeet<D>(dict), key::minKernelSum.read(dict)) {
  still_ = key::stillWaterLevel.read(dict);
  this->offset_ = key::bottom.read(dict) - still_;
  this->fileName_ = "elevation.dat";
  this->columnPrefix_ = "gauge";
  eta_.assign(this->points_.size(), 0);
}

template <int D>
const std::vector<double>& WaveGauge<D>::elevation(const FlowState<D>& s) {
  const auto& h = this->evaluate(s);
  for (std::size_t g = 0; g < h.size(); ++g) eta_[g] = h[g] + this->offset_;
  return eta_;
}

template <int D>
std::string WaveGauge<D>::details() const {
  return cat(", ", this->points_.size(), " gauge", this->points_.size() == 1 ? "" : "s", ", still water at y = ",
             formatNumber(still_), " m, surface at kernel sum ", formatNumber(this->threshold()));
}

template <int D>
std::string WaveGauge<D>::fileComment() const {
  std::string where;
  for (const auto& x : this->points_) where += (where.empty() ? "" : " ") + formatNumber<D>(x);
  return cat("free-surface elevation above y = ", formatNumber(still_), " m at the gauges ", where,
             " (lines up +y from each; surface where the fluid's kernel sum crosses ", formatNumber(this->threshold()),
             ")");
}

template class WaveGauge<2>;
template class WaveGauge<3>;

}  // namespace shizuku
