// Function object `waterLevel`: wave-gauge heights from the fluid's kernel sum; see
// WaterLevel.hpp. Reads points, minKernelSum through the declarations below.
#include "functionObjects/WaterLevel.hpp"
#include "parallel/Communicator.hpp"
#include "core/Parameter.hpp"
#include <algorithm>
#include <cmath>

namespace shizuku {

namespace {
const ParameterGroup waterLevel("system/controlDict: functions/<name> (type waterLevel)",
    "Water height above gauge points (a wave gauge), from the fluid's kernel sum.");
const VectorListParameter pointsParameter = waterLevel.vectorList("points", dim::length,
    "gauge points ((x y [z]) ...): the level is measured up (+y) from each").required();
const ScalarParameter minKernelSum = waterLevel.scalar("minKernelSum", dim::none,
    "kernel sum at the free surface: the level is where the sum crosses it").def(0.5).above(0).max(1);
}  // namespace

template <int D>
WaterLevel<D>::WaterLevel(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "waterLevel", dict) {
  points_ = pointsParameter.read<D>(dict);
  if (points_.empty()) dict.error("points", "needs at least one gauge point, e.g. ((0.5 0 0.5))");
  minKernelSum_ = minKernelSum.read(dict);
  heights_.assign(points_.size(), 0);
}

template <int D>
WaterLevel<D>::WaterLevel(const std::string& name, const std::string& type, const Dictionary& dict,
                          std::vector<Vec<D>> points, double minKernelSum)
    : SampledFunctionObject<D>(name, type, dict), points_(std::move(points)), minKernelSum_(minKernelSum) {
  heights_.assign(points_.size(), 0);
}

template <int D>
std::string WaterLevel<D>::details() const {
  return cat(", ", points_.size(), " gauge", points_.size() == 1 ? "" : "s", ", surface at kernel sum ",
             formatNumber(minKernelSum_));
}

template <int D>
double WaterLevel<D>::height(const FlowState<D>& s, const Vec<D>& foot) {
  const auto& p = s.particles;
  const double support = s.kernel.support(), V = s.V();
  const long n = long(s.numOwned());
  near_.clear();
  double top = -INFINITY;
  // The fluid particles whose support reaches the line (serial push, parallel test).
#pragma omp parallel
  {
    double localTop = -INFINITY;
#pragma omp for schedule(static)
    for (long j = 0; j < n; ++j) {
      if (!p.isFluid(std::size_t(j))) continue;
      Vec<D> d = s.periodic.difference(p.position[std::size_t(j)], foot);
      const double along = d[1];
      d[1] = 0;
      if (d.squaredNorm() >= support * support || along < -support) continue;
      d[1] = along;
      localTop = std::max(localTop, along);
#pragma omp critical(shizukuWaterLevel)
      near_.push_back(d);
    }
#pragma omp critical(shizukuWaterLevelTop)
    top = std::max(top, localTop);
  }
  const auto& world = Communicator::world();
  if (world.isParallel()) {  // every rank's particles near the line (sorted below: the order does not matter)
    top = world.max(top);
    std::vector<double> mine(near_.size() * D);
    for (std::size_t k = 0; k < near_.size(); ++k)
      for (int a = 0; a < D; ++a) mine[k * D + a] = near_[k][a];
    const std::vector<double> all = world.allGatherVariable(mine);
    near_.resize(all.size() / D);
    for (std::size_t k = 0; k < near_.size(); ++k)
      for (int a = 0; a < D; ++a) near_[k][a] = all[k * D + a];
  }
  if (near_.empty()) return 0;
  // Deterministic sums whatever the thread count: the offsets in a fixed order.
  std::sort(near_.begin(), near_.end(), [](const Vec<D>& a, const Vec<D>& b) {
    return std::lexicographical_compare(a.data(), a.data() + D, b.data(), b.data() + D);
  });
  auto sum = [&](double y) {
    double S = 0;
    for (const auto& d : near_) {
      Vec<D> r = d;
      r[1] -= y;
      const double len = r.norm();
      if (len < support) S += V * s.kernel.w(len);
    }
    return S;
  };
  // From the top down: the first sample at or above the threshold ends the search.
  const double step = 0.25 * s.d0;
  double yAbove = std::max(0.0, top + support), sAbove = sum(yAbove);
  for (double y = yAbove - step;; y -= step) {
    const double yy = std::max(0.0, y), sy = sum(yy);
    if (sy >= minKernelSum_) return sAbove < minKernelSum_ ? yy + (yAbove - yy) * (sy - minKernelSum_) / (sy - sAbove) : yy;
    if (yy <= 0) return 0;
    yAbove = yy;
    sAbove = sy;
  }
}

template <int D>
const std::vector<double>& WaterLevel<D>::evaluate(const FlowState<D>& s) {
  for (std::size_t g = 0; g < points_.size(); ++g) heights_[g] = height(s, points_[g]);
  return heights_;
}

template <int D>
std::string WaterLevel<D>::fileComment() const {
  std::string where;
  for (const auto& x : points_) where += (where.empty() ? "" : " ") + formatNumber<D>(x);
  return cat("water height above the gauge points ", where, " (m, up along +y): where the fluid's kernel sum crosses ",
             formatNumber(minKernelSum_));
}

template <int D>
void WaterLevel<D>::open(const FlowState<D>&, const RunInfo& info) {
  this->file_.emplace(this->makeFile(info, fileName_));
  this->file_->comment(fileComment());
  std::vector<std::string> names{"time"}, units{"s"};
  for (std::size_t g = 0; g < points_.size(); ++g) {
    names.push_back(cat(columnPrefix_, g));
    units.push_back("m");
  }
  this->file_->columns(names, units);
}

template <int D>
void WaterLevel<D>::sample(const FlowState<D>& s, const RunInfo&) {
  std::string row = PostProcessingFile::number(s.time);
  for (double h : evaluate(s)) row += " " + PostProcessingFile::number(h + offset_);
  this->file_->row(row);
}

template class WaterLevel<2>;
template class WaterLevel<3>;

}  // namespace shizuku
