// Function object `flux`: see Flux.hpp (docs/boundaries.md).
#include "functionObjects/Flux.hpp"
#include "parallel/Communicator.hpp"
#include "core/BlockReduce.hpp"
#include "core/Parameter.hpp"
#include <cmath>
#include <algorithm>
#include <limits>

namespace shizuku {

namespace key {
namespace {
const ParameterGroup flux("system/controlDict: functions/<name>/plane (type flux)",
                          "The plane a flux function object measures through (absent: `boundary <name>;`).");
const VectorParameter point = flux.vector("point", dim::length, "a point of the plane").required();
const VectorParameter normal = flux.vector("normal", dim::none, "the plane's normal: positive flux along it").required();
const ScalarParameter thickness = flux.scalar("thickness", dim::length, "slab thickness delta of the estimate")
                                      .def(1).shownDefault("d0").above(0);
const VectorParameter lo = flux.vector("min", dim::length, "only particles above this corner").defZero("unbounded");
const VectorParameter hi = flux.vector("max", dim::length, "only particles below this corner").defZero("unbounded");
}  // namespace
}  // namespace key

template <int D>
Flux<D>::Flux(const std::string& name, const Dictionary& dict)
    : SampledFunctionObject<D>(name, "flux", dict), dict_(&dict),
      lo_(Vec<D>::Constant(-INFINITY)), hi_(Vec<D>::Constant(INFINITY)) {
  const bool hasBoundary = dict.found("boundary"), hasPlane = dict.found("plane");
  if (hasBoundary == hasPlane)
    dict.error(hasBoundary ? "plane" : "type", "a flux function object takes exactly one of `boundary <inlet or outlet "
                                               "name>;` and `plane { point (..); normal (..); }`");
  if (hasBoundary) {
    boundary_ = dict.getWord("boundary");
    return;
  }
  const Dictionary& p = dict.subDict("plane");
  point_ = key::point.read<D>(p);
  normal_ = key::normal.read<D>(p);
  if (!(normal_.norm() > 0)) p.error("normal", "the normal is zero");
  normal_.normalize();
  if (p.found("thickness")) thickness_ = key::thickness.read(p);  // else d0, known at the start
  if (p.found("min")) lo_ = key::lo.read<D>(p);
  if (p.found("max")) hi_ = key::hi.read<D>(p);
}

template <int D>
std::string Flux<D>::details() const {
  if (!boundary_.empty()) return cat(", through '", boundary_, "'");
  return cat(", through the plane at ", formatNumber<D>(point_), " normal ", formatNumber<D>(normal_));
}

template <int D>
double Flux<D>::planeFlux(const FlowState<D>& s, const Vec<D>& point, const Vec<D>& normal, double delta,
                          const Vec<D>& lo, const Vec<D>& hi) {
  const auto& P = s.particles;
  thread_local std::vector<double> partial;
  const double own = blockReduce(s.numOwned(), partial, [&](double& a, std::size_t i) {
    if (!P.isFluid(i)) return;
    const Vec<D>& x = P.position[i];
    if (!(std::abs((x - point).dot(normal)) < 0.5 * delta)) return;
    for (int k = 0; k < D; ++k)
      if (x[k] < lo[k] || x[k] > hi[k]) return;
    a += P.velocity[i].dot(normal);
  });
  const double sum = Communicator::world().sum(own);  // every rank's own particles
  return s.V() * sum / delta;
}

template <int D>
long Flux<D>::crossedNow(const RunInfo& info) const {
  return Communicator::world().sum((*info.crossings)[index_].count);  // each rank counts its own crossings
}

template <int D>
void Flux<D>::open(const FlowState<D>& s, const RunInfo& info) {
  if (!boundary_.empty()) {
    std::vector<std::string> names;
    if (info.crossings)
      for (const auto& c : *info.crossings) names.push_back(c.name);
    auto it = std::find(names.begin(), names.end(), boundary_);
    if (it == names.end()) {
      if (info.postProcessing)
        dict_->error("boundary", "the flux through an inlet or outlet is counted during the run; in post-processing "
                                 "use a plane { point (..); normal (..); }");
      const std::string near = closestMatch(boundary_, names);
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      dict_->error("boundary", cat("'", boundary_, "' is not an inlet or outlet of system/particlesDict (",
                                   names.empty() ? std::string("the case has none") : "they are: " + list, ")",
                                   near.empty() ? std::string() : cat("; did you mean '", near, "'?")));
    }
    index_ = std::size_t(it - names.begin());
    startCount_ = lastCount_ = crossedNow(info);
    lastTime_ = s.time;
  }
  this->file_.emplace(this->makeFile(info, "flux.dat"));
  const std::string unit = D == 2 ? "m^2/s" : "m^3/s";
  if (!boundary_.empty()) {
    const bool inlet = (*info.crossings)[index_].inlet;
    this->file_->comment(cat("volume flow rate through ", inlet ? "inlet '" : "outlet '", boundary_, "', ", D, "D",
                             D == 2 ? " per unit depth" : "", ": particles ", inlet ? "released" : "captured",
                             " since the previous row x V / time since it; volume: since the run began"));
    this->file_->columns({"time", "flux", "volume"}, {"s", unit, units::volume(D)});
  } else {
    this->file_->comment(cat("volume flow rate through the plane at ", formatNumber<D>(point_), " normal ",
                             formatNumber<D>(normal_), ": (1/delta) sum V u.n over fluid within delta/2, delta = ",
                             thickness_ > 0 ? thickness_ : s.d0, " m"));
    this->file_->columns({"time", "flux"}, {"s", unit});
  }
}

template <int D>
void Flux<D>::sample(const FlowState<D>& s, const RunInfo& info) {
  using F = PostProcessingFile;
  if (boundary_.empty()) {
    const double q = planeFlux(s, point_, normal_, thickness_ > 0 ? thickness_ : s.d0, lo_, hi_);
    this->file_->row(F::number(s.time) + " " + F::number(q));
    return;
  }
  const long now = crossedNow(info);
  if (!(s.time > lastTime_)) return;  // no interval yet (the start time)
  const double q = double(now - lastCount_) * s.V() / (s.time - lastTime_);
  this->file_->row(F::number(s.time) + " " + F::number(q) + " " + F::number(double(now - startCount_) * s.V()));
  lastCount_ = now;
  lastTime_ = s.time;
}

template class Flux<2>;
template class Flux<3>;

}  // namespace shizuku
